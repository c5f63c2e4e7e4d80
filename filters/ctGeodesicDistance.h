/**
 * @class ctGeodesicDistance
 * @brief Geodesic distance from a set of source points over a triangle surface.
 *
 * Adds the point array "GeodesicDistance" (metres; NaN where no source is reachable or beyond
 * DistanceLimit). Methods: DIJKSTRA (shortest edge paths, fast, overestimates), FAST_MARCHING
 * (default: triangle-unfolding updates, local and accurate) and HEAT (Crane et al. 2013,
 * prefactored sparse Cholesky; most accurate on clean meshes, always global).
 */
#ifndef ctGeodesicDistance_h
#define ctGeodesicDistance_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <vector>

class CTFILTERS_EXPORT ctGeodesicDistance : public vtkPolyDataAlgorithm
{
public:
  static ctGeodesicDistance* New();
  vtkTypeMacro(ctGeodesicDistance, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    DIJKSTRA = 0,
    FAST_MARCHING = 1,
    HEAT = 2
  };
  vtkSetClampMacro(Method, int, DIJKSTRA, HEAT);
  vtkGetMacro(Method, int);

  /// Distances beyond this are not computed (reported as NaN); <= 0 means no limit.
  vtkSetClampMacro(DistanceLimit, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DistanceLimit, double);

  void AddSourcePoint(vtkIdType pointId);
  void ClearSourcePoints();
  int GetNumberOfSourcePoints() const { return static_cast<int>(this->SourcePoints.size()); }

protected:
  ctGeodesicDistance() = default;
  ~ctGeodesicDistance() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  int Method = FAST_MARCHING;
  double DistanceLimit = 0.0;
  std::vector<vtkIdType> SourcePoints;

private:
  ctGeodesicDistance(const ctGeodesicDistance&) = delete;
  void operator=(const ctGeodesicDistance&) = delete;
};

#endif
