#include "ctBuiltinBodyModel.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/BodyModelBuilder.h>
#include <clothtrack/body/ProceduralBody.h>
#include <clothtrack/body/ProceduralBodyGrid.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkWindowedSincPolyDataFilter.h>

namespace clothtrack
{
TriangleMesh proceduralBodyMesh(double stature, int targetVertices)
{
  const SkeletonGeometry skeleton = proceduralSkeleton(stature);
  // Contoured at 6 mm, then decimated to the target size.
  const DistanceGrid samples = builtinBodyGrid(stature);
  std::vector<float> values = proceduralBodyDistanceGrid(skeleton, stature, samples);
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(samples.dims.data());
  grid->SetOrigin(samples.origin.data());
  grid->SetSpacing(samples.spacing, samples.spacing, samples.spacing);
  vtkNew<vtkFloatArray> distance;
  // Borrowed, not copied: `values` outlives every filter below (saved: VTK does not free it).
  distance->SetArray(values.data(), static_cast<vtkIdType>(values.size()), 1);
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
