/**
 * @class ctSurfaceTopology
 * @brief Connected components of a surface with their area, boundaries and genus.
 *
 * Adds cell and point arrays "ComponentId" (0 = largest component by area) and the point
 * array "VoronoiArea" (mixed Voronoi vertex areas), and a field data entry per component
 * property: ComponentArea, ComponentGenus, ComponentBoundaries, ComponentEulerCharacteristic.
 * Also reports NonManifoldEdges and NonManifoldVertices as field data.
 */
#ifndef ctSurfaceTopology_h
#define ctSurfaceTopology_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

class CTFILTERS_EXPORT ctSurfaceTopology : public vtkPolyDataAlgorithm
{
public:
  static ctSurfaceTopology* New();
  vtkTypeMacro(ctSurfaceTopology, vtkPolyDataAlgorithm);

protected:
  ctSurfaceTopology() = default;
  ~ctSurfaceTopology() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

private:
  ctSurfaceTopology(const ctSurfaceTopology&) = delete;
  void operator=(const ctSurfaceTopology&) = delete;
};

#endif
