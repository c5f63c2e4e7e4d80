#ifndef ctLandmarkPolyData_h
#define ctLandmarkPolyData_h
// Oriented landmarks transferred onto a frame, as vtkPolyData: one vertex per body landmark
// (on the frame when valid, at the body point when not) with point data Valid, Direction,
// Offset, FrameFace, FrameBarycentric and field data FoundFraction. C++ only (not wrapped).
#include "ctFiltersModule.h"

#include <clothtrack/body/BodyModel.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace clothtrack
{
CTFILTERS_EXPORT vtkSmartPointer<vtkPolyData>
transferredLandmarksToPolyData(const std::vector<OrientedPoint>& bodyPoints,
                               const std::vector<TransferredLandmark>& transferred);

/// The valid landmarks of such a polydata as surface points (id from LandmarkId, else the point
/// index; offset from Offset when present). Throws Error naming `name` when Valid, FrameFace,
/// FrameBarycentric or Direction is missing or a face is outside [0, numFaces).
CTFILTERS_EXPORT std::vector<OrientedSurfacePoint>
landmarkSurfacePoints(vtkPolyData* landmarks, int numFaces, const std::string& name);
/// Adds LandmarkId, LandmarkName and VertexId (the model's landmark order) to `landmarks`.
CTFILTERS_EXPORT void addLandmarkIdentity(const BodyModel& model, vtkPolyData* landmarks);
} // namespace clothtrack

#endif
