/**
 * @class ctModelChoice
 * @brief Which of several alignments of one sequence, each made under another body model, to keep.
 *
 * The rule of `clothtrack align --model A --model B` (clothtrack/eval/ModelChoice.h): the first
 * alignment is kept unless others are both less stretched and closer to the frames than it, each
 * by more than Margin (a share of the first's figure); of those, the one whose smaller gain of the
 * two is the largest. No ground truth is used.
 *
 * Input port 0 (one connection per alignment, in the order the models were named): the per-frame
 * table of ctTemplateFit (its output port 1), with the columns Stretch and MeanSurfaceDistance.
 *
 * Output: a vtkTable with one row per alignment: Alignment (its connection index), MeanStretch,
 * MeanSurfaceDistance (metres, means over the frames that have one) and Kept (1 for the kept
 * alignment, else 0); and the field arrays KeptAlignment (the kept connection index),
 * Criterion (the rule in words) and TemplateChoiceCriterion (the same rule in words for
 * alignments under several template frames, the first the one chosen by pose).
 */
#ifndef ctModelChoice_h
#define ctModelChoice_h

#include "ctFiltersModule.h"

#include <vtkTableAlgorithm.h>

class CTFILTERS_EXPORT ctModelChoice : public vtkTableAlgorithm
{
public:
  static ctModelChoice* New();
  vtkTypeMacro(ctModelChoice, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Share by which another alignment's figures must both be lower than the first's to replace it.
  vtkSetClampMacro(Margin, double, 0.0, 1.0);
  vtkGetMacro(Margin, double);

  /// Index of the kept alignment (its connection on input port 0); -1 before an update.
  vtkGetMacro(KeptAlignment, int);

protected:
  ctModelChoice();
  ~ctModelChoice() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  double Margin;
  int KeptAlignment = -1;

private:
  ctModelChoice(const ctModelChoice&) = delete;
  void operator=(const ctModelChoice&) = delete;
};

#endif
