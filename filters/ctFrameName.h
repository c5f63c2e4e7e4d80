#ifndef ctFrameName_h
#define ctFrameName_h
// How filters name a frame of a sequence in their messages. C++ only (not wrapped).
#include "ctFiltersModule.h"

#include <string>

class vtkDataObject;

namespace clothtrack
{
/// "frame K (file)" when the reader recorded the frame's SourceFile, else "frame K".
CTFILTERS_EXPORT std::string frameName(vtkDataObject* block, int index);
} // namespace clothtrack

#endif
