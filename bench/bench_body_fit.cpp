// Body fit under clothing, measured.
//   bench_body_fit synthetic PRESET FRAMES [SAMPLES [STATURE]]   synthetic capture with known
//                                            beta and pose (STATURE: the person's height, m)
//   bench_body_fit folder DIR [STRIDE]        a real sequence (no body ground truth)
// Prints the accuracy figures and the time of the fit.
#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctMeshConversion.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/body/OrientedLandmarks.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/mesh/InsideTest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace clothtrack;

namespace
{
/// Fraction of the body's vertices inside the surface or within `slack` of it.
double insideOrNear(const SurfaceLocator& surface, const Points& body, double slack)
{
  int count = 0;
  for (Eigen::Index i = 0; i < body.rows(); ++i)
  {
    const Vec3 p = body.row(i).transpose();
    count += surface.closestPoint(p, slack).valid() || insideByRayParity(surface, p);
  }
  return static_cast<double>(count) / body.rows();
}

double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

struct LandmarkStats
{
  int total = 0, found = 0, compared = 0;
  double errorSum = 0.0;
};

void printStatus(const BodyFitResult& fit)
{
  int counts[3] = {0, 0, 0};
  double inside = 0, distance = 0;
  for (const auto& f : fit.frames)
  {
    ++counts[static_cast<int>(f.status)];
    inside += f.insideFraction;
    distance += f.medianDistance;
  }
  std::printf("status: %d ok, %d poor, %d failed; median body-frame distance %.2f cm, "
              "samples inside (closest-point sign) %.1f %%\n",
              counts[0], counts[1], counts[2], 100 * distance / fit.frames.size(),
              100 * inside / fit.frames.size());
}

int synthetic(const std::string& preset, int numFrames, double stature,
              const BodyFitOptions& options)
{
  const BodyModel& model = builtinBodyModel();
  SyntheticOptions synth;
  synth.preset = preset;
  synth.frames = numFrames;
  synth.stature = stature;
  std::vector<SyntheticFrame> truth;
  std::vector<TriangleMesh> captures;
  const Eigen::VectorXd trueBeta = generateSyntheticSequence(
      model, synth,
      [&](const SyntheticFrame& frame)
      {
        truth.push_back(frame);
        captures.push_back(simulateCapture(frame.clothed, CaptureOptions()));
      });
  std::vector<const TriangleMesh*> frames;
  for (const auto& c : captures) frames.push_back(&c);
  const auto start = std::chrono::steady_clock::now();
  const BodyFitResult fit = fitBodySequence(model, frames, options);
  const double elapsed = seconds(start);

  double jointError = 0, surfaceError = 0, inside = 0, near = 0, trueNear = 0;
  LandmarkStats landmarks;
  for (int i = 0; i < numFrames; ++i)
  {
    Points fittedJoints, trueJoints;
    const TriangleMesh fitted = model.posed(fit.beta, fit.frames[i].pose, &fittedJoints);
    const TriangleMesh body = model.posed(trueBeta, truth[i].pose, &trueJoints);
    const double frameJointError = (fittedJoints - trueJoints).rowwise().norm().mean();
    jointError += frameJointError;
    if (std::getenv("CLOTHTRACK_BENCH_VERBOSE"))
    {
      Eigen::Index worst;
      (fittedJoints - trueJoints).rowwise().norm().maxCoeff(&worst);
      std::printf("frame %d: joint error %.2f cm (worst %s)\n", i, 100 * frameJointError,
                  jointNames()[worst]);
      if (std::atoi(std::getenv("CLOTHTRACK_BENCH_VERBOSE")) > 1)
        for (int j = 0; j < fittedJoints.rows(); ++j)
          std::printf("  %-16s error %5.2f cm  fitted rotation %+.2f %+.2f %+.2f  true %+.2f %+.2f "
                      "%+.2f\n",
                      jointNames()[j], 100 * (fittedJoints.row(j) - trueJoints.row(j)).norm(),
                      fit.frames[i].pose.rotations(j, 0), fit.frames[i].pose.rotations(j, 1),
                      fit.frames[i].pose.rotations(j, 2), truth[i].pose.rotations(j, 0),
                      truth[i].pose.rotations(j, 1), truth[i].pose.rotations(j, 2));
    }
    surfaceError += (fitted.V - body.V).rowwise().norm().mean();
    const SurfaceLocator captured(captures[i]);
    inside += fractionInside(captured, fitted.V);
    near += insideOrNear(captured, fitted.V, 0.01);
    trueNear += insideOrNear(captured, body.V, 0.01);
    const SurfaceLocator clothed(truth[i].clothed);
    const auto reference =
        transferLandmarks(orientedLandmarks(model, body), truth[i].clothed, clothed);
    const auto estimate =
        transferLandmarks(orientedLandmarks(model, fitted), captures[i], captured);
    for (size_t k = 0; k < estimate.size(); ++k)
    {
      ++landmarks.total;
      landmarks.found += estimate[k].valid;
      if (estimate[k].valid && reference[k].valid)
      {
        ++landmarks.compared;
        landmarks.errorSum += (estimate[k].point.position - reference[k].point.position).norm();
      }
    }
  }
  std::printf("preset %s, %d frames: fit %.1f s (%.2f s/frame)\n", preset.c_str(), numFrames,
              elapsed, elapsed / numFrames);
  std::printf("beta error (first 4): ");
  for (int k = 0; k < 4; ++k) std::printf("%+.2f/%+.2f ", fit.beta[k], trueBeta[k]);
  std::printf("\n");
  printStatus(fit);
  std::printf("body vertices inside the capture %.1f %%, inside or within 1 cm %.1f %% (true "
              "body: %.1f %%)\n",
              100 * inside / numFrames, 100 * near / numFrames, 100 * trueNear / numFrames);
  std::printf("| preset | joints | body surface | landmark transfer | landmarks found |\n");
  std::printf("| %s | %.2f cm | %.2f cm | %.2f cm | %.1f %% |\n", preset.c_str(),
              100 * jointError / numFrames, 100 * surfaceError / numFrames,
              100 * landmarks.errorSum / std::max(1, landmarks.compared),
              100.0 * landmarks.found / landmarks.total);
  return 0;
}

int folder(const std::string& path, int stride, const BodyFitOptions& options)
{
  const BodyModel& model = builtinBodyModel();
  std::vector<TriangleMesh> meshes;
  for (const std::string& file : listFrames(path))
    meshes.push_back(loadFrame(file, FrameConventions()));
  std::vector<TriangleMesh> used;
  for (size_t i = 0; i < meshes.size(); i += stride) used.push_back(meshes[i]);
  std::vector<const TriangleMesh*> frames;
  for (const auto& m : used) frames.push_back(&m);
  const auto start = std::chrono::steady_clock::now();
  const BodyFitResult fit = fitBodySequence(model, frames, options);
  const double elapsed = seconds(start);
  double inside = 0, near = 0;
  LandmarkStats landmarks;
  for (size_t i = 0; i < used.size(); ++i)
  {
    const TriangleMesh fitted = model.posed(fit.beta, fit.frames[i].pose);
    const SurfaceLocator surface(used[i]);
    inside += fractionInside(surface, fitted.V);
    near += insideOrNear(surface, fitted.V, 0.01);
    for (const auto& t : transferLandmarks(orientedLandmarks(model, fitted), used[i], surface))
    {
      ++landmarks.total;
      landmarks.found += t.valid;
    }
  }
  std::printf("%s: %zu frames, fit %.1f s (%.2f s/frame)\n", path.c_str(), used.size(), elapsed,
              elapsed / used.size());
  printStatus(fit);
  std::printf("landmarks found %.1f %%, body vertices inside the frame %.1f %% (inside or within "
              "1 cm of it: %.1f %%)\n",
              100.0 * landmarks.found / landmarks.total, 100 * inside / used.size(),
              100 * near / used.size());
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string mode = argc > 1 ? argv[1] : "";
    // Optional arguments: body samples of the dense terms; the synthetic person's height.
    BodyFitOptions options;
    if (mode == "synthetic" && argc >= 4)
    {
      if (argc > 4) options.samples = std::stoi(argv[4]);
      return synthetic(argv[2], std::stoi(argv[3]), argc > 5 ? std::stod(argv[5]) : 0.0, options);
    }
    if (mode == "folder" && argc >= 3)
    {
      if (argc > 4) options.samples = std::stoi(argv[4]);
      return folder(argv[2], argc > 3 ? std::stoi(argv[3]) : 1, options);
    }
    std::fprintf(stderr,
                 "usage: bench_body_fit synthetic PRESET FRAMES [SAMPLES [STATURE]] | folder DIR "
                 "[STRIDE [SAMPLES]]\n");
    return 1;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "bench_body_fit: error: %s\n", e.what());
    return 1;
  }
}
