#ifndef ctCaptureSimulation_h
#define ctCaptureSimulation_h
// What a multi-view capture makes of a surface: the inside of the true surface is voxelised
// and the boundary of the occupied voxels re-extracted, independently per frame. Parts closer
// than about a voxel merge (an arm against the torso, legs inside a dress), vertex count and
// order change, and optional holes and noise are added. C++ only (not wrapped).
#include "ctFiltersModule.h"

#include <clothtrack/mesh/TriangleMesh.h>

#include <vector>

class vtkPolyData;

namespace clothtrack
{
struct CaptureOptions
{
  double voxelSize = 0.015;      ///< metres
  double sheetThickness = 0.012; ///< open surfaces (garments) are thickened to this
  int holes = 0;                 ///< random holes punched per frame
  double holeRadius = 0.03;      ///< metres
  double noise = 0.0;            ///< standard deviation of normal noise, metres
  /// Fill what cameras around the person cannot see into: empty regions of a horizontal slice
  /// enclosed by the surface (inside a dress; between an arm and the torso where they touch).
  bool fillEnclosed = true;
  unsigned seed = 1;
};

/// For each captured vertex: the closest point of the true surface.
struct SourceMap
{
  std::vector<int> face;
  std::vector<Vec3> barycentric;
  std::vector<double> distance;
};

/// The captured surface of `truth` (any triangle mesh: closed parts are filled, open ones
/// thickened). `sourceMap` (optional) receives the closest true point of every output vertex.
CTFILTERS_EXPORT TriangleMesh simulateCapture(const TriangleMesh& truth,
                                              const CaptureOptions& options,
                                              SourceMap* sourceMap = nullptr);
/// Adds SourceFace, SourceBarycentric and SourceDistance point arrays to a captured mesh.
CTFILTERS_EXPORT void addSourceMapArrays(const SourceMap& map, vtkPolyData* mesh);
} // namespace clothtrack

#endif
