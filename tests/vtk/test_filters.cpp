#include "ctGeodesicDistance.h"
#include "ctMeshConversion.h"
#include "ctSurfaceTopology.h"

#include <clothtrack/mesh/Primitives.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace clothtrack;

TEST(GeodesicDistanceFilter, SphereDistancesFromAPole)
{
  const TriangleMesh sphere = icosphere(4, 2.0);
  for (int method :
       {ctGeodesicDistance::DIJKSTRA, ctGeodesicDistance::FAST_MARCHING, ctGeodesicDistance::HEAT})
  {
    SCOPED_TRACE(method);
    vtkNew<ctGeodesicDistance> filter;
    filter->SetInputData(toPolyData(sphere));
    filter->AddSourcePoint(0);
    filter->SetMethod(method);
    filter->Update();
    vtkDataArray* d = filter->GetOutput()->GetPointData()->GetArray("GeodesicDistance");
    ASSERT_NE(d, nullptr);
    double meanError = 0;
    const Vec3 p0 = sphere.vertex(0).normalized();
    for (int v = 0; v < sphere.numVertices(); ++v)
      meanError +=
          std::abs(d->GetTuple1(v) -
                   2.0 * std::acos(std::clamp(p0.dot(sphere.vertex(v).normalized()), -1.0, 1.0)));
    meanError /= sphere.numVertices();
    EXPECT_LT(meanError, method == ctGeodesicDistance::DIJKSTRA ? 0.25 : 0.05);
  }
}

TEST(GeodesicDistanceFilter, LimitGivesNaNBeyond)
{
  vtkNew<ctGeodesicDistance> filter;
  filter->SetInputData(toPolyData(icosphere(3)));
  filter->AddSourcePoint(5);
  filter->SetDistanceLimit(0.3);
  filter->Update();
  vtkDataArray* d = filter->GetOutput()->GetPointData()->GetArray("GeodesicDistance");
  int finite = 0;
  for (vtkIdType v = 0; v < d->GetNumberOfTuples(); ++v)
    finite += std::isfinite(d->GetTuple1(v)) ? 1 : 0;
  EXPECT_GT(finite, 5);
  EXPECT_LT(finite, d->GetNumberOfTuples() / 4);
}

TEST(GeodesicDistanceFilter, BadSourceFails)
{
  vtkNew<ctGeodesicDistance> filter;
  filter->SetInputData(toPolyData(icosphere(1)));
  filter->AddSourcePoint(1000);
  filter->GlobalWarningDisplayOff();
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetArray("GeodesicDistance"), nullptr);
  filter->GlobalWarningDisplayOn();
}

TEST(SurfaceTopologyFilter, TorusAndSphere)
{
  const TriangleMesh both = concatenate(torus(1.0, 0.3, 30, 12), icosphere(2, 0.2, Vec3(4, 0, 0)));
  vtkNew<ctSurfaceTopology> filter;
  filter->SetInputData(toPolyData(both));
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* genus = out->GetFieldData()->GetArray("ComponentGenus");
  ASSERT_NE(genus, nullptr);
  ASSERT_EQ(genus->GetNumberOfTuples(), 2);
  EXPECT_EQ(genus->GetTuple1(0), 1); // the torus is the larger
  EXPECT_EQ(genus->GetTuple1(1), 0);
  vtkDataArray* area = out->GetPointData()->GetArray("VoronoiArea");
  double sum = 0;
  for (vtkIdType i = 0; i < area->GetNumberOfTuples(); ++i) sum += area->GetTuple1(i);
  EXPECT_NEAR(sum, surfaceArea(both), 1e-9);
  EXPECT_EQ(out->GetFieldData()->GetArray("NonManifoldEdges")->GetTuple1(0), 0);
}
