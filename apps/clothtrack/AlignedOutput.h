#pragma once
// The aligned sequence on disk: OUT/aligned.pvd and OUT/aligned/aligned_NNNN.vtp, each the
// template's connectivity with the point arrays Displacement, SurfaceDistance,
// CorrespondenceUsed and, with a ground truth, Error, and the field data FitAttempts, FitDoubt
// and FitRecovery (how the frame's fit was judged and retried).
#include <clothtrack/fit/TemplateFit.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace clothtrack::app
{
class AlignedOutput
{
public:
  AlignedOutput(const std::filesystem::path& outputFolder, const TriangleMesh& templateMesh);

  /// aligned/aligned_NNNN.vtp of the input's frame number.
  std::filesystem::path framePath(int frameNumber) const;
  /// The fit of a frame written by an earlier run (positions, correspondences used, surface
  /// distances, attempts, doubt and recovery), when it is readable and fits this template;
  /// `errors`, when given, receives its errors against the ground truth (empty without them).
  std::optional<FrameFit> earlier(int frameNumber, Eigen::VectorXd* errors = nullptr) const;
  /// Writes one frame (called from a writer thread: everything is passed by value).
  void write(int frameNumber, const FrameFit& fit, const Eigen::VectorXd& errors) const;
  /// aligned.pvd, listing the frames at their times.
  void writeCollection(const std::vector<int>& frameNumbers, double fps) const;

private:
  std::filesystem::path folder_;
  const TriangleMesh& template_;
};
} // namespace clothtrack::app
