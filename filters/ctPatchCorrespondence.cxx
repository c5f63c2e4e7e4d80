#include "ctPatchCorrespondence.h"

#include "ctArrayNames.h"
#include "ctFrameName.h"
#include "ctLandmarkPolyData.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
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

int ctPatchCorrespondence::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector)
{
  using namespace clothtrack;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* landmarkBlocks = vtkMultiBlockDataSet::GetData(inputVector[1], 0);
  try
  {
    checkOneBlockPerFrame(sequence, landmarkBlocks, "patch correspondence", "landmarks");
    const int n = static_cast<int>(sequence->GetNumberOfBlocks());
    auto frameLandmarks = [&](int k, const TriangleMesh& mesh)
    {
      auto* poly = vtkPolyData::SafeDownCast(landmarkBlocks->GetBlock(static_cast<unsigned>(k)));
      return landmarkSurfacePoints(poly, mesh.numFaces(),
                                   "landmarks of " + frameName(sequence->GetBlock(k), k));
    };

    std::vector<TriangleMesh> frames(n);
    std::vector<const TriangleMesh*> pointers(n);
    std::vector<std::vector<OrientedSurfacePoint>> landmarks(n);
    for (int k = 0; k < n; ++k)
    {
      frames[k] = frameMesh(sequence, k);
      pointers[k] = &frames[k];
      landmarks[k] = frameLandmarks(k, frames[k]);
    }
    // Template: given, or chosen by topology then pose or area uniformity.
    int chosen = this->TemplateFrame;
    if (chosen >= n)
      throw Error("patch correspondence: template frame " + std::to_string(chosen) +
                  " is beyond the last frame (" + std::to_string(n - 1) + ")");
    if (chosen < 0)
    {
      TemplateSelectionOptions selection;
      selection.minimumShellArea = this->MinimumShellArea;
      selection.persistence = this->Persistence;
      selection.criterion = static_cast<clothtrack::TemplateCriterion>(this->TemplateCriterion);
      chosen = chooseTemplateFrame(
                   pointers, selection,
                   blockFieldValues(landmarkBlocks, clothtrack::arrays::RestPoseDistance, NAN))
                   .chosen;
    }
    this->ChosenFrame = chosen;
    this->UpdateProgress(0.05);
    auto* templateData = vtkPolyData::SafeDownCast(sequence->GetBlock(chosen));
    const TriangleMesh& templateMesh = frames[chosen];
    const std::vector<OrientedSurfacePoint>& templateLandmarks = landmarks[chosen];
    if (templateLandmarks.empty())
      throw Error("patch correspondence: the template " +
                  frameName(sequence->GetBlock(chosen), chosen) + " has no valid landmark");
    for (int k = 0; k < n; ++k)
      if (k != chosen && landmarks[k].empty())
        vtkWarningMacro(<< "patch correspondence: " << frameName(sequence->GetBlock(k), k)
                        << " has no landmark; no vertex is matched");
    PatchCorrespondenceOptions options;
    options.epsilon = this->Epsilon;
    options.minRadius = this->MinimumRadius;
    options.maxRadius = this->MaximumRadius;
    options.anchors = this->NumberOfAnchors;
    options.maxSeedOffset = this->MaximumSeedOffset;
    options.minConsensus = this->MinimumSeedConsensus;
    options.consensusRadius = this->SeedConsensusRadius;
    options.consensusTolerance = this->SeedConsensusTolerance;
    options.consensusRelative = this->SeedConsensusRelativeTolerance;
    const TemplatePatches patches(templateMesh, templateLandmarks, options);
    std::vector<FrameCorrespondence> results(n);
    std::vector<int> all(n);
    for (int k = 0; k < n; ++k) all[k] = k;
    correspondFrames(
        patches, chosen, all, [&](int k) -> const TriangleMesh& { return frames[k]; },
        [&](int k) -> const std::vector<OrientedSurfacePoint>& { return landmarks[k]; },
        [&](int k, FrameCorrespondence&& c) { results[k] = std::move(c); },
        [this](double done)
        {
          this->UpdateProgress(0.05 + 0.9 * done);
          return !this->GetAbortExecute();
        });

    auto* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
    vtkTable* table = vtkTable::GetData(outputVector, 1);
    output->SetNumberOfBlocks(n);
    auto frameColumn = namedArray<vtkIntArray>("Frame");
    auto matchedColumn = namedArray<vtkDoubleArray>(clothtrack::arrays::MatchedFraction);
    auto keptColumn = namedArray<vtkIntArray>("PatchesKept");
    auto pairsColumn = namedArray<vtkIntArray>("LandmarkPairs");
    auto outvotedColumn = namedArray<vtkIntArray>("SeedsOutvoted");
    auto secondsColumn = namedArray<vtkDoubleArray>("Seconds");
    for (int k = 0; k < n; ++k)
    {
      const FrameCorrespondence& c = results[k];
      int pairs = 0, kept = 0, outvoted = 0;
      if (k != chosen)
      {
        for (const auto& p : c.patches) kept += p.kept, outvoted += p.outvoted;
        for (const auto& t : templateLandmarks)
          pairs += std::any_of(landmarks[k].begin(), landmarks[k].end(),
                               [&](const OrientedSurfacePoint& l) { return l.id == t.id; });
      }
      vtkSmartPointer<vtkPolyData> block = correspondencePolyData(templateData, c);
      vtkFieldData* fd = block->GetFieldData();
      addFieldValue(fd, clothtrack::arrays::FrameIndex, k);
      addFieldValue(fd, clothtrack::arrays::TemplateFrame, chosen);
      addFieldValue(fd, clothtrack::arrays::MatchedFraction, c.matchedFraction());
      output->SetBlock(k, block);
      output->GetMetaData(static_cast<unsigned>(k))
          ->Set(vtkCompositeDataSet::NAME(), ("correspondence_" + std::to_string(k)).c_str());
      frameColumn->InsertNextValue(k);
      matchedColumn->InsertNextValue(c.matchedFraction());
      keptColumn->InsertNextValue(kept);
      pairsColumn->InsertNextValue(pairs);
      outvotedColumn->InsertNextValue(outvoted);
      secondsColumn->InsertNextValue(c.seconds);
    }
    this->UpdateProgress(1.0);
    for (vtkAbstractArray* column :
         {static_cast<vtkAbstractArray*>(frameColumn),
          static_cast<vtkAbstractArray*>(matchedColumn), static_cast<vtkAbstractArray*>(keptColumn),
          static_cast<vtkAbstractArray*>(pairsColumn),
          static_cast<vtkAbstractArray*>(outvotedColumn),
          static_cast<vtkAbstractArray*>(secondsColumn)})
      table->AddColumn(column);
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
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "MinimumRadius: " << this->MinimumRadius << "\n";
  os << indent << "MaximumRadius: " << this->MaximumRadius << "\n";
  os << indent << "NumberOfAnchors: " << this->NumberOfAnchors << "\n";
  os << indent << "MaximumSeedOffset: " << this->MaximumSeedOffset << "\n";
  os << indent << "MinimumSeedConsensus: " << this->MinimumSeedConsensus << "\n";
  os << indent << "SeedConsensusRadius: " << this->SeedConsensusRadius << "\n";
  os << indent << "SeedConsensusTolerance: " << this->SeedConsensusTolerance << "\n";
  os << indent << "SeedConsensusRelativeTolerance: " << this->SeedConsensusRelativeTolerance
     << "\n";
  os << indent << "TemplateFrame: " << this->TemplateFrame << "\n";
  os << indent << "MinimumShellArea: " << this->MinimumShellArea << "\n";
  os << indent << "Persistence: " << this->Persistence << "\n";
}
