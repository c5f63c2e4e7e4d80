#include "ctAlignmentError.h"
#include "ctFirstPieceOnly.h"
#include "ctOptionProperty.h"

#include "ctArrayNames.h"
#include "ctFrameName.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/eval/AlignmentError.h>

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

ctOptionClampDefinition(ctAlignmentError, MaximumTruthDistance, double,
                        Options.maximumTruthDistance, 1e-6, 100.0);

ctAlignmentError::ctAlignmentError()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
}

void ctAlignmentError::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumTruthDistance: " << this->Options.maximumTruthDistance << "\n";
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

namespace
{
using clothtrack::namedArray;

/// Output port 1: per-frame statistics; field data: the whole sequence's.
void addFrameErrorRows(vtkTable* frameTable, const clothtrack::SequenceErrors& summary)
{
  using clothtrack::addFieldValue;
  const int n = static_cast<int>(summary.perFrame.size());
  auto frameColumn = namedArray<vtkIntArray>("Frame", n);
  auto verticesColumn = namedArray<vtkIntArray>("Vertices", n);
  const char* statisticNames[] = {"Mean", "Median", "P90", "Max", "Within5cm", "Within10cm"};
  std::vector<vtkSmartPointer<vtkDoubleArray>> statistics;
  for (const char* name : statisticNames) statistics.push_back(namedArray<vtkDoubleArray>(name, n));
  for (int k = 0; k < n; ++k)
  {
    const clothtrack::ErrorStatistics& s = summary.perFrame[k];
    frameColumn->SetValue(k, k);
    verticesColumn->SetValue(k, s.count);
    const double values[] = {s.mean, s.median, s.p90, s.max, s.within5cm, s.within10cm};
    for (size_t c = 0; c < statistics.size(); ++c) statistics[c]->SetValue(k, values[c]);
  }
  frameTable->AddColumn(frameColumn);
  for (auto& column : statistics) frameTable->AddColumn(column);
  frameTable->AddColumn(verticesColumn);
  // The whole sequence (every frame but the template frame), as the app's metrics.json has it.
  const clothtrack::ErrorStatistics& all = summary.pooled;
  vtkFieldData* pooled = frameTable->GetFieldData();
  const std::pair<const char*, double> sequenceValues[] = {
      {"SequenceMean", all.mean},
      {"SequenceMedian", all.median},
      {"SequenceP90", all.p90},
      {"SequenceMax", all.max},
      {"SequenceWithin5cm", all.within5cm},
      {"SequenceWithin10cm", all.within10cm},
      {"DriftPerFrame", summary.driftPerFrame}};
  for (const auto& [name, value] : sequenceValues) addFieldValue(pooled, name, value);
  addFieldValue(pooled, "WorstFrame", summary.worstFrame);
}

/// Output port 2: the cumulative error curve.
void addCumulativeRows(vtkTable* curveTable, const clothtrack::SequenceErrors& summary)
{
  const size_t rows = summary.thresholds.size();
  auto thresholdColumn = namedArray<vtkDoubleArray>("Threshold", rows);
  auto fractionColumn = namedArray<vtkDoubleArray>("Fraction", rows);
  for (size_t t = 0; t < rows; ++t)
  {
    thresholdColumn->SetValue(t, summary.thresholds[t]);
    fractionColumn->SetValue(t, summary.fractions[t]);
  }
  curveTable->AddColumn(thresholdColumn);
  curveTable->AddColumn(fractionColumn);
}
} // namespace

int ctAlignmentError::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                  vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  auto* aligned = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* truthSequence = vtkMultiBlockDataSet::GetData(inputVector[1], 0);
  try
  {
    checkOneBlockPerFrame(aligned, truthSequence, "alignment error", "ground-truth frame");
    const int n = static_cast<int>(aligned->GetNumberOfBlocks());
    auto* first = vtkPolyData::SafeDownCast(aligned->GetBlock(0));
    vtkDataArray* templateField =
        first ? first->GetFieldData()->GetArray(clothtrack::arrays::TemplateFrame) : nullptr;
    if (!templateField)
      throw Error("alignment error: the aligned blocks carry no TemplateFrame (use ctTemplateFit)");
    const int j = static_cast<int>(templateField->GetComponent(0, 0));
    if (j < 0 || j >= n)
      throw Error("alignment error: the template frame " + std::to_string(j) +
                  " is not in the sequence");
    const TriangleMesh templateMesh = frameMesh(aligned, j);
    const TruthAnchors anchors = anchorToTruth(templateMesh.V, frameMesh(truthSequence, j),
                                               this->Options.maximumTruthDistance);
    if (anchors.count() == 0)
      throw Error("alignment error: no template vertex lies within " +
                  std::to_string(this->Options.maximumTruthDistance) +
                  " m of the ground truth at the template frame (units or frames mismatched?)");

    auto* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
    vtkTable* frameTable = vtkTable::GetData(outputVector, 1);
    vtkTable* curveTable = vtkTable::GetData(outputVector, 2);
    output->SetNumberOfBlocks(n);
    std::vector<Eigen::VectorXd> errors(n);
    for (int k = 0; k < n; ++k)
    {
      const TriangleMesh frame = frameMesh(aligned, k);
      if (frame.numVertices() != templateMesh.numVertices())
        throw Error("alignment error: " + frameName(aligned->GetBlock(k), k) + " has " +
                    std::to_string(frame.numVertices()) + " vertices, the template " +
                    std::to_string(templateMesh.numVertices()));
      errors[k] = vertexErrors(frame.V, frameMesh(truthSequence, k), anchors);
      auto block = vtkSmartPointer<vtkPolyData>::New();
      block->ShallowCopy(aligned->GetBlock(k));
      auto errorArray = namedArray<vtkDoubleArray>("Error", errors[k].size());
      for (Eigen::Index i = 0; i < errors[k].size(); ++i) errorArray->SetValue(i, errors[k][i]);
      block->GetPointData()->AddArray(errorArray);
      output->SetBlock(k, block);
      output->GetMetaData(static_cast<unsigned>(k))
          ->Set(vtkCompositeDataSet::NAME(), ("aligned_" + std::to_string(k)).c_str());
      this->UpdateProgress(static_cast<double>(k + 1) / n);
    }
    const SequenceErrors summary = sequenceErrors(errors, j);
    addFrameErrorRows(frameTable, summary);
    addCumulativeRows(curveTable, summary);
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}
