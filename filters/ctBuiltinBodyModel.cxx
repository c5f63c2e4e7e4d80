#include "ctBuiltinBodyModel.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/BodyModelBuilder.h>
#include <clothtrack/body/ProceduralBody.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSMPTools.h>
#include <vtkWindowedSincPolyDataFilter.h>

namespace clothtrack
{
TriangleMesh proceduralBodyMesh(double stature, int targetVertices)
{
  const SkeletonGeometry skeleton = proceduralSkeleton(stature);
  // A 6 mm grid resolves the thumbs and the nose; decimation then brings it to the target size.
  const double h = 0.0035 * stature;
  const double lo[3] = {-0.45 * stature, -0.01 * stature, -0.12 * stature};
  const double hi[3] = {0.45 * stature, 1.01 * stature, 0.16 * stature};
  int dims[3];
  for (int k = 0; k < 3; ++k) dims[k] = static_cast<int>((hi[k] - lo[k]) / h) + 1;
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(dims);
  grid->SetOrigin(lo[0], lo[1], lo[2]);
  grid->SetSpacing(h, h, h);
  vtkNew<vtkFloatArray> distance;
  distance->SetNumberOfTuples(static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2]);
  vtkSMPTools::For(
      0, dims[2],
      [&](vtkIdType k0, vtkIdType k1)
      {
        for (vtkIdType k = k0; k < k1; ++k)
          for (int j = 0; j < dims[1]; ++j)
            for (int i = 0; i < dims[0]; ++i)
              distance->SetValue(
                  i + dims[0] * (j + dims[1] * k),
                  static_cast<float>(proceduralBodyDistance(
                      skeleton, stature, Vec3(lo[0] + i * h, lo[1] + j * h, lo[2] + k * h))));
      });
  grid->GetPointData()->SetScalars(distance);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputConnection(contour->GetOutputPort());
  contour->Update();
  const double ratio =
      1.0 - static_cast<double>(targetVertices) / contour->GetOutput()->GetNumberOfPoints();
  decimate->SetTargetReduction(std::clamp(ratio, 0.0, 0.99));
  decimate->VolumePreservationOn();
  vtkNew<vtkWindowedSincPolyDataFilter> smooth;
  smooth->SetInputConnection(decimate->GetOutputPort());
  smooth->SetNumberOfIterations(20);
  smooth->SetPassBand(0.1);
  smooth->NormalizeCoordinatesOn();
  smooth->BoundarySmoothingOff();
  smooth->FeatureEdgeSmoothingOff();
  smooth->Update();

  TriangleMesh mesh = toTriangleMesh(smooth->GetOutput(), "procedural body");
  validateAndClean(mesh, "procedural body");
  // Keep the one body shell (decimation never splits it, but be certain).
  const Components components = connectedComponents(mesh, buildTopology(mesh));
  if (components.count() > 1) mesh = extractComponent(mesh, components, 0);
  // Body models face outward: normals point away from the body (landmark transfer relies on it).
  if (signedVolume(mesh) < 0) mesh.F.col(1).swap(mesh.F.col(2));
  return mesh;
}

BodyModel proceduralBodyModel(const BodySpread& spread)
{
  const double stature = 1.72;
  BodyModelBuildOptions options;
  options.spread = spread;
  return buildBodyModel(proceduralBodyMesh(stature), proceduralSkeleton(stature), stature, options);
}

const BodyModel& builtinBodyModel()
{
  static const BodyModel model = proceduralBodyModel(BodySpread{});
  return model;
}
} // namespace clothtrack
