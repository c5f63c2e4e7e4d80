#include "ctTemplateFit.h"
#include "ctFirstPieceOnly.h"
#include "ctOptionProperty.h"

#include "ctArrayNames.h"
#include "ctFrameName.h"
#include "ctLandmarkPolyData.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/fit/MotionPrediction.h>
#include <clothtrack/fit/TemplateFit.h>
#include <clothtrack/pipeline/BodyStartPrediction.h>
#include <clothtrack/pipeline/FitJudge.h>
#include <clothtrack/pipeline/LandmarkConsensus.h>

#include <vtkCharArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <cmath>

vtkStandardNewMacro(ctTemplateFit);

ctOptionClampDefinition(ctTemplateFit, RoundsPerStage, int, Options.roundsPerStage, 1, 100);
ctOptionClampDefinition(ctTemplateFit, SolverTolerance, double, Options.solverTolerance, 1e-12,
                        0.5);
ctOptionClampDefinition(ctTemplateFit, IntermediateTolerance, double, Options.intermediateTolerance,
                        1e-12, 0.5);
ctOptionClampDefinition(ctTemplateFit, RefactorSteps, double, Options.refactorSteps, 0.0, 1000.0);
ctOptionClampDefinition(ctTemplateFit, NearestReuse, double, Options.nearestReuse, 0.0, 0.01);
ctOptionClampDefinition(ctTemplateFit, NearestEvery, int, Options.nearestEvery, 1, 10000);
ctOptionClampDefinition(ctTemplateFit, MaximumNearestDistance, double,
                        Options.maximumNearestDistance, 1e-6, 100.0);
ctOptionClampDefinition(ctTemplateFit, MaximumNormalAngle, double, Options.maximumNormalAngle, 1.0,
                        180.0);
ctOptionClampDefinition(ctTemplateFit, CoverageWeight, double, Options.coverageWeight, 0.0, 100.0);
ctOptionDefinition(ctTemplateFit, UseCorrespondence, bool, Options.useCorrespondence);
ctOptionDefinition(ctTemplateFit, UseNearest, bool, Options.useNearest);
ctOptionClampDefinition(ctTemplateFit, PredictRadius, double, Prediction.predictRadius, 0.0, 100.0);
ctOptionClampDefinition(ctTemplateFit, LandmarkConsensus, double, Prediction.landmarkConsensus, 0.0,
                        10.0);

