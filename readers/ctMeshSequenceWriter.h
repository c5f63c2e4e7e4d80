/**
 * @class ctMeshSequenceWriter
 * @brief Writes a mesh sequence as a ParaView collection: `name.pvd` plus one `.vtp` per frame.
 *
 * FileName is the `.pvd` path; frames go to a folder beside it with the same stem
 * (`out/aligned.pvd` -> `out/aligned/aligned_0000.vtp`, ...). The input is either a
 * vtkMultiBlockDataSet holding one vtkPolyData per frame (time k / FrameRate, or the frame's
 * TimeValue field), or a temporal vtkPolyData, in which case every time step of the input is
 * requested and written in turn. With WriteOBJ on, each frame is also written as `.obj`.
 * Every file is written under a temporary name and renamed when complete. When several
 * processes share the pipeline (pvbatch --mpi), the first one writes the whole sequence.
 */
#ifndef ctMeshSequenceWriter_h
#define ctMeshSequenceWriter_h

#include "ctReadersModule.h"

#include <vtkWriter.h>

#include <string>
#include <vector>

class CTREADERS_EXPORT ctMeshSequenceWriter : public vtkWriter
{
public:
  static ctMeshSequenceWriter* New();
  vtkTypeMacro(ctMeshSequenceWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// Also write every frame as Wavefront OBJ.
  vtkSetMacro(WriteOBJ, bool);
  vtkGetMacro(WriteOBJ, bool);
  vtkBooleanMacro(WriteOBJ, bool);

  /// Time of frame k for a multi-block input whose frames carry no TimeValue.
  vtkSetClampMacro(FrameRate, double, 1e-6, 1e6);
  vtkGetMacro(FrameRate, double);

  /// Number of frames written by the last Write().
  vtkGetMacro(NumberOfFramesWritten, int);

protected:
  ctMeshSequenceWriter();
  ~ctMeshSequenceWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) override;
  void WriteData() override {}

  std::string FileName;
  bool WriteOBJ = false;
  double FrameRate = 25.0;
  int NumberOfFramesWritten = 0;

private:
  ctMeshSequenceWriter(const ctMeshSequenceWriter&) = delete;
  void operator=(const ctMeshSequenceWriter&) = delete;

  bool WriteFrame(vtkDataObject* frame, int index, double time);
  bool WriteCollection();
  int Finish(bool framesWritten);

  std::vector<double> InputTimes;
  std::vector<std::pair<double, std::string>> Written;
  int CurrentTimeIndex = 0;
};

#endif
