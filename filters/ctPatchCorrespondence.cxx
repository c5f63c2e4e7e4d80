#include "ctPatchCorrespondence.h"
#include "ctFirstPieceOnly.h"
#include "ctOptionProperty.h"

#include "ctArrayNames.h"
#include "ctFrameName.h"
#include "ctLandmarkPolyData.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/pipeline/CorrespondenceStage.h>
#include <clothtrack/pipeline/TemplateStage.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <vtkCharArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>
#include <chrono>

vtkStandardNewMacro(ctPatchCorrespondence);

ctOptionClampDefinition(ctPatchCorrespondence, Epsilon, double, Patches.epsilon, 1e-4, 10.0);
ctOptionClampDefinition(ctPatchCorrespondence, MinimumRadius, double, Patches.minimumRadius, 0.0,
                        10.0);
ctOptionClampDefinition(ctPatchCorrespondence, MaximumRadius, double, Patches.maximumRadius, 1e-3,
                        10.0);
ctOptionClampDefinition(ctPatchCorrespondence, NumberOfAnchors, int, Patches.numberOfAnchors, 0,
                        64);
ctOptionClampDefinition(ctPatchCorrespondence, MaximumSeedOffset, double, Patches.maximumSeedOffset,
                        0.0, 100.0);
ctOptionClampDefinition(ctPatchCorrespondence, MinimumSeedConsensus, double,
                        Patches.minimumSeedConsensus, 0.0, 1.0);
ctOptionClampDefinition(ctPatchCorrespondence, SeedConsensusRadius, double,
                        Patches.seedConsensusRadius, 0.01, 100.0);
ctOptionClampDefinition(ctPatchCorrespondence, SeedConsensusTolerance, double,
                        Patches.seedConsensusTolerance, 0.0, 10.0);
ctOptionClampDefinition(ctPatchCorrespondence, SeedConsensusRelativeTolerance, double,
                        Patches.seedConsensusRelativeTolerance, 0.0, 10.0);
ctOptionClampDefinition(ctPatchCorrespondence, MinimumShellArea, double, Selection.minimumShellArea,
                        0.0, 100.0);
ctOptionClampDefinition(ctPatchCorrespondence, Persistence, int, Selection.persistence, 1, 10000);

ctOptionEnumDefinition(ctPatchCorrespondence, TemplateCriterion, clothtrack::TemplateCriterion,
                       Selection.templateCriterion, 0, 1);

namespace
{
using clothtrack::namedArray;

/// A copy of the template carrying the correspondence of one frame.
vtkSmartPointer<vtkPolyData> correspondencePolyData(vtkPolyData* templateData,
                                                    const clothtrack::FrameCorrespondence& c)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->CopyStructure(templateData);
  const vtkIdType n = static_cast<vtkIdType>(c.vertices.size());
  auto matched = namedArray<vtkCharArray>(clothtrack::arrays::Matched, n);
  auto position = namedArray<vtkDoubleArray>(clothtrack::arrays::TargetPosition, n, 3);
  auto face = namedArray<vtkIntArray>("TargetFace", n);
  auto bary = namedArray<vtkDoubleArray>("TargetBarycentric", n, 3);
  auto count = namedArray<vtkIntArray>("PatchCount", n);
  auto spread = namedArray<vtkDoubleArray>("Spread", n);
  auto patch = namedArray<vtkIntArray>("PatchId", n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    const clothtrack::VertexMatch& m = c.vertices[v];
    matched->SetValue(v, m.matched() ? 1 : 0);
    position->SetTuple3(v, m.position[0], m.position[1], m.position[2]);
    face->SetValue(v, m.face);
    bary->SetTuple3(v, m.bary[0], m.bary[1], m.bary[2]);
    count->SetValue(v, m.patches);
    spread->SetValue(v, m.spread);
    patch->SetValue(v, m.patchId);
  }
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(matched);
  pd->AddArray(position);
  pd->AddArray(face);
  pd->AddArray(bary);
  pd->AddArray(count);
  pd->AddArray(spread);
  pd->AddArray(patch);
  return out;
}
} // namespace

ctPatchCorrespondence::ctPatchCorrespondence()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkTable* ctPatchCorrespondence::GetSummaryOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(1));
}

int ctPatchCorrespondence::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

int ctPatchCorrespondence::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkTable" : "vtkMultiBlockDataSet");
  return 1;
}