namespace
{
using clothtrack::namedArray;

/// The correspondence of one frame from a ctPatchCorrespondence block.
clothtrack::VertexTargets targetsOf(vtkPolyData* block, int n, const std::string& name)
{
  using clothtrack::Error;
  if (!block || block->GetNumberOfPoints() != n)
    throw Error("the correspondence of " + name + " does not have one point per template vertex");
  vtkDataArray* matched = block->GetPointData()->GetArray(clothtrack::arrays::Matched);
  vtkDataArray* position = block->GetPointData()->GetArray(clothtrack::arrays::TargetPosition);
  if (!matched || !position || position->GetNumberOfComponents() != 3)
    throw Error("the correspondence of " + name +
                " lacks the Matched or TargetPosition array (use ctPatchCorrespondence)");
  clothtrack::VertexTargets t;
  t.position.resize(n, 3);
  t.matched.assign(n, 0);
  for (int v = 0; v < n; ++v)
  {
    if (matched->GetComponent(v, 0) == 0) continue;
    double p[3];
    position->GetTuple(v, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Error("the correspondence of " + name + " has a non-finite target at vertex " +
                  std::to_string(v));
    t.matched[v] = 1;
    t.position.row(v) << p[0], p[1], p[2];
  }
  return t;
}

/// One ctBodyFit output block: its skeleton (field data Pose and JointPositions) and whether
/// its fit is ok (FitStatus).
clothtrack::PosedSkeleton skeletonOf(vtkPolyData* block, const std::string& name, bool& ok)
{
  using namespace clothtrack;
  vtkFieldData* fd = block ? block->GetFieldData() : nullptr;
  vtkDataArray* pose = fd ? fd->GetArray("Pose") : nullptr;
  vtkDataArray* joints = fd ? fd->GetArray("JointPositions") : nullptr;
  vtkDataArray* status = fd ? fd->GetArray("FitStatus") : nullptr;
  if (!pose || pose->GetNumberOfValues() != 3 * NumJoints + 3 || !joints ||
      joints->GetNumberOfTuples() != NumJoints || joints->GetNumberOfComponents() != 3 || !status)
    throw Error("the body of " + name +
                " lacks the Pose, JointPositions or FitStatus field data (use ctBodyFit)");
  PosedSkeleton out;
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c)
    {
      out.pose.rotations(j, c) = pose->GetComponent(3 * j + c, 0);
      out.joints(j, c) = joints->GetComponent(j, c);
    }
  for (int c = 0; c < 3; ++c) out.pose.translation[c] = pose->GetComponent(3 * NumJoints + c, 0);
  ok = status->GetComponent(0, 0) == static_cast<int>(BodyFitStatus::Ok);
  return out;
}

/// What the doubts need of each body (clothtrack::doubtFromBodies), from its
/// FitStatus, ContinuesPrevious and RivalScoreRatio field data; a body without the second
/// continues its predecessor, one without the third has no rival measured.
clothtrack::BodyFitResult bodyFitFlags(vtkMultiBlockDataSet* bodies)
{
  using namespace clothtrack;
  BodyFitResult fits;
  for (unsigned k = 0; k < bodies->GetNumberOfBlocks(); ++k)
  {
    auto* block = vtkPolyData::SafeDownCast(bodies->GetBlock(k));
    vtkFieldData* fd = block ? block->GetFieldData() : nullptr;
    vtkDataArray* status = fd ? fd->GetArray("FitStatus") : nullptr;
    vtkDataArray* continues = fd ? fd->GetArray("ContinuesPrevious") : nullptr;
    vtkDataArray* rival = fd ? fd->GetArray("RivalScoreRatio") : nullptr;
    BodyFrameFit& f = fits.frames.emplace_back();
    if (status) f.status = static_cast<BodyFitStatus>(static_cast<int>(status->GetTuple1(0)));
    f.continuesPrevious = !continues || continues->GetTuple1(0) != 0;
    if (rival) f.rivalScoreRatio = rival->GetTuple1(0);
  }
  return fits;
}

/// The template posed by each frame's fitted body (ctBodyFit output 0), nothing where the body
/// is not trusted (bodyPosedTemplate).
clothtrack::TemplatePosedByBody posedByBody(vtkMultiBlockDataSet* sequence,
                                            vtkMultiBlockDataSet* bodies,
                                            const clothtrack::TriangleMesh& templateMesh, int j)
{
  using namespace clothtrack;
  const int n = static_cast<int>(sequence->GetNumberOfBlocks());
  FittedBodies fitted;
  for (int k = 0; k < n; ++k)
  {
    bool ok = false;
    fitted.skeletons.push_back(skeletonOf(vtkPolyData::SafeDownCast(bodies->GetBlock(k)),
                                          frameName(sequence->GetBlock(k), k), ok));
    fitted.trusted.push_back(ok);
  }
  auto* body = vtkPolyData::SafeDownCast(bodies->GetBlock(j));
  vtkDataArray* weights = body->GetPointData()->GetArray("SkinWeights");
  const vtkIdType nb = body->GetNumberOfPoints();
  if (!weights || weights->GetNumberOfTuples() != nb ||
      weights->GetNumberOfComponents() != NumJoints)
    throw Error("the body of " + frameName(sequence->GetBlock(j), j) +
                " lacks the SkinWeights point data (use ctBodyFit)");
  fitted.templateBody.resize(nb, 3);
  fitted.weights.resize(nb, NumJoints);
  for (vtkIdType i = 0; i < nb; ++i)
  {
    double p[3];
    body->GetPoint(i, p);
    fitted.templateBody.row(i) << p[0], p[1], p[2];
    for (int c = 0; c < NumJoints; ++c) fitted.weights(i, c) = weights->GetComponent(i, c);
  }
  return bodyPosedTemplate(templateMesh, j, std::move(fitted));
}

vtkSmartPointer<vtkPolyData> alignedPolyData(vtkPolyData* templateData,
                                             const clothtrack::TriangleMesh& templateMesh,
                                             const clothtrack::FrameFit& fit)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->CopyStructure(templateData);
  const vtkIdType n = templateMesh.numVertices();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto displacement = namedArray<vtkDoubleArray>("Displacement", n, 3);
  auto used = namedArray<vtkCharArray>("CorrespondenceUsed", n);
  auto distance = namedArray<vtkDoubleArray>("SurfaceDistance", n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    const clothtrack::Vec3 p = fit.positions.row(v).transpose();
    const clothtrack::Vec3 d = p - templateMesh.vertex(static_cast<int>(v));
    points->SetPoint(v, p.data());
    displacement->SetTuple3(v, d[0], d[1], d[2]);
    used->SetValue(v, fit.used.empty() ? 0 : fit.used[v]);
    distance->SetValue(v, fit.surfaceDistance.size() ? fit.surfaceDistance[v] : 0.0);
  }
  out->SetPoints(points);
  out->GetPointData()->AddArray(displacement);
  out->GetPointData()->AddArray(used);
  out->GetPointData()->AddArray(distance);
  return out;
}
} // namespace

