#include "ctSurfaceTopology.h"

#include "ctFirstPieceOnly.h"
#include "ctNamedArrays.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/Laplacian.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(ctSurfaceTopology);

int ctSurfaceTopology::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  try
  {
    const clothtrack::TriangleMesh mesh =
        clothtrack::toTriangleMesh(input, "surface topology input");
    clothtrack::validateMesh(mesh, "surface topology input");
    // The output carries the triangles actually analysed, so cell arrays match cells.
    output->ShallowCopy(clothtrack::toPolyData(mesh));
    output->GetPointData()->PassData(input->GetPointData());
    const clothtrack::MeshTopology topology = clothtrack::buildTopology(mesh);
    const clothtrack::Components components = clothtrack::connectedComponents(mesh, topology);
    const clothtrack::ManifoldReport manifold = clothtrack::checkManifold(mesh, topology);
    const Eigen::VectorXd areas = clothtrack::mixedVoronoiAreas(mesh);

    auto cellComponent = clothtrack::namedArray<vtkIntArray>("ComponentId", mesh.numFaces());
    for (int f = 0; f < mesh.numFaces(); ++f) cellComponent->SetValue(f, components.faceLabel[f]);
    auto pointComponent = clothtrack::namedArray<vtkIntArray>("ComponentId", mesh.numVertices());
    auto voronoi = clothtrack::namedArray<vtkDoubleArray>("VoronoiArea", mesh.numVertices());
    for (int v = 0; v < mesh.numVertices(); ++v)
    {
      pointComponent->SetValue(v, components.vertexLabel[v]);
      voronoi->SetValue(v, areas[v]);
    }
    output->GetCellData()->AddArray(cellComponent);
    output->GetPointData()->AddArray(pointComponent);
    output->GetPointData()->AddArray(voronoi);

    const int nc = components.count();
    auto area = clothtrack::namedArray<vtkDoubleArray>("ComponentArea", nc);
    auto genus = clothtrack::namedArray<vtkIntArray>("ComponentGenus", nc);
    auto boundaries = clothtrack::namedArray<vtkIntArray>("ComponentBoundaries", nc);
    auto euler = clothtrack::namedArray<vtkIntArray>("ComponentEulerCharacteristic", nc);
    for (int c = 0; c < nc; ++c)
    {
      area->SetValue(c, components.info[c].area);
      genus->SetValue(c, components.info[c].genus());
      boundaries->SetValue(c, components.info[c].numBoundaries);
      euler->SetValue(c, components.info[c].eulerCharacteristic());
    }
    auto nmEdges = clothtrack::namedArray<vtkIntArray>("NonManifoldEdges", 1);
    nmEdges->SetValue(0, manifold.nonManifoldEdges);
    auto nmVertices = clothtrack::namedArray<vtkIntArray>("NonManifoldVertices", 1);
    nmVertices->SetValue(0, manifold.nonManifoldVertices);
    for (vtkAbstractArray* a :
         {static_cast<vtkAbstractArray*>(area), static_cast<vtkAbstractArray*>(genus),
          static_cast<vtkAbstractArray*>(boundaries), static_cast<vtkAbstractArray*>(euler),
          static_cast<vtkAbstractArray*>(nmEdges), static_cast<vtkAbstractArray*>(nmVertices)})
      output->GetFieldData()->AddArray(a);
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}
