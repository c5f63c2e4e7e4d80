#ifndef ctFrameName_h
#define ctFrameName_h
// How filters name and read the frames of a sequence input (a vtkMultiBlockDataSet of
// vtkPolyData). C++ only (not wrapped).
#include "ctFiltersModule.h"

#include <clothtrack/mesh/TriangleMesh.h>

#include <string>

class vtkDataObject;
class vtkMultiBlockDataSet;

namespace clothtrack
{
/// "frame K (file)" when the reader recorded the frame's SourceFile, else "frame K".
CTFILTERS_EXPORT std::string frameName(vtkDataObject* block, int index);

/// Frame `index` of `sequence` as a validated triangle mesh; throws Error naming the frame when
/// it is not a vtkPolyData or not a usable mesh.
CTFILTERS_EXPORT TriangleMesh frameMesh(vtkMultiBlockDataSet* sequence, int index);

/// Throws Error unless `perFrame` has one block per frame of `sequence` (which must have some).
/// `filter` and `what` name the filter and the per-frame input in the message.
CTFILTERS_EXPORT void checkOneBlockPerFrame(vtkMultiBlockDataSet* sequence,
                                            vtkMultiBlockDataSet* perFrame,
                                            const std::string& filter, const std::string& what);
} // namespace clothtrack

#endif