ctTemplateFit::ctTemplateFit()
{
  this->SetNumberOfInputPorts(4);
  this->SetNumberOfOutputPorts(2);
  this->SetDefaultStages();
}

void ctTemplateFit::AddStage(double correspondence, double smoothness, double nearest,
                             double temporal)
{
  this->Options.stages.push_back({correspondence, smoothness, nearest, temporal});
  this->Modified();
}

void ctTemplateFit::RemoveAllStages()
{
  this->Options.stages.clear();
  this->Modified();
}

void ctTemplateFit::SetDefaultStages()
{
  this->Options.stages = clothtrack::TemplateFitOptions().stages;
  this->Modified();
}

ctOptionEnumDefinition(ctTemplateFit, Solver, clothtrack::FitSolver, Options.solver, EXACT, LBFGS);
ctOptionEnumDefinition(ctTemplateFit, FactorBackend, clothtrack::FactorBackend,
                       Options.factorBackend, BLOCK, CHOLMOD);

vtkTable* ctTemplateFit::GetSummaryOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(1));
}

int ctTemplateFit::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  if (port >= 2) info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int ctTemplateFit::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkTable" : "vtkMultiBlockDataSet");
  return 1;
}

namespace
{
/// The template frame the correspondences were made for (their TemplateFrame field data).
int correspondenceTemplateFrame(vtkMultiBlockDataSet* correspondence, int frames)
{
  auto* first = vtkPolyData::SafeDownCast(correspondence->GetBlock(0));
  vtkDataArray* templateField =
      first ? first->GetFieldData()->GetArray(clothtrack::arrays::TemplateFrame) : nullptr;
  if (!templateField)
    throw clothtrack::Error("template fit: the correspondence blocks carry no TemplateFrame (use "
                            "ctPatchCorrespondence)");
  const int j = static_cast<int>(templateField->GetComponent(0, 0));
  if (j < 0 || j >= frames)
    throw clothtrack::Error("template fit: the template frame " + std::to_string(j) +
                            " is not in the sequence");
  return j;
}

/// Output port 0: the aligned template of every frame, labelled as its input frame.
void addAlignedBlocks(vtkMultiBlockDataSet* output, vtkMultiBlockDataSet* sequence,
                      const clothtrack::TriangleMesh& templateMesh, int j,
                      const std::vector<clothtrack::FrameFit>& fits)
{
  const int n = static_cast<int>(fits.size());
  auto* templateData = vtkPolyData::SafeDownCast(sequence->GetBlock(j));
  output->SetNumberOfBlocks(n);
  for (int k = 0; k < n; ++k)
  {
    vtkSmartPointer<vtkPolyData> block = alignedPolyData(templateData, templateMesh, fits[k]);
    clothtrack::addFieldValue(block->GetFieldData(), clothtrack::arrays::FrameIndex, k);
    clothtrack::addFieldValue(block->GetFieldData(), clothtrack::arrays::TemplateFrame, j);
    // The frame's own time and name, so that players and writers label it as its input.
    if (auto* input = vtkPolyData::SafeDownCast(sequence->GetBlock(static_cast<unsigned>(k))))
      for (const char* name : {clothtrack::arrays::TimeValue, clothtrack::arrays::FrameNumber,
                               clothtrack::arrays::SourceFile})
        if (vtkAbstractArray* array = input->GetFieldData()->GetAbstractArray(name))
          block->GetFieldData()->AddArray(array);
    output->SetBlock(k, block);
    output->GetMetaData(static_cast<unsigned>(k))
        ->Set(vtkCompositeDataSet::NAME(), ("aligned_" + std::to_string(k)).c_str());
  }
}

/// Output port 1: one row per frame, with its confidence (clothtrack/eval/FrameConfidence.h).
void addSummaryRows(vtkTable* table, const std::vector<clothtrack::FrameFit>& fits,
                    const std::vector<clothtrack::FrameConfidence>& confidence)
{
  const int n = static_cast<int>(fits.size());
  auto frameColumn = namedArray<vtkIntArray>("Frame", n);
  auto distanceColumn = namedArray<vtkDoubleArray>("MeanSurfaceDistance", n);
  auto usedColumn = namedArray<vtkIntArray>("CorrespondencesUsed", n);
  auto nearestColumn = namedArray<vtkIntArray>("NearestValid", n);
  auto roundsColumn = namedArray<vtkIntArray>("Rounds", n);
  auto iterationsColumn = namedArray<vtkIntArray>("Iterations", n);
  auto energyColumn = namedArray<vtkDoubleArray>("Energy", n);
  auto secondsColumn = namedArray<vtkDoubleArray>("Seconds", n);
  auto coverageColumn = namedArray<vtkDoubleArray>("CoverageDistance", n);
  auto stretchColumn = namedArray<vtkDoubleArray>("Stretch", n);
  auto foldedColumn = namedArray<vtkDoubleArray>("Folded", n);
  auto bodyColumn = namedArray<vtkDoubleArray>("BodyDistance", n);
  auto extentColumn = namedArray<vtkDoubleArray>("ExtentGap", n);
  auto confidenceColumn = namedArray<vtkDoubleArray>("Confidence", n);
  auto attemptsColumn = namedArray<vtkIntArray>("Attempts", n);
  for (int k = 0; k < n; ++k)
  {
    const clothtrack::FrameFit& fit = fits[k];
    coverageColumn->SetValue(k, confidence[k].coverageDistance);
    stretchColumn->SetValue(k, confidence[k].stretch);
    foldedColumn->SetValue(k, confidence[k].folded);
    bodyColumn->SetValue(k, confidence[k].bodyDistance >= 0 ? confidence[k].bodyDistance : NAN);
    extentColumn->SetValue(k, confidence[k].extentGap >= 0 ? confidence[k].extentGap : NAN);
    confidenceColumn->SetValue(k, confidence[k].confidence);
    attemptsColumn->SetValue(k, fit.attempts);
    frameColumn->SetValue(k, k);
    distanceColumn->SetValue(k, fit.surfaceDistance.size() ? fit.surfaceDistance.mean() : 0.0);
    usedColumn->SetValue(k, static_cast<int>(std::count(fit.used.begin(), fit.used.end(), 1)));
    nearestColumn->SetValue(k, fit.nearestValid);
    roundsColumn->SetValue(k, fit.rounds);
    iterationsColumn->SetValue(k, fit.iterations);
    energyColumn->SetValue(k, fit.energy);
    secondsColumn->SetValue(k, fit.seconds);
  }
  for (vtkAbstractArray* column :
       {static_cast<vtkAbstractArray*>(frameColumn), static_cast<vtkAbstractArray*>(distanceColumn),
        static_cast<vtkAbstractArray*>(usedColumn), static_cast<vtkAbstractArray*>(nearestColumn),
        static_cast<vtkAbstractArray*>(roundsColumn),
        static_cast<vtkAbstractArray*>(iterationsColumn),
        static_cast<vtkAbstractArray*>(energyColumn), static_cast<vtkAbstractArray*>(secondsColumn),
        static_cast<vtkAbstractArray*>(coverageColumn),
        static_cast<vtkAbstractArray*>(stretchColumn), static_cast<vtkAbstractArray*>(foldedColumn),
        static_cast<vtkAbstractArray*>(bodyColumn), static_cast<vtkAbstractArray*>(extentColumn),
        static_cast<vtkAbstractArray*>(confidenceColumn),
        static_cast<vtkAbstractArray*>(attemptsColumn)})
    table->AddColumn(column);
}
} // namespace

