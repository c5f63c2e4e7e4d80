#include "ctCaptureSimulation.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <random>

namespace clothtrack
{
namespace
{
struct Grid
{
  Vec3 origin;
  double h;
  int n[3];
  std::vector<float> values;
  size_t index(int i, int j, int k) const
  {
    return i + static_cast<size_t>(n[0]) * (j + static_cast<size_t>(n[1]) * k);
  }
  Vec3 point(int i, int j, int k) const { return origin + h * Vec3(i, j, k); }
};

// Fills the inside of a closed surface. Along each vertical line through voxel centres the
// winding number counts entries minus exits (from the triangle orientation), so that parts of
// a self-intersecting surface (skinned joints) stay filled where parity would empty them.
void fillClosed(const TriangleMesh& closed, Grid& grid)
{
  const SurfaceLocator locator(closed);
  const Points normals = faceNormals(closed);
  // Outward orientation from the sign of the enclosed volume.
  const double outward = signedVolume(closed) >= 0 ? 1.0 : -1.0;
  vtkSMPTools::For(0, grid.n[2],
                   [&](vtkIdType k0, vtkIdType k1)
                   {
                     for (vtkIdType k = k0; k < k1; ++k)
                       for (int i = 0; i < grid.n[0]; ++i)
                       {
                         const Vec3 base = grid.point(i, 0, static_cast<int>(k));
                         const auto hits = locator.intersectLine(base, Vec3::UnitY());
                         int winding = 0;
                         for (size_t a = 0; a + 1 < hits.size(); ++a)
                         {
                           winding += outward * normals(hits[a].point.face, 1) < 0 ? 1 : -1;
                           if (winding <= 0) continue;
                           const int j0 =
                               std::max(0, static_cast<int>(std::ceil(hits[a].t / grid.h)));
                           const int j1 = std::min(
                               grid.n[1] - 1, static_cast<int>(std::floor(hits[a + 1].t / grid.h)));
                           for (int j = j0; j <= j1; ++j)
                             grid.values[grid.index(i, j, static_cast<int>(k))] = 1.0f;
                         }
                       }
                   });
}

// Occupancy around an open surface, soft so that the 0.5 level lies at `radius` from the
// sheet: radius is half the thickness, but at least 0.6 voxel so that a sheet passing between
// voxel centres leaves no gap.
void fillSheet(const TriangleMesh& sheet, double thickness, Grid& grid)
{
  const SurfaceLocator locator(sheet);
  const double radius = std::max(0.5 * thickness, 0.6 * grid.h);
  const double reach = radius + grid.h;
  for (int f = 0; f < sheet.numFaces(); ++f)
  {
    Eigen::AlignedBox3d box;
    for (int c = 0; c < 3; ++c) box.extend(sheet.vertex(sheet.F(f, c)));
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::max(
          0, static_cast<int>(std::floor((box.min()[a] - reach - grid.origin[a]) / grid.h)));
      hi[a] =
          std::min(grid.n[a] - 1,
                   static_cast<int>(std::ceil((box.max()[a] + reach - grid.origin[a]) / grid.h)));
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
        {
          float& v = grid.values[grid.index(i, j, k)];
          if (v >= 1.0f) continue;
          const SurfacePoint p = locator.closestPoint(grid.point(i, j, k), reach);
          if (p.valid())
            v = std::max(
                v, static_cast<float>(std::clamp(0.5 + (radius - p.distance) / grid.h, 0.0, 1.0)));
        }
  }
}

// Fills, in every horizontal slice, the empty regions enclosed by occupied voxels: cameras
// around the person cannot see into them (the inside of a dress, the gap closed by an arm
// against the torso), so a multi-view reconstruction fills them like a visual hull.
void fillEnclosed(Grid& grid)
{
  const int nx = grid.n[0], nz = grid.n[2];
  vtkSMPTools::For(0, grid.n[1],
                   [&](vtkIdType j0, vtkIdType j1)
                   {
                     std::vector<char> outside(static_cast<size_t>(nx) * nz);
                     std::vector<int> stack;
                     for (vtkIdType j = j0; j < j1; ++j)
                     {
                       std::fill(outside.begin(), outside.end(), 0);
                       auto empty = [&](int i, int k)
                       { return grid.values[grid.index(i, static_cast<int>(j), k)] < 0.5f; };
                       auto push = [&](int i, int k)
                       {
                         const size_t id = i + static_cast<size_t>(nx) * k;
                         if (!outside[id] && empty(i, k))
                         {
                           outside[id] = 1;
                           stack.push_back(static_cast<int>(id));
                         }
                       };
                       for (int i = 0; i < nx; ++i)
                       {
                         push(i, 0);
                         push(i, nz - 1);
                       }
                       for (int k = 0; k < nz; ++k)
                       {
                         push(0, k);
                         push(nx - 1, k);
                       }
                       while (!stack.empty())
                       {
                         const int id = stack.back();
                         stack.pop_back();
                         const int i = id % nx, k = id / nx;
                         if (i > 0) push(i - 1, k);
                         if (i + 1 < nx) push(i + 1, k);
                         if (k > 0) push(i, k - 1);
                         if (k + 1 < nz) push(i, k + 1);
                       }
                       for (int k = 0; k < nz; ++k)
                         for (int i = 0; i < nx; ++i)
                           if (!outside[i + static_cast<size_t>(nx) * k])
                             grid.values[grid.index(i, static_cast<int>(j), k)] = 1.0f;
                     }
                   });
}

// Separable [1 2 1]/4 smoothing, so that the extracted surface is not a staircase.
void smooth(Grid& grid)
{
  std::vector<float> tmp(grid.values.size());
  for (int axis = 0; axis < 3; ++axis)
  {
    const size_t stride = axis == 0   ? 1
                          : axis == 1 ? grid.n[0]
                                      : static_cast<size_t>(grid.n[0]) * grid.n[1];
    for (int k = 0; k < grid.n[2]; ++k)
      for (int j = 0; j < grid.n[1]; ++j)
        for (int i = 0; i < grid.n[0]; ++i)
        {
          const int c[3] = {i, j, k};
          const size_t id = grid.index(i, j, k);
          const float left = c[axis] > 0 ? grid.values[id - stride] : 0.0f;
          const float right = c[axis] + 1 < grid.n[axis] ? grid.values[id + stride] : 0.0f;
          tmp[id] = 0.25f * left + 0.5f * grid.values[id] + 0.25f * right;
        }
    grid.values.swap(tmp);
  }
}

void punchHoles(TriangleMesh& mesh, const CaptureOptions& options, std::mt19937& rng)
{
  if (options.holes <= 0 || mesh.numVertices() == 0) return;
  std::uniform_int_distribution<int> pick(0, mesh.numVertices() - 1);
  std::vector<Vec3> centres;
  for (int h = 0; h < options.holes; ++h) centres.push_back(mesh.vertex(pick(rng)));
  std::vector<int> kept;
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    const Vec3 c =
        (mesh.vertex(mesh.F(f, 0)) + mesh.vertex(mesh.F(f, 1)) + mesh.vertex(mesh.F(f, 2))) / 3.0;
    bool inHole = false;
    for (const Vec3& centre : centres) inHole = inHole || (c - centre).norm() < options.holeRadius;
    if (!inHole) kept.push_back(f);
  }
  Triangles faces(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t f = 0; f < kept.size(); ++f)
    faces.row(static_cast<Eigen::Index>(f)) = mesh.F.row(kept[f]);
  mesh.F = faces;
  cleanMesh(mesh); // drops the vertices the holes left unused
}
} // namespace

