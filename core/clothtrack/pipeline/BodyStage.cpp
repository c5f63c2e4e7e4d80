#include "BodyStage.h"

#include <clothtrack/base/Bytes.h>
#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/body/OrientedLandmarks.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace clothtrack
{
FrameMotion rigidFrameMotion(const RigidRegistrationOptions& options, double minimumOverlap)
{
  return [options, minimumOverlap](const TriangleMesh& from,
                                   const TriangleMesh& to) -> std::optional<Eigen::Isometry3d>
  {
    try
    {
      const RigidRegistration r = registerRigidly(from.V, to.V, options);
      if (!r.converged || r.overlap < minimumOverlap) return std::nullopt;
      return r.motion;
    }
    catch (const Error&) // too few points to register: the predecessor's pose as it is
    {
      return std::nullopt;
    }
  };
}

namespace
{
/// The frames whose landmarks this process carries: with a shared body fit its part of the
/// sequence (the others' come from them), else all.
std::pair<int, int> transferredFrames(const BodyStageOptions& options, int n)
{
  const BodyFitSharing& sharing = options.fit.sharing;
  if (!sharing.splits(n) || !sharing.allGather || options.keepBodyLandmarks) return {0, n};
  return rangePart(n, sharing.part, sharing.parts);
}

std::string encodeLandmarks(const std::vector<FrameLandmarks>& landmarks, int from, int to)
{
  ByteWriter w;
  w.put(static_cast<std::int32_t>(from));
  w.put(static_cast<std::int32_t>(to));
  for (int k = from; k < to; ++k)
  {
    w.put(static_cast<std::uint32_t>(landmarks[k].size()));
    for (const OrientedSurfacePoint& p : landmarks[k])
    {
      w.put(static_cast<std::int32_t>(p.id));
      w.put(static_cast<std::int32_t>(p.face));
      for (int c = 0; c < 3; ++c) w.put(p.bary[c]);
      for (int c = 0; c < 3; ++c) w.put(p.direction[c]);
      w.put(p.offset);
    }
  }
  return w.take();
}

void decodeLandmarks(const std::string& bytes, std::vector<FrameLandmarks>& landmarks)
{
  ByteReader r(bytes, "shared landmarks");
  const int from = r.get<std::int32_t>(), to = r.get<std::int32_t>();
  if (from < 0 || to > static_cast<int>(landmarks.size()) || from > to)
    throw Error("shared landmarks: frames out of range");
  for (int k = from; k < to; ++k)
  {
    landmarks[k].resize(r.get<std::uint32_t>());
    for (OrientedSurfacePoint& p : landmarks[k])
    {
      p.id = r.get<std::int32_t>();
      p.face = r.get<std::int32_t>();
      for (int c = 0; c < 3; ++c) p.bary[c] = r.get<double>();
      for (int c = 0; c < 3; ++c) p.direction[c] = r.get<double>();
      p.offset = r.get<double>();
    }
  }
  r.expectEnd();
}
} // namespace

BodyStageResult fitBodyAndLandmarks(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyStageOptions& options, const StageProgress& progress)
{
  return fitBodyAndLandmarks(model, FramesInMemory(frames), options, progress);
}

BodyStageResult fitBodyAndLandmarks(const BodyModel& model, const FrameSource& frames,
                                    const BodyStageOptions& options, const StageProgress& progress)
{
  constexpr double fitShare = 0.95;
  BodyStageResult out;
  BodyFitOptions fit = options.fit;
  if (options.registerFrames)
    fit.frameMotion = rigidFrameMotion(options.registration, options.minimumRegistrationOverlap);
  out.body = fitBodySequence(model, frames, fit,
                             [&](double done) { return !progress || progress(fitShare * done); });
  const int n = frames.count();
  if (options.keepBodyLandmarks)
  {
    out.bodyLandmarks.resize(n);
    out.transferred.resize(n);
  }
  out.landmarks.resize(n);
  const auto [from, to] = transferredFrames(options, n);
  parallelFor(
      from, to,
      [&](int k)
      {
        const BodyFrameFit& fit = out.body.frames[k];
        std::vector<OrientedPoint> bodyPoints =
            orientedLandmarks(model, model.posed(out.body.beta, fit.pose));
        std::vector<TransferredLandmark> transferred(bodyPoints.size());
        const FramePtr frame = fit.status == BodyFitStatus::Failed ? FramePtr() : frames.frame(k);
        if (frame)
        {
          const SurfaceLocator locator(*frame);
          transferred = transferLandmarks(bodyPoints, *frame, locator, options.transfer);
          out.landmarks[k] = landmarkSeeds(transferred);
        }
        if (!options.keepBodyLandmarks) return;
        out.bodyLandmarks[k] = std::move(bodyPoints);
        out.transferred[k] = std::move(transferred);
      },
      1);
  if (to - from < n)
    for (const std::string& bytes :
         options.fit.sharing.allGather(encodeLandmarks(out.landmarks, from, to)))
      decodeLandmarks(bytes, out.landmarks);
  if (progress && !progress(1.0)) throw Error("Body fit: cancelled.");
  return out;
}

std::vector<double> restPoseDistances(const BodyFitResult& body, double explainedRatio)
{
  const std::optional<double> median = medianFrameDistance(body.frames);
  const double limit = median ? explainedRatio * *median : std::numeric_limits<double>::infinity();
  std::vector<double> own;
  for (const BodyFrameFit& f : body.frames)
    own.push_back(f.frameDistance <= limit ? fittedRestPoseDistance(f.status, f.pose)
                                           : std::numeric_limits<double>::quiet_NaN());
  return confirmedByNeighbours(body.frames, own);
}

std::vector<double> confirmedByNeighbours(const std::vector<BodyFrameFit>& fits,
                                          const std::vector<double>& own)
{
  std::vector<double> out = own;
  for (size_t i = 0; i < own.size(); ++i)
  {
    if (!std::isfinite(own[i])) continue;
    if (i > 0 && fits[i].continuesPrevious && std::isfinite(own[i - 1]))
      out[i] = std::max(out[i], own[i - 1]);
    if (i + 1 < own.size() && fits[i + 1].continuesPrevious && std::isfinite(own[i + 1]))
      out[i] = std::max(out[i], own[i + 1]);
  }
  return out;
}
} // namespace clothtrack
