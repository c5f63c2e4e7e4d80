#include "AlignInput.h"

#include "ErrorMetrics.h"
#include "Progress.h"
#include "ReconstructRun.h"

#include "ctMeshConversion.h"
#include "ctPointCloudFile.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/MeshBinary.h>
#include <clothtrack/mesh/SubjectSize.h>

#include <algorithm>
#include <cstdio>
#include <map>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
/// The scanned meshes of one kind (input or ground truth): in memory while they fit in the
/// budget; from the first that does not, all of them in `folder` instead.
class FrameKeeper
{
public:
  FrameKeeper(fs::path folder, std::size_t budget) : folder_(std::move(folder)), budget_(budget) {}

  void add(int number, TriangleMesh mesh)
  {
    if (spilled_)
    {
      writeMeshBinary(path(folder_, number), mesh);
      return;
    }
    bytes_ += meshBytes(mesh);
    held_.emplace(number, std::move(mesh));
    if (bytes_ <= budget_) return;
    spilled_ = true;
    fs::create_directories(folder_);
    for (const auto& [n, m] : held_) writeMeshBinary(path(folder_, n), m);
    held_.clear();
  }

  /// The frames `numbers` (the ones kept, in order) as a cache of the same budget.
  std::shared_ptr<CachedFrames> frames(const std::vector<int>& numbers,
                                       const std::vector<std::string>& files,
                                       const FrameConventions& conventions)
  {
    auto load = [numbers, files, conventions, folder = folder_, spilled = spilled_](int k) {
      return spilled ? readMeshBinary(path(folder, numbers[k])) : loadFrame(files[k], conventions);
    };
    auto cache =
        std::make_shared<CachedFrames>(static_cast<int>(numbers.size()), std::move(load), budget_);
    for (size_t k = 0; k < numbers.size(); ++k)
      if (auto held = held_.find(numbers[k]); held != held_.end())
        cache->offer(static_cast<int>(k), std::move(held->second));
    held_.clear();
    return cache;
  }

  bool spilled() const { return spilled_; }

private:
  static std::string path(const fs::path& folder, int number)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%06d.bin", number);
    return (folder / name).string();
  }

  fs::path folder_;
  std::size_t budget_;
  std::size_t bytes_ = 0;
  bool spilled_ = false;
  std::map<int, TriangleMesh> held_;
};

/// What the scan keeps of a frame besides its mesh.
struct ScannedFrame
{
  std::string file, truthFile;
  int number = 0;
  FrameExtent extent;
  std::vector<std::string> subjectWarnings;
  std::string truthProblem; ///< groundTruthMismatch
  bool truthRefused = false;
};

/// Refuses a frame whose size says it is in another unit (leaves it out with --skip-bad-frames)
/// and warns about frames whose size or place jumps otherwise.
std::vector<FrameJump> checkFrameJumps(std::vector<ScannedFrame>& scanned, bool skipBadFrames)
{
  std::vector<FrameExtent> extents;
  for (const ScannedFrame& f : scanned) extents.push_back(f.extent);
  const std::vector<FrameJump> jumps = frameJumps(extents);
  std::vector<FrameJump> kept;
  for (auto jump = jumps.rbegin(); jump != jumps.rend(); ++jump)
  {
    const int k = jump->frame;
    const std::string line = scanned[k].file + ": " + jump->problem;
    if (!jump->refused)
    {
      kept.insert(kept.begin(), *jump);
      continue;
    }
    if (!skipBadFrames)
      throw UsageError{line + ": convert it, or leave it out with --skip-bad-frames"};
    std::fprintf(stderr, "warning: %s (frame left out)\n", line.c_str());
    scanned.erase(scanned.begin() + k);
    for (FrameJump& later : kept) --later.frame;
  }
  for (const FrameJump& jump : kept)
    std::fprintf(stderr, "warning: %s: %s\n", scanned[jump.frame].file.c_str(),
                 jump.problem.c_str());
  return kept;
}

/// Refuses a ground truth of another scale than the input; warns once when it lies elsewhere.
void checkGroundTruth(const std::vector<ScannedFrame>& scanned)
{
  bool warned = false;
  for (const ScannedFrame& f : scanned)
  {
    if (f.truthRefused) throw UsageError{f.truthFile + ": " + f.truthProblem + " (" + f.file + ")"};
    if (!f.truthProblem.empty() && !warned)
      std::fprintf(stderr, "warning: %s: %s (%s)\n", f.truthFile.c_str(), f.truthProblem.c_str(),
                   f.file.c_str());
    warned = warned || !f.truthProblem.empty();
  }
}

/// Says so when frames are missing from a numbered sequence: the motion jumps there. Files listed
/// in another order than their numbers (a list file) are a chosen set of poses: nothing is missing.
void warnAboutGaps(const std::vector<std::string>& files)
{
  for (size_t k = 1; k < files.size(); ++k)
    if (frameNumberFromName(files[k]) <= frameNumberFromName(files[k - 1])) return;
  for (size_t k = 1; k < files.size(); ++k)
  {
    const long before = frameNumberFromName(files[k - 1]), after = frameNumberFromName(files[k]);
    if (before >= 0 && after > before + 1)
      std::fprintf(stderr, "warning: frames %ld to %ld are missing between %s and %s\n", before + 1,
                   after - 1, fs::path(files[k - 1]).filename().c_str(),
                   fs::path(files[k]).filename().c_str());
  }
}

