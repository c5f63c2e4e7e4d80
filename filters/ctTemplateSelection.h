/**
 * @class ctTemplateSelection
 * @brief Chooses the template frame of a sequence by topology, then body pose or area
 * uniformity.
 *
 * Input: the whole sequence as a vtkMultiBlockDataSet of vtkPolyData frames (e.g. port 1 of
 * ctMeshSequenceReader). Per frame: connected components, shells (components of at least
 * MinimumShellArea), genus of the largest component and its area ratio (largest / smallest
 * mixed Voronoi vertex area). Splits count only when they persist for Persistence consecutive
 * frames. Candidates have the most shells, then the smallest genus. Among them, with
 * TemplateCriterion RestPose (default) and the body fit on input port 1, the template is the
 * candidate whose fitted body is closest to the rest pose; otherwise (TemplateCriterion AreaRatio,
 * the paper's, or no body fit) the candidate with the smallest area ratio. TemplateFrame >= 0
 * overrides the choice.
 *
 * Input port 1 (optional): one block per frame with field data RestPoseDistance (and
 * ContinuesPrevious), as output port 0 or 1 of ctBodyFit.
 *
 * Output port 0: the template mesh (field data TemplateFrame, TemplateCriterion, and
 * CollectionOfPoses: 1 when at least half of the frames after the first do not continue their
 * predecessor, clothtrack::isCollectionOfPoses; DefaultTemplateCandidates: the template frames
 * worth aligning under when none is given, clothtrack::defaultTemplateCandidates). Output port 1:
 * a vtkTable with every frame's criteria (RestPoseDistance NaN where unknown), PoseOrder (the
 * order in which the rest-pose
 * criterion would choose the frames, clothtrack::templateFramesByPose; -1 for the others or
 * when it did not decide) and the choice.
 */
#ifndef ctTemplateSelection_h
#define ctTemplateSelection_h

#include "ctFiltersModule.h"

#include <clothtrack/selection/TemplateSelection.h>

#include <vtkPolyDataAlgorithm.h>

class vtkTable;

class CTFILTERS_EXPORT ctTemplateSelection : public vtkPolyDataAlgorithm
{
public:
  static ctTemplateSelection* New();
  vtkTypeMacro(ctTemplateSelection, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  virtual void SetMinimumShellArea(double value);
  virtual double GetMinimumShellArea();
  virtual void SetPersistence(int value);
  virtual int GetPersistence();
  /// Last criterion among the topological candidates: 0 area ratio (the paper's), 1 rest pose
  /// (default; needs the body fit on port 1, else the area ratio decides).
  virtual void SetTemplateCriterion(int criterion);
  virtual int GetTemplateCriterion();
  /// Former name of TemplateCriterion, kept for existing scripts.
  void SetCriterion(int criterion) { this->SetTemplateCriterion(criterion); }
  int GetCriterion() { return this->GetTemplateCriterion(); }
  /// Threads of this filter's loops (0: the process's count, every core by default).
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  /// The body fit (output port 0 or 1 of ctBodyFit) on input port 1.
  void SetBodyFitConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// A frame index to use as template; -1 (default) chooses automatically.
  vtkSetMacro(TemplateFrame, int);
  vtkGetMacro(TemplateFrame, int);

  /// The frame chosen by the last update.
  vtkGetMacro(ChosenFrame, int);
  vtkTable* GetCriteriaOutput();

protected:
  ctTemplateSelection();
  ~ctTemplateSelection() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;
  int TemplateFrame = -1;
  int NumberOfThreads = 0;
  int ChosenFrame = -1;

private:
  ctTemplateSelection(const ctTemplateSelection&) = delete;
  void operator=(const ctTemplateSelection&) = delete;
  clothtrack::TemplateSelectionOptions Options;
};

#endif