int ctTemplateFit::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                               vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* correspondence = vtkMultiBlockDataSet::GetData(inputVector[1], 0);
  ThreadBudget threads(this->NumberOfThreads);
  try
  {
    checkOneBlockPerFrame(sequence, correspondence, "template fit", "correspondence");
    const int n = static_cast<int>(sequence->GetNumberOfBlocks());
    const int j = correspondenceTemplateFrame(correspondence, n);
    // The template is frame j itself: its geometry, with the correspondence's connectivity.
    const TriangleMesh templateMesh = frameMesh(sequence, j);
    const int nv = templateMesh.numVertices();
    std::vector<TriangleMesh> frames(n);
    for (int k = 0; k < n; ++k) frames[k] = frameMesh(sequence, k);
    SequenceFitHooks hooks;
    hooks.frame = [&](int k) { return borrowedFrame(frames[k]); };
    // Correspondences are converted when their turn comes; only the current one is held.
    VertexTargets targets;
    hooks.targets = [&](int k) -> const VertexTargets*
    {
      const std::string name = frameName(sequence->GetBlock(k), k);
      targets = targetsOf(vtkPolyData::SafeDownCast(correspondence->GetBlock(k)), nv, name);
      if (targets.count() == 0)
        vtkWarningMacro(<< "template fit: " << name
                        << " has no correspondence; it is fitted from nearest points alone");
      return &targets;
    };
    // With landmarks, each start follows their motion from the neighbouring frame.
    auto* landmarkBlocks = this->GetNumberOfInputConnections(2) > 0
                               ? vtkMultiBlockDataSet::GetData(inputVector[2], 0)
                               : nullptr;
    std::vector<std::vector<OrientedSurfacePoint>> landmarks;
    if (landmarkBlocks && this->Prediction.predictRadius > 0)
    {
      checkOneBlockPerFrame(sequence, landmarkBlocks, "template fit", "landmarks");
      for (int k = 0; k < n; ++k)
        landmarks.push_back(landmarkSurfacePoints(
            vtkPolyData::SafeDownCast(landmarkBlocks->GetBlock(static_cast<unsigned>(k))),
            frames[k].numFaces(), "landmarks of " + frameName(sequence->GetBlock(k), k)));
      hooks.start = landmarkStartPrediction([&](int k) { return borrowedFrame(frames[k]); },
                                            [&](int k) -> const std::vector<OrientedSurfacePoint>&
                                            { return landmarks[k]; },
                                            this->Prediction);
    }
    auto* bodies = this->GetNumberOfInputConnections(3) > 0
                       ? vtkMultiBlockDataSet::GetData(inputVector[3], 0)
                       : nullptr;
    // With bodies, each frame's fit is also judged against the template its body poses.
    TemplatePosedByBody posed;
    if (bodies)
    {
      checkOneBlockPerFrame(sequence, bodies, "template fit", "bodies");
      posed = posedByBody(sequence, bodies, templateMesh, j);
    }
    if (posed && this->StartFromBody)
    {
      const std::function<FramePtr(int)> stretchTo =
          this->StretchStartToFrame
              ? std::function<FramePtr(int)>([&](int k) { return borrowedFrame(frames[k]); })
              : nullptr;
      hooks.start = bodyStartPrediction(posed, std::move(hooks.start), stretchTo);
      narrowTargetsToBodyStart(hooks, posed, stretchTo, this->CorrespondenceGate);
    }
    if (this->RetryDoubtfulFrames) judgeFits(hooks, templateMesh, {}, posed);
    hooks.progress = [this](double done)
    {
      this->UpdateProgress(done);
      return !this->GetAbortExecute();
    };
    const std::vector<FrameFit> fits =
        fitTemplateSequence(templateMesh, j, n, hooks, this->Options);
    addAlignedBlocks(vtkMultiBlockDataSet::GetData(outputVector, 0), sequence, templateMesh, j,
                     fits);
    // Nothing is passed on unjudged: each frame's confidence, and a warning for a doubtful one.
    std::vector<const TriangleMesh*> framePointers;
    for (const TriangleMesh& frame : frames) framePointers.push_back(&frame);
    SequenceQuality quality =
        fittedSequenceQuality(fits, templateMesh.F, framePointers, j, {}, posed);
    if (bodies) doubtFromBodies(quality, bodyFitFlags(bodies));
    for (int k : quality.doubtfulFrames)
      vtkWarningMacro(<< "template fit: " << frameName(sequence->GetBlock(k), k)
                      << " is doubtful: " << quality.confidence[k].doubt);
    addSummaryRows(vtkTable::GetData(outputVector, 1), fits, quality.confidence);
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctTemplateFit::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Solver: " << (this->GetSolver() == LBFGS ? "L-BFGS" : "exact") << "\n";
  os << indent << "FactorBackend: " << (this->GetFactorBackend() == CHOLMOD ? "CHOLMOD" : "block")
     << "\n";
  for (const auto& s : this->Options.stages)
    os << indent << "Stage (wc, ws, wd, wt): " << s.correspondence << ", " << s.smoothness << ", "
       << s.nearest << ", " << s.temporal << "\n";
  os << indent << "RoundsPerStage: " << this->Options.roundsPerStage << "\n";
  os << indent << "SolverTolerance: " << this->Options.solverTolerance << "\n";
  os << indent << "IntermediateTolerance: " << this->Options.intermediateTolerance << "\n";
  os << indent << "RefactorSteps: " << this->Options.refactorSteps << "\n";
  os << indent << "NearestReuse: " << this->Options.nearestReuse << "\n";
  os << indent << "CoverageWeight: " << this->Options.coverageWeight << "\n";
  os << indent << "NearestEvery: " << this->Options.nearestEvery << "\n";
  os << indent << "MaximumNearestDistance: " << this->Options.maximumNearestDistance << "\n";
  os << indent << "MaximumNormalAngle: " << this->Options.maximumNormalAngle << "\n";
  os << indent << "UseCorrespondence: " << this->Options.useCorrespondence << "\n";
  os << indent << "UseNearest: " << this->Options.useNearest << "\n";
  os << indent << "RetryDoubtfulFrames: " << this->RetryDoubtfulFrames << "\n";
  os << indent << "PredictRadius: " << this->Prediction.predictRadius << "\n";
  os << indent << "LandmarkConsensus: " << this->Prediction.landmarkConsensus << "\n";
  os << indent << "StartFromBody: " << this->StartFromBody << "\n";
  os << indent << "StretchStartToFrame: " << this->StretchStartToFrame << "\n";
  os << indent << "CorrespondenceGate: " << this->CorrespondenceGate << "\n";
}