/// Point clouds among the frames in [begin, end) are reconstructed into OUT/reconstructed first
/// (in metres, Y up); the list then names the meshes ("" for a cloud that could not be).
bool reconstructClouds(const AlignSettings& s, std::vector<std::string>& files, int begin, int end)
{
  if (!std::any_of(files.begin() + begin, files.begin() + end, isPointCloudFile)) return false;
  const std::vector<std::string> clouds(files.begin() + begin, files.begin() + end);
  for (const auto& file : clouds)
    if (!isPointCloudFile(file))
      throw UsageError{file + ": a mesh among point clouds; give a sequence of one kind"};
  ReconstructSettings settings{s.reconstruction, toConventions(s.sequence), s.skipBadFrames};
  const auto meshes =
      reconstructSequence(clouds, (fs::path(s.output) / "reconstructed").string(), settings, begin);
  std::copy(meshes.begin(), meshes.end(), files.begin() + begin);
  return true;
}

/// The ground-truth files of `allFiles`, checked for number; empty without a ground truth.
std::vector<std::string> listGroundTruth(const AlignSettings& s, size_t inputFrames)
{
  if (s.truthInput.empty()) return {};
  std::vector<std::string> truth = listFrames(s.truthInput);
  if (truth.size() != inputFrames)
    throw UsageError{s.truthInput + ": " + std::to_string(truth.size()) +
                     " ground-truth frames for " + std::to_string(inputFrames) + " input frames"};
  return truth;
}
} // namespace

std::pair<int, int> frameRange(const std::string& spec, int count)
{
  if (spec.empty()) return {0, count};
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw UsageError{"--frames must be A:B (got '" + spec + "')"};
  auto number = [&](const std::string& text, int fallback)
  {
    if (text.empty()) return fallback;
    size_t used = 0;
    int value = 0;
    try
    {
      value = std::stoi(text, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used != text.size() || value < 0)
      throw UsageError{"--frames must be A:B with frame numbers >= 0 (got '" + spec + "')"};
    return value;
  };
  const int begin = number(spec.substr(0, colon), 0);
  const int end = std::min(count, number(spec.substr(colon + 1), count));
  if (begin >= end)
    throw UsageError{"--frames " + spec + " selects no frame of the " + std::to_string(count)};
  return {begin, end};
}

bool inputHasPointClouds(const AlignSettings& s)
{
  const std::vector<std::string> files = listFrames(s.input);
  const auto [begin, end] = frameRange(s.frameSpec, static_cast<int>(files.size()));
  return std::any_of(files.begin() + begin, files.begin() + end, isPointCloudFile);
}

Input readInput(const AlignSettings& s, const fs::path& work)
{
  FrameConventions conventions = toConventions(s.sequence);
  std::vector<std::string> allFiles = listFrames(s.input);
  const auto [begin, end] = frameRange(s.frameSpec, static_cast<int>(allFiles.size()));
  const bool fromClouds = reconstructClouds(s, allFiles, begin, end);
  const FrameConventions truthConventions = conventions;
  if (fromClouds) conventions = FrameConventions{};
  const std::vector<std::string> allTruth = listGroundTruth(s, allFiles.size());
  const auto budget = static_cast<std::size_t>(s.frameMemoryMB * 1024 * 1024);
  FrameKeeper frames(work / "frames", budget), truth(work / "truth", budget);
  std::vector<ScannedFrame> scanned;
  int truthFaces = -1;
  Progress progress("reading", end - begin);
  for (int k = begin; k < end; ++k)
  {
    try
    {
      if (allFiles[k].empty()) throw Error("frame " + std::to_string(k) + ": no reconstruction");
      std::vector<std::string> warnings;
      TriangleMesh mesh = loadFrame(allFiles[k], conventions, &warnings);
      for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
      ScannedFrame f;
      f.file = fs::absolute(allFiles[k]).string();
      f.number = k;
      f.extent = frameExtent(mesh);
      f.subjectWarnings = subjectWarnings(mesh);
      if (!allTruth.empty())
      {
        f.truthFile = allTruth[k];
        TriangleMesh t = loadFrame(f.truthFile, truthConventions);
        if (truthFaces < 0) truthFaces = t.numFaces();
        checkTruthConnectivity(f.truthFile, t, truthFaces);
        f.truthProblem = groundTruthMismatch(mesh, t, f.truthRefused);
        truth.add(k, std::move(t));
      }
      frames.add(k, std::move(mesh));
      scanned.push_back(std::move(f));
    }
    catch (const Error& e) // a UsageError (not an Error) stops the run
    {
      if (!s.skipBadFrames) throw;
      std::fprintf(stderr, "warning: %s (frame left out)\n", e.what());
    }
    progress.step(k - begin + 1);
  }
  progress.finish();
  Input in;
  for (const ScannedFrame& f : scanned) in.files.push_back(f.file);
  warnAboutGaps(in.files);
  in.jumps = checkFrameJumps(scanned, s.skipBadFrames);
  if (scanned.size() < 2) throw UsageError{s.input + ": at least two readable frames are needed"};
  for (const std::string& w : scanned.front().subjectWarnings)
    std::fprintf(stderr, "warning: %s: %s\n", scanned.front().file.c_str(), w.c_str());
  checkGroundTruth(scanned);
  in.files.clear();
  for (const ScannedFrame& f : scanned)
  {
    in.files.push_back(f.file);
    in.frameNumber.push_back(f.number);
    if (!allTruth.empty()) in.truthFiles.push_back(f.truthFile);
  }
  in.frames = frames.frames(in.frameNumber, in.files, conventions);
  if (!allTruth.empty()) in.truth = truth.frames(in.frameNumber, in.truthFiles, truthConventions);
  in.spilled = frames.spilled();
  // Markers are read now, so that a bad file stops the run before the long stages.
  if (!s.markersPath.empty()) in.markers = selectedMarkers(s.markersPath, in.frameNumber);
  return in;
}
} // namespace clothtrack::app
