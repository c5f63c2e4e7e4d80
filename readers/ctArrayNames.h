#ifndef ctArrayNames_h
#define ctArrayNames_h
// Names of the arrays that one ClothTrack filter writes and another reads. A filter that writes
// or reads one of them uses the constant, so that the two sides cannot drift apart. C++ only (not
// wrapped).
namespace clothtrack::arrays
{
// Field data of every frame block.
constexpr const char* FrameIndex = "FrameIndex";   ///< position of the block in the sequence
constexpr const char* FrameNumber = "FrameNumber"; ///< frame number of the input file
constexpr const char* TimeValue = "TimeValue";     ///< seconds
constexpr const char* SourceFile = "SourceFile";   ///< the file the frame was read from
constexpr const char* TemplateFrame = "TemplateFrame";
constexpr const char* RestPoseDistance = "RestPoseDistance"; ///< fitted body from the rest pose

// Landmarks (ctBodyFit output 1, ctLandmarkTransfer): one point per model landmark.
constexpr const char* LandmarkValid = "Valid";
constexpr const char* LandmarkId = "LandmarkId";
constexpr const char* LandmarkVertex = "VertexId";
constexpr const char* LandmarkName = "LandmarkName";
constexpr const char* LandmarkFace = "FrameFace";
constexpr const char* LandmarkBarycentric = "FrameBarycentric";
constexpr const char* LandmarkDirection = "Direction";
constexpr const char* LandmarkOffset = "Offset";
constexpr const char* LandmarksFound = "FoundFraction";

// Correspondences (ctPatchCorrespondence output 0): one point per template vertex.
constexpr const char* Matched = "Matched";
constexpr const char* TargetPosition = "TargetPosition";
constexpr const char* MatchedFraction = "MatchedFraction";
} // namespace clothtrack::arrays

#endif
