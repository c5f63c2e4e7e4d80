#ifndef ctBodyModelIO_h
#define ctBodyModelIO_h
// The body model file format: one VTP file (docs/body-model-format.md). C++ only.
#include "ctReadersModule.h"

#include <clothtrack/body/BodyModel.h>

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace clothtrack
{
/// The model as a vtkPolyData in the file layout (mean mesh, skinning weights, shape basis,
/// skeleton and landmarks).
CTREADERS_EXPORT vtkSmartPointer<vtkPolyData> bodyModelToPolyData(const BodyModel& model);
/// Inverse of bodyModelToPolyData; throws Error naming `name` when an array is missing or
/// inconsistent.
CTREADERS_EXPORT BodyModel bodyModelFromPolyData(vtkPolyData* data, const std::string& name);

CTREADERS_EXPORT void writeBodyModel(const std::string& path, const BodyModel& model);
CTREADERS_EXPORT BodyModel readBodyModel(const std::string& path);

/// Adds SkinWeights, BodyPart (point data) and JointNames, JointPositions (field data) to a
/// mesh with the model's vertices (e.g. a posed body).
CTREADERS_EXPORT void addBodyModelArrays(const BodyModel& model, const Points& joints,
                                         vtkPolyData* mesh);
} // namespace clothtrack

#endif
