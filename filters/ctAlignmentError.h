/**
 * @class ctAlignmentError
 * @brief Error of an aligned sequence against a consistent-connectivity ground truth.
 *
 * Input port 0: the aligned template of every frame, output port 0 of ctTemplateFit (field
 * data TemplateFrame). Input port 1: the ground truth, a vtkMultiBlockDataSet with one
 * vtkPolyData per frame, all with the same connectivity.
 *
 * Each template vertex is tied, at the template frame, to its closest ground-truth surface point
 * (triangle + barycentric: the vertex itself when the template frame is a ground-truth frame);
 * its error in frame k is the distance between the aligned vertex and that point in frame k.
 * Vertices further than MaximumTruthDistance from the ground truth have none (NaN). See
 * clothtrack/AlignmentError.h.
 *
 * Output port 0: the aligned sequence with point data Error (metres).
 * Output port 1: vtkTable, one row per frame: Frame, Mean, Median, P90, Max, Within5cm,
 * Within10cm (fractions), Vertices (with ground truth); its field data holds the figures of the
 * whole sequence, every frame but the template frame pooled: SequenceMean, SequenceMedian,
 * SequenceP90, SequenceMax, SequenceWithin5cm, SequenceWithin10cm, WorstFrame, DriftPerFrame.
 * Output port 2: vtkTable, the cumulative error curve over every frame but the template frame:
 * Threshold (metres), Fraction.
 */
#ifndef ctAlignmentError_h
#define ctAlignmentError_h

#include "ctFiltersModule.h"

#include <clothtrack/eval/AlignmentError.h>

#include <vtkMultiBlockDataSetAlgorithm.h>

class vtkTable;

class CTFILTERS_EXPORT ctAlignmentError : public vtkMultiBlockDataSetAlgorithm
{
public:
  static ctAlignmentError* New();
  vtkTypeMacro(ctAlignmentError, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Template vertices further than this from the ground truth have no error (metres).
  virtual void SetMaximumTruthDistance(double value);
  virtual double GetMaximumTruthDistance();

  /// The ground truth (input port 1).
  void SetGroundTruthConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  vtkTable* GetFrameErrorOutput();
  vtkTable* GetCumulativeOutput();

protected:
  ctAlignmentError();
  ~ctAlignmentError() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  ctAlignmentError(const ctAlignmentError&) = delete;
  void operator=(const ctAlignmentError&) = delete;
  clothtrack::TruthAnchorOptions Options;
};

#endif
