/**
 * @class ctBodyModelSource
 * @brief The body model M(beta, theta) posed: the mesh and its oriented anatomical landmarks.
 *
 * Uses the built-in statistical body model (or a model file written by ctBodyModelWriter /
 * `clothtrack body-model`, see ModelFileName). ShapeCoefficients are beta in standard
 * deviations (missing ones are 0). JointRotation j is an axis-angle vector (radians) relative to
 * the rest A-pose, in world axes at rest; Translation moves the whole body.
 *
 * Output port 0: the posed mesh, with point data SkinWeights (one component per joint) and
 * BodyPart (the most influential joint) and field data JointNames and JointPositions (posed).
 * Output port 1: the landmarks as points, with point data LandmarkId, Direction (unit tangent),
 * Normal (outward unit normal) and VertexId, and the string array LandmarkName.
 */
#ifndef ctBodyModelSource_h
#define ctBodyModelSource_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

class CTFILTERS_EXPORT ctBodyModelSource : public vtkPolyDataAlgorithm
{
public:
  static ctBodyModelSource* New();
  vtkTypeMacro(ctBodyModelSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// A body model file (.vtp); empty for the built-in model.
  vtkSetStdStringFromCharMacro(ModelFileName);
  vtkGetCharFromStdStringMacro(ModelFileName);

  void SetShapeCoefficient(int index, double value);
  double GetShapeCoefficient(int index) const;
  void ClearShapeCoefficients();

  /// Axis-angle rotation (radians) of joint `joint` (0 = pelvis ... 21 = right toe).
  void SetJointRotation(int joint, double x, double y, double z);
  void ClearJointRotations();

  vtkSetVector3Macro(Translation, double);
  vtkGetVector3Macro(Translation, double);

  /// Number of joints and shape components of the model in use (after Update()).
  int GetNumberOfJoints() const;
  vtkGetMacro(NumberOfShapeComponents, int);

  vtkPolyData* GetLandmarksOutput();

protected:
  ctBodyModelSource();
  ~ctBodyModelSource() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  std::string ModelFileName;
  std::vector<double> ShapeCoefficients;
  std::vector<std::array<double, 3>> JointRotations;
  double Translation[3] = {0, 0, 0};
  int NumberOfShapeComponents = 0;

private:
  ctBodyModelSource(const ctBodyModelSource&) = delete;
  void operator=(const ctBodyModelSource&) = delete;
};

#endif