/// The frames and their landmarks, read and checked once.
struct ctPatchCorrespondence::Inputs
{
  std::vector<clothtrack::TriangleMesh> frames;
  std::vector<const clothtrack::TriangleMesh*> pointers;
  std::vector<std::vector<clothtrack::OrientedSurfacePoint>> landmarks;
};

namespace
{
/// Output port 1: one row per frame.
void addSummaryRows(vtkTable* table, const std::vector<clothtrack::FrameCorrespondence>& results,
                    const std::vector<std::vector<clothtrack::OrientedSurfacePoint>>& landmarks,
                    int templateFrame)
{
  auto frameColumn = namedArray<vtkIntArray>("Frame");
  auto matchedColumn = namedArray<vtkDoubleArray>(clothtrack::arrays::MatchedFraction);
  auto keptColumn = namedArray<vtkIntArray>("PatchesKept");
  auto pairsColumn = namedArray<vtkIntArray>("LandmarkPairs");
  auto outvotedColumn = namedArray<vtkIntArray>("SeedsOutvoted");
  auto secondsColumn = namedArray<vtkDoubleArray>("Seconds");
  const auto& templateLandmarks = landmarks[templateFrame];
  for (int k = 0; k < static_cast<int>(results.size()); ++k)
  {
    const clothtrack::FrameCorrespondence& c = results[k];
    int pairs = 0, kept = 0, outvoted = 0;
    if (k != templateFrame)
    {
      for (const auto& p : c.patches) kept += p.kept, outvoted += p.outvoted;
      for (const auto& t : templateLandmarks)
        pairs +=
            std::any_of(landmarks[k].begin(), landmarks[k].end(),
                        [&](const clothtrack::OrientedSurfacePoint& l) { return l.id == t.id; });
    }
    frameColumn->InsertNextValue(k);
    matchedColumn->InsertNextValue(c.matchedFraction());
    keptColumn->InsertNextValue(kept);
    pairsColumn->InsertNextValue(pairs);
    outvotedColumn->InsertNextValue(outvoted);
    secondsColumn->InsertNextValue(c.seconds);
  }
  for (vtkAbstractArray* column :
       {static_cast<vtkAbstractArray*>(frameColumn), static_cast<vtkAbstractArray*>(matchedColumn),
        static_cast<vtkAbstractArray*>(keptColumn), static_cast<vtkAbstractArray*>(pairsColumn),
        static_cast<vtkAbstractArray*>(outvotedColumn),
        static_cast<vtkAbstractArray*>(secondsColumn)})
    table->AddColumn(column);
}

/// Output port 0: one copy of the template per frame with its correspondence.
void addCorrespondenceBlocks(vtkMultiBlockDataSet* output, vtkPolyData* templateData,
                             const std::vector<clothtrack::FrameCorrespondence>& results,
                             int templateFrame)
{
  const int n = static_cast<int>(results.size());
  output->SetNumberOfBlocks(n);
  for (int k = 0; k < n; ++k)
  {
    const clothtrack::FrameCorrespondence& c = results[k];
    vtkSmartPointer<vtkPolyData> block = correspondencePolyData(templateData, c);
    vtkFieldData* fd = block->GetFieldData();
    clothtrack::addFieldValue(fd, clothtrack::arrays::FrameIndex, k);
    clothtrack::addFieldValue(fd, clothtrack::arrays::TemplateFrame, templateFrame);
    clothtrack::addFieldValue(fd, clothtrack::arrays::MatchedFraction, c.matchedFraction());
    output->SetBlock(k, block);
    output->GetMetaData(static_cast<unsigned>(k))
        ->Set(vtkCompositeDataSet::NAME(), ("correspondence_" + std::to_string(k)).c_str());
  }
}
} // namespace

ctPatchCorrespondence::Inputs
ctPatchCorrespondence::ReadInputs(vtkMultiBlockDataSet* sequence,
                                  vtkMultiBlockDataSet* landmarkBlocks)
{
  using namespace clothtrack;
  checkOneBlockPerFrame(sequence, landmarkBlocks, "patch correspondence", "landmarks");
  const int n = static_cast<int>(sequence->GetNumberOfBlocks());
  Inputs in;
  in.frames.resize(n);
  in.pointers.resize(n);
  in.landmarks.resize(n);
  for (int k = 0; k < n; ++k)
  {
    in.frames[k] = frameMesh(sequence, k);
    in.pointers[k] = &in.frames[k];
    auto* poly = vtkPolyData::SafeDownCast(landmarkBlocks->GetBlock(static_cast<unsigned>(k)));
    in.landmarks[k] = landmarkSurfacePoints(poly, in.frames[k].numFaces(),
                                            "landmarks of " + frameName(sequence->GetBlock(k), k));
  }
  return in;
}