TriangleMesh simulateCapture(const TriangleMesh& truth, const CaptureOptions& options,
                             SourceMap* sourceMap)
{
  if (!(options.voxelSize > 0)) throw Error("capture simulation: the voxel size must be positive");
  validateMesh(truth, "capture simulation input");
  Eigen::AlignedBox3d box;
  for (int i = 0; i < truth.numVertices(); ++i) box.extend(truth.vertex(i));
  Grid grid;
  grid.h = options.voxelSize;
  const double margin = 3 * grid.h + options.sheetThickness;
  grid.origin = box.min() - Vec3::Constant(margin);
  for (int a = 0; a < 3; ++a)
    grid.n[a] = static_cast<int>(std::ceil((box.sizes()[a] + 2 * margin) / grid.h)) + 1;
  const double voxels = static_cast<double>(grid.n[0]) * grid.n[1] * grid.n[2];
  if (voxels > 2e8)
    throw Error("capture simulation: the grid would have " +
                std::to_string(static_cast<long>(voxels)) + " voxels; use a larger voxel size");
  grid.values.assign(static_cast<size_t>(voxels), 0.0f);

  const MeshTopology topology = buildTopology(truth);
  const Components components = connectedComponents(truth, topology);
  for (int c = 0; c < components.count(); ++c)
  {
    const TriangleMesh part = extractComponent(truth, components, c);
    if (components.info[c].numBoundaries == 0)
      fillClosed(part, grid);
    else
      fillSheet(part, options.sheetThickness, grid);
  }
  if (options.fillEnclosed) fillEnclosed(grid);
  smooth(grid);

  vtkNew<vtkImageData> image;
  image->SetDimensions(grid.n);
  image->SetOrigin(grid.origin.data());
  image->SetSpacing(grid.h, grid.h, grid.h);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetArray(grid.values.data(), static_cast<vtkIdType>(grid.values.size()), 1);
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  if (contour->GetOutput()->GetNumberOfPoints() == 0)
    throw Error("capture simulation: nothing captured (surface thinner than the voxels?)");
  TriangleMesh captured = toTriangleMesh(contour->GetOutput(), "captured surface");
  cleanMesh(captured);

  std::mt19937 rng(options.seed);
  punchHoles(captured, options, rng);
  if (options.noise > 0)
  {
    std::normal_distribution<double> noise(0.0, options.noise);
    const Points normals = vertexNormals(captured);
    for (int i = 0; i < captured.numVertices(); ++i)
      captured.V.row(i) += noise(rng) * normals.row(i);
  }

  if (sourceMap)
  {
    const SurfaceLocator locator(truth);
    const int n = captured.numVertices();
    sourceMap->face.assign(n, -1);
    sourceMap->barycentric.assign(n, Vec3::Zero());
    sourceMap->distance.assign(n, 0.0);
    vtkSMPTools::For(0, n,
                     [&](vtkIdType a, vtkIdType b)
                     {
                       for (vtkIdType i = a; i < b; ++i)
                       {
                         const SurfacePoint p =
                             locator.closestPoint(captured.vertex(static_cast<int>(i)));
                         sourceMap->face[i] = p.face;
                         sourceMap->barycentric[i] = p.bary;
                         sourceMap->distance[i] = p.distance;
                       }
                     });
  }
  return captured;
}

void addSourceMapArrays(const SourceMap& map, vtkPolyData* mesh)
{
  const vtkIdType n = static_cast<vtkIdType>(map.face.size());
  vtkNew<vtkIntArray> face;
  face->SetName("SourceFace");
  face->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("SourceBarycentric");
  bary->SetNumberOfComponents(3);
  bary->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("SourceDistance");
  distance->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    face->SetValue(i, map.face[i]);
    bary->SetTuple(i, map.barycentric[i].data());
    distance->SetValue(i, map.distance[i]);
  }
  mesh->GetPointData()->AddArray(face);
  mesh->GetPointData()->AddArray(bary);
  mesh->GetPointData()->AddArray(distance);
}
} // namespace clothtrack
