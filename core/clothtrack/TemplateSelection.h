#pragma once
// Automatic template frame selection (Shehu et al. 2016, section 4.2, after Letouzey and Boyer):
// the true topology is fixed, acquisition can only merge parts, so observed splits are real when
// they persist. Candidates are the frames with the most (persistent) shells; among them, the
// smallest genus of the largest shell; among them, the smallest area ratio (largest / smallest
// mixed Voronoi vertex area of the largest shell): the most uniform mesh.
#include "TriangleMesh.h"

#include <vector>

namespace clothtrack
{
struct FrameTopology
{
  int components = 0; ///< all connected components
  int shells = 0;     ///< components with area >= the minimum shell area
  int genus = 0;      ///< genus of the largest component
  double areaRatio = 0.0;
  double area = 0.0;  ///< area of the largest component
  int boundaries = 0; ///< boundary loops (holes) of the largest component
  int nonManifoldEdges = 0;
};

struct TemplateSelectionOptions
{
  double minimumShellArea = 0.1; ///< m^2: smaller components are noise, not body parts
  int persistence = 3;           ///< a split counts only if it lasts this many consecutive frames
};

struct TemplateSelection
{
  int chosen = -1;
  std::vector<int> persistentShells; ///< per frame: shell count once short-lived splits are ignored
  std::vector<char> candidate;       ///< passed the topological criteria
};

/// The criteria of one frame.
FrameTopology frameTopology(const TriangleMesh& mesh, double minimumShellArea);

/// Chooses the template among frames described by their criteria. Ties go to the earliest frame.
TemplateSelection selectTemplate(const std::vector<FrameTopology>& frames,
                                 const TemplateSelectionOptions& options);
} // namespace clothtrack
