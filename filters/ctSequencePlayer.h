/**
 * @class ctSequencePlayer
 * @brief Presents a whole-sequence result (one block per frame) as a temporal polydata, so that
 * ParaView's Play and time scrubbing step through it.
 *
 * Input: a vtkMultiBlockDataSet with one vtkPolyData per frame, such as output 0 of
 * ctTemplateFit or ctAlignmentError, or output 1 of ctMeshSequenceReader.
 * Output: the block of the requested time. Block k's time is its field value TimeValue when
 * every block has one (frames read by ctMeshSequenceReader carry it, and ctTemplateFit passes
 * it on), otherwise k / FrameRate.
 *
 * The number of frames is only known once the whole sequence has been computed, so
 * RequestInformation brings the input up to date. Scrubbing never re-executes the input:
 * the time request is not passed upstream, and the block is picked from the cached result.
 */
#ifndef ctSequencePlayer_h
#define ctSequencePlayer_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <vector>

class CTFILTERS_EXPORT ctSequencePlayer : public vtkPolyDataAlgorithm
{
public:
  static ctSequencePlayer* New();
  vtkTypeMacro(ctSequencePlayer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Frames per second, for blocks without a TimeValue.
  vtkSetClampMacro(FrameRate, double, 1e-3, 1e6);
  vtkGetMacro(FrameRate, double);

  /// Time of each frame, known after UpdateInformation().
  const std::vector<double>& GetFrameTimes() const { return this->FrameTimes; }

  /// The frame shown at time t: the last one starting at or before t.
  int FrameAtTime(double t) const;

protected:
  ctSequencePlayer() = default;
  ~ctSequencePlayer() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  ctSequencePlayer(const ctSequencePlayer&) = delete;
  void operator=(const ctSequencePlayer&) = delete;

  double FrameRate = 25.0;
  std::vector<double> FrameTimes;
};

#endif
