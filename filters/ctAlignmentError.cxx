#include "ctAlignmentError.h"

#include "ctFrameName.h"
#include "ctNamedArrays.h"

#include <clothtrack/AlignmentError.h>
#include <clothtrack/Error.h>

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <vector>

vtkStandardNewMacro(ctAlignmentError);

ctAlignmentError::ctAlignmentError()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
}

void ctAlignmentError::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumTruthDistance: " << this->MaximumTruthDistance << "\n";
}

vtkTable* ctAlignmentError::GetFrameErrorOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(1));
}

vtkTable* ctAlignmentError::GetCumulativeOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(2));
}

int ctAlignmentError::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

int ctAlignmentError::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkMultiBlockDataSet" : "vtkTable");
  return 1;
}

int ctAlignmentError::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                  vtkInformationVector* outputVector)
{
  using namespace clothtrack;
  auto* aligned = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* truthSequence = vtkMultiBlockDataSet::GetData(inputVector[1], 0);
  try
  {
    checkOneBlockPerFrame(aligned, truthSequence, "alignment error", "ground-truth frame");
    const int n = static_cast<int>(aligned->GetNumberOfBlocks());
    auto* first = vtkPolyData::SafeDownCast(aligned->GetBlock(0));
    vtkDataArray* templateField =
        first ? first->GetFieldData()->GetArray("TemplateFrame") : nullptr;
    if (!templateField)
      throw Error("alignment error: the aligned blocks carry no TemplateFrame (use ctTemplateFit)");
    const int j = static_cast<int>(templateField->GetComponent(0, 0));
    if (j < 0 || j >= n)
      throw Error("alignment error: the template frame " + std::to_string(j) +
                  " is not in the sequence");
    const TriangleMesh templateMesh = frameMesh(aligned, j);
    const TruthAnchors anchors =
        anchorToTruth(templateMesh.V, frameMesh(truthSequence, j), this->MaximumTruthDistance);
    if (anchors.count() == 0)
      throw Error("alignment error: no template vertex lies within " +
                  std::to_string(this->MaximumTruthDistance) +
                  " m of the ground truth at the template frame (units or frames mismatched?)");

    auto* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
    vtkTable* frameTable = vtkTable::GetData(outputVector, 1);
    vtkTable* curveTable = vtkTable::GetData(outputVector, 2);
    output->SetNumberOfBlocks(n);
    auto frameColumn = namedArray<vtkIntArray>("Frame", n);
    auto verticesColumn = namedArray<vtkIntArray>("Vertices", n);
    const char* statisticNames[] = {"Mean", "Median", "P90", "Max", "Within5cm", "Within10cm"};
    std::vector<vtkSmartPointer<vtkDoubleArray>> statistics;
    for (const char* name : statisticNames)
      statistics.push_back(namedArray<vtkDoubleArray>(name, n));
    std::vector<double> pooled;
    for (int k = 0; k < n; ++k)
    {
      const TriangleMesh frame = frameMesh(aligned, k);
      if (frame.numVertices() != templateMesh.numVertices())
        throw Error("alignment error: " + frameName(aligned->GetBlock(k), k) + " has " +
                    std::to_string(frame.numVertices()) + " vertices, the template " +
                    std::to_string(templateMesh.numVertices()));
      const Eigen::VectorXd errors = vertexErrors(frame.V, frameMesh(truthSequence, k), anchors);
      auto block = vtkSmartPointer<vtkPolyData>::New();
      block->ShallowCopy(aligned->GetBlock(k));
      auto errorArray = namedArray<vtkDoubleArray>("Error", errors.size());
      for (Eigen::Index i = 0; i < errors.size(); ++i) errorArray->SetValue(i, errors[i]);
      block->GetPointData()->AddArray(errorArray);
      output->SetBlock(k, block);
      output->GetMetaData(static_cast<unsigned>(k))
          ->Set(vtkCompositeDataSet::NAME(), ("aligned_" + std::to_string(k)).c_str());

      const ErrorStatistics s = errorStatistics(errors);
      frameColumn->SetValue(k, k);
      verticesColumn->SetValue(k, s.count);
      const double values[] = {s.mean, s.median, s.p90, s.max, s.within5cm, s.within10cm};
      for (size_t c = 0; c < statistics.size(); ++c) statistics[c]->SetValue(k, values[c]);
      if (k != j) pooled.insert(pooled.end(), errors.data(), errors.data() + errors.size());
      this->UpdateProgress(static_cast<double>(k + 1) / n);
    }
    frameTable->AddColumn(frameColumn);
    for (auto& column : statistics) frameTable->AddColumn(column);
    frameTable->AddColumn(verticesColumn);

    std::vector<double> thresholds;
    for (int t = 0; t <= 40; ++t) thresholds.push_back(0.005 * t);
    const std::vector<double> fractions = cumulativeCurve(pooled, thresholds);
    auto thresholdColumn = namedArray<vtkDoubleArray>("Threshold", thresholds.size());
    auto fractionColumn = namedArray<vtkDoubleArray>("Fraction", thresholds.size());
    for (size_t t = 0; t < thresholds.size(); ++t)
    {
      thresholdColumn->SetValue(t, thresholds[t]);
      fractionColumn->SetValue(t, fractions[t]);
    }
    curveTable->AddColumn(thresholdColumn);
    curveTable->AddColumn(fractionColumn);
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}
