#ifndef ctFirstPieceOnly_h
#define ctFirstPieceOnly_h
// ClothTrack's algorithms work on whole sequences, which do not split into spatial pieces. When
// several processes share a pipeline (pvbatch --mpi, or any vtkMultiProcessController), each
// process asks for its own piece: the first piece gets the whole result and the others stay
// empty, so that no result is computed twice or shown twice. C++ only.
#include "ctReadersModule.h"

class vtkInformation;
class vtkInformationVector;

namespace clothtrack
{
/// True when the request is for a piece other than the first: every output is then emptied and
/// RequestData has nothing more to do.
CTREADERS_EXPORT bool leaveOtherPieceEmpty(vtkInformationVector* outputVector);
/// This process's index among the global controller's processes (0 without one).
CTREADERS_EXPORT int processIndex();
/// For a sink (a writer): asks its input for this process's piece of as many as there are
/// processes, so that the whole result arrives on the first process only.
CTREADERS_EXPORT void requestProcessPiece(vtkInformation* inputInformation);
} // namespace clothtrack

#endif
