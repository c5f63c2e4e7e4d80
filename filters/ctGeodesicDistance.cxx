#include "ctGeodesicDistance.h"

#include "ctFirstPieceOnly.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/Geodesic.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>

vtkStandardNewMacro(ctGeodesicDistance);

void ctGeodesicDistance::AddSourcePoint(vtkIdType pointId)
{
  this->SourcePoints.push_back(pointId);
  this->Modified();
}

void ctGeodesicDistance::ClearSourcePoints()
{
  if (this->SourcePoints.empty()) return;
  this->SourcePoints.clear();
  this->Modified();
}

int ctGeodesicDistance::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->ShallowCopy(input);
  if (this->SourcePoints.empty())
  {
    vtkErrorMacro(<< "no source point given");
    return 0;
  }
  try
  {
    const clothtrack::TriangleMesh mesh =
        clothtrack::toTriangleMesh(input, "geodesic distance input");
    clothtrack::validateMesh(mesh, "geodesic distance input");
    std::vector<int> sources;
    for (vtkIdType id : this->SourcePoints)
    {
      if (id < 0 || id >= mesh.numVertices())
        throw clothtrack::Error("source point " + std::to_string(id) + " is out of range [0, " +
                                std::to_string(mesh.numVertices()) + ")");
      sources.push_back(static_cast<int>(id));
    }
    const double limit = this->DistanceLimit > 0 ? this->DistanceLimit : clothtrack::kUnreached;
    this->UpdateProgress(0.1);
    Eigen::VectorXd d;
    if (this->Method == HEAT)
      d = clothtrack::HeatGeodesic(mesh).distances(sources, limit);
    else
      d = clothtrack::WavefrontGeodesic(
              mesh, this->Method == DIJKSTRA ? clothtrack::WavefrontGeodesic::Method::Dijkstra
                                             : clothtrack::WavefrontGeodesic::Method::FastMarching)
              .distances(sources, limit);
    vtkNew<vtkDoubleArray> distance;
    distance->SetName("GeodesicDistance");
    distance->SetNumberOfTuples(d.size());
    for (Eigen::Index i = 0; i < d.size(); ++i)
      distance->SetValue(i, std::isfinite(d[i]) ? d[i] : std::numeric_limits<double>::quiet_NaN());
    output->GetPointData()->AddArray(distance);
    output->GetPointData()->SetActiveScalars("GeodesicDistance");
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctGeodesicDistance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << this->Method << "\n";
  os << indent << "DistanceLimit: " << this->DistanceLimit << "\n";
  os << indent << "SourcePoints: " << this->SourcePoints.size() << "\n";
}
