/**
 * @class ctSurfaceReconstruction
 * @brief Makes a captured point cloud (depth cameras, multi-view stereo, LiDAR) into a mesh.
 *
 * Points with NaN coordinates are dropped; isolated points are removed (statistical outlier
 * test over OutlierNeighbours, OutlierDeviations); the density is evened on a voxel grid
 * (VoxelSize); normals are estimated over NormalNeighbours points and oriented consistently
 * (the input's "Normals" are used when present); a watertight Poisson surface of octree depth
 * PoissonDepth is fitted; and every part further than CropDistance from the points is cut away,
 * so that no skin is invented where no camera looked. Cells of the input are ignored.
 *
 * The output's field data say how sure the result is: ReconstructionPieces,
 * ReconstructionBoundaryLoops, ReconstructionGenus, ReconstructionUnexplainedShare (points more
 * than 1 cm from the surface), ReconstructionMeanPointDistance, and ReconstructionDoubts (empty
 * when the result looks like a captured surface; each doubt is also a warning).
 *
 * Uses PCL's surface library, which links Debian's VTK 9.1: the filter is not part of the
 * ParaView plugin built against Debian's ParaView (which carries its own VTK).
 */
#ifndef ctSurfaceReconstruction_h
#define ctSurfaceReconstruction_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

class CTFILTERS_EXPORT ctSurfaceReconstruction : public vtkPolyDataAlgorithm
{
public:
  static ctSurfaceReconstruction* New();
  vtkTypeMacro(ctSurfaceReconstruction, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Voxel-grid thinning, metres (0 keeps every point).
  vtkSetClampMacro(VoxelSize, double, 0.0, 0.1);
  vtkGetMacro(VoxelSize, double);
  /// Neighbours of the statistical outlier test (0: no test).
  vtkSetClampMacro(OutlierNeighbours, int, 0, 200);
  vtkGetMacro(OutlierNeighbours, int);
  /// A point whose mean neighbour distance exceeds the cloud's by this many deviations goes.
  vtkSetClampMacro(OutlierDeviations, double, 0.1, 100.0);
  vtkGetMacro(OutlierDeviations, double);
  /// Points in each plane fitted for a normal.
  vtkSetClampMacro(NormalNeighbours, int, 3, 200);
  vtkGetMacro(NormalNeighbours, int);
  /// Poisson octree depth: 7 gives cells of about 1.5 cm for a person.
  vtkSetClampMacro(PoissonDepth, int, 5, 12);
  vtkGetMacro(PoissonDepth, int);
  /// Surface further than this from every point is cut away, metres.
  vtkSetClampMacro(CropDistance, double, 0.001, 0.5);
  vtkGetMacro(CropDistance, double);

protected:
  ctSurfaceReconstruction() = default;
  ~ctSurfaceReconstruction() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  double VoxelSize = 0.005;
  int OutlierNeighbours = 16;
  double OutlierDeviations = 2.0;
  int NormalNeighbours = 20;
  int PoissonDepth = 7;
  double CropDistance = 0.02;

private:
  ctSurfaceReconstruction(const ctSurfaceReconstruction&) = delete;
  void operator=(const ctSurfaceReconstruction&) = delete;
};

#endif
