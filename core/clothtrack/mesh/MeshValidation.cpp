#include "MeshValidation.h"

#include "ManifoldRepair.h"
#include "PointIndex.h"
#include <clothtrack/base/Error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace clothtrack
{
void validateMesh(const TriangleMesh& mesh, const std::string& name)
{
  if (mesh.numVertices() == 0) throw Error(name + ": empty mesh (no vertex)");
  if (mesh.numFaces() == 0) throw Error(name + ": no face (a point cloud is not a surface)");
  for (int i = 0; i < mesh.numVertices(); ++i)
    if (!mesh.V.row(i).allFinite())
      throw Error(name + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  // Areas and normals square and multiply coordinates: far beyond any capture's unit they
  // overflow, and every face would look degenerate.
  const double largest = mesh.V.cwiseAbs().maxCoeff();
  if (largest > 1e12)
  {
    char value[32];
    std::snprintf(value, sizeof(value), "%g", largest);
    throw Error(name + ": a coordinate of " + value +
                " is beyond any capture's size (corrupt file?)");
  }
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.F(f, k) < 0 || mesh.F(f, k) >= mesh.numVertices())
        throw Error(name + ": face " + std::to_string(f) + " uses vertex index " +
                    std::to_string(mesh.F(f, k)) + ", out of range [0, " +
                    std::to_string(mesh.numVertices()) + ")");
}

CleaningReport cleanMesh(TriangleMesh& mesh, const CleaningOptions& options,
                         std::vector<int>* vertexMap)
{
  CleaningReport report;
  const int nv = mesh.numVertices();
  std::vector<int> representative(nv);
  for (int i = 0; i < nv; ++i) representative[i] = i;

  if (options.mergeDuplicateVertices && nv > 0)
  {
    Eigen::AlignedBox3d box;
    for (int i = 0; i < nv; ++i) box.extend(mesh.vertex(i));
    const double tol = options.mergeTolerance * std::max(box.diagonal().norm(), 1e-300);
    const PointIndex index(mesh.V);
    for (int i = 0; i < nv; ++i)
    {
      if (representative[i] != i) continue;
      for (const auto& n : index.withinRadius(mesh.vertex(i), tol))
        if (n.index > i && representative[n.index] == n.index)
        {
          representative[n.index] = i;
          ++report.mergedVertices;
        }
    }
  }

  std::vector<std::array<int, 3>> candidates;
  candidates.reserve(mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    std::array<int, 3> tri = {representative[mesh.F(f, 0)], representative[mesh.F(f, 1)],
                              representative[mesh.F(f, 2)]};
    if (options.removeDegenerateFaces)
    {
      const Vec3 a = mesh.vertex(tri[0]), b = mesh.vertex(tri[1]), c = mesh.vertex(tri[2]);
      // Zero area relative to the edge lengths: collapsed or collinear corners.
      const double scale =
          std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
          (b - a).cross(c - a).norm() <= 1e-12 * scale)
      {
        ++report.degenerateFaces;
        continue;
      }
    }
    candidates.push_back(tri);
  }
  // The same triangle twice (any winding) is a duplicate, not a surface: the first one is kept.
  // (Sorted keys rather than a set: one allocation instead of one per face.)
  std::vector<std::pair<std::array<int, 3>, int>> keys(candidates.size());
  for (size_t f = 0; f < candidates.size(); ++f)
  {
    keys[f] = {candidates[f], static_cast<int>(f)};
    std::sort(keys[f].first.begin(), keys[f].first.end());
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> repeated(candidates.size(), 0);
  for (size_t k = 1; k < keys.size(); ++k)
    if (keys[k].first == keys[k - 1].first)
    {
      repeated[keys[k].second] = 1;
      ++report.duplicateFaces;
    }
  std::vector<std::array<int, 3>> faces;
  faces.reserve(candidates.size());
  for (size_t f = 0; f < candidates.size(); ++f)
    if (!repeated[f]) faces.push_back(candidates[f]);

  std::vector<int> newIndex(nv, -1);
  int kept = 0;
  if (options.removeUnusedVertices)
  {
    for (const auto& t : faces)
      for (int v : t)
        if (newIndex[v] < 0) newIndex[v] = 0;
    for (int i = 0; i < nv; ++i)
      if (newIndex[i] == 0) newIndex[i] = kept++;
    for (int i = 0; i < nv; ++i)
      if (representative[i] == i && newIndex[i] < 0) ++report.unusedVertices;
  }
  else
  {
    for (int i = 0; i < nv; ++i)
      if (representative[i] == i) newIndex[i] = kept++;
  }

  TriangleMesh out;
  out.V.resize(kept, 3);
  for (int i = 0; i < nv; ++i)
    if (newIndex[i] >= 0) out.V.row(newIndex[i]) = mesh.V.row(i);
  out.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) out.F(static_cast<Eigen::Index>(f), k) = newIndex[faces[f][k]];
  if (vertexMap)
  {
    vertexMap->resize(nv);
    for (int i = 0; i < nv; ++i) (*vertexMap)[i] = newIndex[representative[i]];
  }
  mesh = std::move(out);

  if (report.mergedVertices)
    report.warnings.push_back("merged " + std::to_string(report.mergedVertices) +
                              " duplicated vertices");
  if (report.degenerateFaces)
    report.warnings.push_back("removed " + std::to_string(report.degenerateFaces) +
                              " zero-area faces");
  if (report.duplicateFaces)
    report.warnings.push_back("removed " + std::to_string(report.duplicateFaces) +
                              " repeated faces");
  if (report.unusedVertices)
    report.warnings.push_back("removed " + std::to_string(report.unusedVertices) +
                              " vertices used by no face");
  return report;
}

CleaningReport validateAndClean(TriangleMesh& mesh, const std::string& name,
                                const CleaningOptions& options)
{
  validateMesh(mesh, name);
  CleaningReport report = cleanMesh(mesh, options);
  if (mesh.numFaces() == 0) throw Error(name + ": every face has zero area");
  if (options.makeManifold)
  {
    const ManifoldRepairReport repair = makeManifold(mesh);
    report.nonManifoldFacesRemoved = repair.removedFaces;
    report.bowTieVerticesSplit = repair.splitVertices;
    if (repair.removedFaces)
      report.warnings.push_back("removed " + std::to_string(repair.removedFaces) +
                                " faces on edges shared by more than two faces (non-manifold)");
    if (repair.splitVertices)
      report.warnings.push_back("split " + std::to_string(repair.splitVertices) +
                                " non-manifold (bow-tie) vertices");
    if (repair.removedFaces)
    {
      CleaningOptions unusedOnly;
      unusedOnly.mergeDuplicateVertices = false;
      unusedOnly.removeDegenerateFaces = false;
      cleanMesh(mesh, unusedOnly); // vertices only the removed faces used
    }
  }
  return report;
}
} // namespace clothtrack