int ctPatchCorrespondence::ChooseTemplate(const Inputs& in, vtkMultiBlockDataSet* landmarkBlocks)
{
  using namespace clothtrack;
  const int n = static_cast<int>(in.frames.size());
  if (this->TemplateFrame >= n)
    throw Error("patch correspondence: template frame " + std::to_string(this->TemplateFrame) +
                " is beyond the last frame (" + std::to_string(n - 1) + ")");
  if (this->TemplateFrame >= 0) return this->TemplateFrame;
  // Chosen by topology, then the body's pose or the area uniformity.
  return chooseTemplateFrame(
             in.pointers, this->Selection,
             blockFieldValues(landmarkBlocks, clothtrack::arrays::RestPoseDistance, NAN))
      .chosen;
}

int ctPatchCorrespondence::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* landmarkBlocks = vtkMultiBlockDataSet::GetData(inputVector[1], 0);
  ThreadBudget threads(this->NumberOfThreads);
  try
  {
    const Inputs in = this->ReadInputs(sequence, landmarkBlocks);
    const int n = static_cast<int>(in.frames.size());
    const int chosen = this->ChosenFrame = this->ChooseTemplate(in, landmarkBlocks);
    this->UpdateProgress(0.05);
    if (in.landmarks[chosen].empty())
      throw Error("patch correspondence: the template " +
                  frameName(sequence->GetBlock(chosen), chosen) + " has no valid landmark");
    for (int k = 0; k < n; ++k)
      if (k != chosen && in.landmarks[k].empty())
        vtkWarningMacro(<< "patch correspondence: " << frameName(sequence->GetBlock(k), k)
                        << " has no landmark; no vertex is matched");
    const TemplatePatches patches(in.frames[chosen], in.landmarks[chosen], this->Patches);
    std::vector<FrameCorrespondence> results(n);
    std::vector<int> all(n);
    for (int k = 0; k < n; ++k) all[k] = k;
    correspondFrames(
        patches, chosen, all, [&](int k) { return borrowedFrame(in.frames[k]); },
        [&](int k) -> const std::vector<OrientedSurfacePoint>& { return in.landmarks[k]; },
        [&](int k, FrameCorrespondence&& c) { results[k] = std::move(c); },
        [this](double done)
        {
          this->UpdateProgress(0.05 + 0.9 * done);
          return !this->GetAbortExecute();
        });
    addCorrespondenceBlocks(vtkMultiBlockDataSet::GetData(outputVector, 0),
                            vtkPolyData::SafeDownCast(sequence->GetBlock(chosen)), results, chosen);
    addSummaryRows(vtkTable::GetData(outputVector, 1), results, in.landmarks, chosen);
    this->UpdateProgress(1.0);
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctPatchCorrespondence::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Epsilon: " << this->Patches.epsilon << "\n";
  os << indent << "MinimumRadius: " << this->Patches.minimumRadius << "\n";
  os << indent << "MaximumRadius: " << this->Patches.maximumRadius << "\n";
  os << indent << "NumberOfAnchors: " << this->Patches.numberOfAnchors << "\n";
  os << indent << "MaximumSeedOffset: " << this->Patches.maximumSeedOffset << "\n";
  os << indent << "MinimumSeedConsensus: " << this->Patches.minimumSeedConsensus << "\n";
  os << indent << "SeedConsensusRadius: " << this->Patches.seedConsensusRadius << "\n";
  os << indent << "SeedConsensusTolerance: " << this->Patches.seedConsensusTolerance << "\n";
  os << indent << "SeedConsensusRelativeTolerance: " << this->Patches.seedConsensusRelativeTolerance
     << "\n";
  os << indent << "TemplateFrame: " << this->TemplateFrame << "\n";
  os << indent << "MinimumShellArea: " << this->Selection.minimumShellArea << "\n";
  os << indent << "Persistence: " << this->Selection.persistence << "\n";
}
