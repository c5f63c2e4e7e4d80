// Landmark transfer from the body onto clothed captures, against the ground-truth garment.
#include "ctBodyModelSource.h"
#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctLandmarkTransfer.h"
#include "ctMeshConversion.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/body/OrientedLandmarks.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace clothtrack;

TEST(LandmarkTransfer, OnCapturedDressFramesAgainstTheGroundTruth)
{
  const BodyModel& model = builtinBodyModel();
  for (const char* preset : {"dress-walk", "trousers-squat"})
  {
    SyntheticOptions options;
    options.preset = preset;
    options.frames = 16;
    double errorSum = 0;
    int matched = 0, found = 0, total = 0;
    generateSyntheticSequence(
        model, options,
        [&](const SyntheticFrame& frame)
        {
          if (frame.index % 5 != 0) return;
          const auto points = orientedLandmarks(model, frame.body);
          // Reference: the same rule on the true clothed surface.
          const SurfaceLocator truthLocator(frame.clothed);
          const auto truth = transferLandmarks(points, frame.clothed, truthLocator);
          CaptureOptions capture;
          const TriangleMesh captured = simulateCapture(frame.clothed, capture);
          const SurfaceLocator locator(captured);
          const auto estimate = transferLandmarks(points, captured, locator);
          for (size_t k = 0; k < points.size(); ++k)
          {
            ++total;
            found += estimate[k].valid;
            if (estimate[k].valid && truth[k].valid)
            {
              errorSum += (estimate[k].point.position - truth[k].point.position).norm();
              ++matched;
            }
          }
        });
    const double meanError = errorSum / matched, foundFraction = static_cast<double>(found) / total;
    std::printf("[ measured ] %s: landmarks found on the capture %.1f %%, mean distance to the "
                "ground-truth "
                "garment point %.2f cm\n",
                preset, 100 * foundFraction, 100 * meanError);
    EXPECT_GT(foundFraction, 0.85);
    EXPECT_LT(meanError, 0.03);
  }
}

TEST(LandmarkTransfer, FilterPlacesLandmarksOnAShiftedSurfaceAndDropsFarOnes)
{
  // The body pushed 3 cm outward along its normals: landmarks land 3 cm out.
  vtkNew<ctBodyModelSource> body;
  body->Update();
  TriangleMesh mesh = toTriangleMesh(body->GetOutput(), "body");
  const Points normals = vertexNormals(mesh);
  mesh.V += 0.03 * normals;
  vtkNew<ctLandmarkTransfer> transfer;
  transfer->SetInputData(0, toPolyData(mesh));
  transfer->SetBodyLandmarksConnection(body->GetOutputPort(1));
  transfer->Update();
  vtkPolyData* out = transfer->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 40);
  const double found = out->GetFieldData()->GetArray("FoundFraction")->GetTuple1(0);
  EXPECT_GT(found, 0.9);
  vtkDataArray* offset = out->GetPointData()->GetArray("Offset");
  vtkDataArray* valid = out->GetPointData()->GetArray("Valid");
  for (vtkIdType k = 0; k < 40; ++k)
  {
    if (valid->GetTuple1(k))
    {
      EXPECT_NEAR(offset->GetTuple1(k), 0.03, 0.01);
    }
  }
  // Nothing within 2 cm outside: the rule falls back to crossings inside the body (the far side
  // of a limb, within 20 cm) ...
  transfer->SetOutsideTolerance(0.02);
  transfer->Update();
  out = transfer->GetOutput();
  offset = out->GetPointData()->GetArray("Offset");
  valid = out->GetPointData()->GetArray("Valid");
  for (vtkIdType k = 0; k < 40; ++k)
  {
    if (valid->GetTuple1(k))
    {
      EXPECT_LT(offset->GetTuple1(k), 0.0);
    }
  }
  // ... and with nothing inside within 2 cm either, every landmark is dropped.
  transfer->SetInsideTolerance(0.02);
  transfer->Update();
  EXPECT_EQ(transfer->GetOutput()->GetFieldData()->GetArray("FoundFraction")->GetTuple1(0), 0.0);
}
