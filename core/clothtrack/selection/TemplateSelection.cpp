#include "TemplateSelection.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/Laplacian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace clothtrack
{
FrameTopology frameTopology(const TriangleMesh& mesh, double minimumShellArea)
{
  FrameTopology t;
  const MeshTopology topology = buildTopology(mesh);
  const Components c = connectedComponents(mesh, topology);
  t.nonManifoldEdges = checkManifold(mesh, topology).nonManifoldEdges;
  t.components = c.count();
  for (const auto& info : c.info) t.shells += info.area >= minimumShellArea ? 1 : 0;
  if (c.count() == 0) return t;
  t.genus = c.info[0].genus();
  t.area = c.info[0].area;
  t.boundaries = c.info[0].numBoundaries;
  const Eigen::VectorXd areas = mixedVoronoiAreas(extractComponent(mesh, c, 0));
  const double smallest = areas.minCoeff();
  t.areaRatio =
      smallest > 0 ? areas.maxCoeff() / smallest : std::numeric_limits<double>::infinity();
  return t;
}

const char* templateCriterionName(TemplateCriterion criterion)
{
  return criterion == TemplateCriterion::RestPose ? "rest-pose" : "area-ratio";
}

TemplateSelection selectTemplate(const std::vector<FrameTopology>& frames,
                                 const TemplateSelectionOptions& options,
                                 const std::vector<double>& restPoseDistance)
{
  const int n = static_cast<int>(frames.size());
  if (n == 0) throw Error("template selection: no frame");
  if (!restPoseDistance.empty() && static_cast<int>(restPoseDistance.size()) != n)
    throw Error("template selection: " + std::to_string(restPoseDistance.size()) +
                " rest-pose distances for " + std::to_string(n) + " frames");
  const int k = std::max(1, options.persistence);
  TemplateSelection s;
  s.persistentShells.resize(n);
  // A frame keeps `c` shells if it lies in a run of at least k consecutive frames that all have
  // at least c shells; otherwise try c - 1.
  for (int i = 0; i < n; ++i)
  {
    int c = frames[i].shells;
    for (; c > 1; --c)
    {
      int begin = i, end = i;
      while (begin > 0 && frames[begin - 1].shells >= c) --begin;
      while (end + 1 < n && frames[end + 1].shells >= c) ++end;
      if (end - begin + 1 >= std::min(k, n)) break;
    }
    s.persistentShells[i] = std::max(c, std::min(frames[i].shells, 1));
  }
  const int most = *std::max_element(s.persistentShells.begin(), s.persistentShells.end());
  int lowestGenus = std::numeric_limits<int>::max();
  for (int i = 0; i < n; ++i)
    if (s.persistentShells[i] == most) lowestGenus = std::min(lowestGenus, frames[i].genus);
  s.candidate.assign(n, 0);
  for (int i = 0; i < n; ++i)
    s.candidate[i] = s.persistentShells[i] == most && frames[i].genus == lowestGenus;

  // Rest pose when asked and known for some candidate; unknown poses rank last.
  auto pose = [&](int i)
  {
    const double d = restPoseDistance.empty() ? NAN : restPoseDistance[i];
    return std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
  };
  bool byPose = false;
  if (options.templateCriterion == TemplateCriterion::RestPose)
    for (int i = 0; i < n; ++i) byPose = byPose || (s.candidate[i] && std::isfinite(pose(i)));
  s.decidedBy = byPose ? TemplateCriterion::RestPose : TemplateCriterion::AreaRatio;
  for (int i = 0; i < n; ++i)
  {
    if (!s.candidate[i]) continue;
    if (s.chosen < 0)
    {
      s.chosen = i;
      continue;
    }
    const int c = s.chosen;
    const bool better = byPose && pose(i) != pose(c) ? pose(i) < pose(c)
                                                     : frames[i].areaRatio < frames[c].areaRatio;
    if (better) s.chosen = i;
  }
  return s;
}

std::vector<int> templateFramesByPose(const TemplateSelection& selection,
                                      const std::vector<double>& restPoseDistance)
{
  std::vector<int> frames;
  if (restPoseDistance.size() != selection.candidate.size()) return frames;
  for (size_t k = 0; k < restPoseDistance.size(); ++k)
    if (selection.candidate[k] && std::isfinite(restPoseDistance[k]))
      frames.push_back(static_cast<int>(k));
  std::stable_sort(frames.begin(), frames.end(),
                   [&](int a, int b) { return restPoseDistance[a] < restPoseDistance[b]; });
  return frames;
}

bool isCollectionOfPoses(const std::vector<bool>& continuesPrevious)
{
  if (continuesPrevious.size() < 2) return false;
  const auto unrelated = std::count(continuesPrevious.begin() + 1, continuesPrevious.end(), false);
  return 2 * unrelated >= static_cast<std::ptrdiff_t>(continuesPrevious.size() - 1);
}

int defaultTemplateCandidates(const std::vector<bool>& continuesPrevious)
{
  return isCollectionOfPoses(continuesPrevious) ? 3 : 1;
}
} // namespace clothtrack
