#pragma once
// A captured point cloud made into the mesh the pipeline takes: invalid points dropped, outliers
// removed, density evened, normals estimated and oriented, a watertight Poisson surface, then
// cropped to where the points are, so that no skin is invented far from any point (the soles,
// the top of the head a camera did not see). The report says how sure the result is.
#include <clothtrack/base/Progress.h>
#include <clothtrack/cloud/CloudCleaning.h>
#include <clothtrack/cloud/CloudNormals.h>
#include <clothtrack/reconstruction/PoissonSurface.h>

#include <string>
#include <vector>

namespace clothtrack
{
struct ReconstructionOptions
{
  CloudCleaningOptions cleaning;
  NormalOptions normals;
  PoissonOptions poisson;
  /// Surface further than this from every cleaned point is cut away, metres.
  double cropDistance = 0.02;
  /// Pieces left with fewer than this share of the faces are dropped.
  double minimumPieceShare = 0.01;
  /// Clouds with fewer valid points are refused.
  int minimumPoints = 100;
};

struct ReconstructionReport
{
  int inputPoints = 0;
  int invalidPoints = 0; ///< non-finite, dropped
  CloudCleaningReport cleaning;
  NormalReport normals;
  bool givenNormals = false; ///< the cloud's own normals were used
  int poissonVertices = 0, poissonFaces = 0;
  int unpairedEdges = 0; ///< iso-surface edges Poisson left open
  int vertices = 0, faces = 0;
  int droppedFanFaces = 0;  ///< faces of the smaller fans at bow-tie vertices the crop left
  int repairedVertices = 0; ///< bow-tie vertices split and duplicates merged after that
  int pieces = 0;           ///< connected components of the result
  int boundaryLoops = 0;    ///< holes opened by the crop (and the capture)
  int genus = 0;            ///< of the largest piece
  double area = 0;          ///< of the result, square metres
  /// Share of the cleaned points further than 1 cm from the result.
  double unexplainedShare = 0;
  /// Mean distance of the cleaned points to the result, metres.
  double meanPointDistance = 0;
  /// Seconds spent: dropping and cleaning, normals, Poisson, crop and report.
  double cleaningSeconds = 0, normalSeconds = 0, poissonSeconds = 0, cropSeconds = 0;
  /// Reasons to doubt the result; empty when it looks like a captured surface.
  std::vector<std::string> doubts;
};

/// The cropped Poisson surface of `cloud`. Throws Error naming `name` for a cloud that cannot
/// be a surface (empty, all NaN, too few points, points that fill a volume). `progress` is
/// told the share done after each step; returning false cancels (Error).
TriangleMesh reconstructSurface(const PointCloud& cloud, const std::string& name,
                                const ReconstructionOptions& options = {},
                                ReconstructionReport* report = nullptr,
                                const StageProgress& progress = {});

/// The faces of `mesh` whose three corners lie within `distance` of some point, without pieces
/// smaller than `minimumPieceShare` of them; unused vertices removed.
TriangleMesh cropToPoints(const TriangleMesh& mesh, const Points& points, double distance,
                          double minimumPieceShare);
} // namespace clothtrack
