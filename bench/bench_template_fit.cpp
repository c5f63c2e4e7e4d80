// Template fitting (stage 3) against ground truth: the whole pipeline (body fit, landmarks,
// automatic template, geodesic-patch correspondence, template fit) on a sequence, then the
// distance of every aligned template vertex to the true position of the same point.
//   bench_template_fit samba DIR [options]        the sequence as it is (the paper's protocol:
//                                                 template vertex i is vertex i of the truth)
//   bench_template_fit remesh DIR [options]       re-meshed by the capture simulator (truth through
//                                                 each template vertex's source point)
//   bench_template_fit synthetic PRESET FRAMES [options]
// options: --stride S, --frames N (first N after the stride), --template K (template frame K
// instead of the automatic choice; 0 fits one chain), --variants LIST (comma separated,
// of exact, lbfgs, no-ec, no-ed, lbfgs-no-ec, true-ec (the matched vertices pointing at their
// true positions: stage 3 alone); default exact), --refactor-steps S (exact solve: renew a
// stage's factor after a frame averaging more CG steps per round; 0: only on failure), --rounds R
// (nearest-point rounds per stage), --stages "wc,ws,wd,wt;..." (weights of each stage), --outlier D
// (correspondences further than D from the current fit are dropped; 0: never), --predict R (each
// frame started from the previous fit moved by the landmarks' locally rigid motion, Gaussian width
// R metres), --curve FILE (per-frame mean error of each variant, CSV, rewritten after each
// variant), --repeat N (the variants take turns N times; a table of their median, fastest and
// slowest wall time per frame follows). A variant may carry options of its own after slashes,
// e.g. exact/reuse=0.0002/convergence=1e-3 (keys: reuse, convergence, rounds, tolerance,
// intermediate, refactor).
#include "BenchSequence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/fit/MotionPrediction.h>
#include <clothtrack/fit/SequenceFit.h>
#include <clothtrack/fit/TemplateFit.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

using namespace clothtrack;
using namespace clothtrack::bench;

namespace
{
std::vector<std::string> split(const std::string& list, char separator = ',')
{
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, separator);)
    if (!item.empty()) out.push_back(item);
  return out;
}
struct Variant
{
  std::string name;
  TemplateFitOptions options;
};

int roundsPerStage = 0;           // 0: the default
double solverTolerance = 0;       // 0: the default
double convergence = 0;           // 0: the default
double intermediateTolerance = 0; // 0: the default
double refactorSteps = -1;        // negative: the default
std::vector<FitStage> stages;     // empty: the default
double outlier = -1;              // negative: the default
double predictRadius = 0;         // > 0: starts predicted from the landmarks' motion
double predictOffset = 1e9;       // landmarks further from the body are not used for it
double lengthScale = 0;           // 0: the default

Variant variant(const std::string& fullName)
{
  // NAME/key=value/...: a variant with some options of its own (timing comparisons in one run).
  const std::vector<std::string> parts = split(fullName, '/');
  // (exact/cholmod=1: the same with CHOLMOD's factorisation.)
  const std::string name = parts.empty() ? "" : parts[0];
  Variant v{fullName, {}};
  if (roundsPerStage > 0) v.options.roundsPerStage = roundsPerStage;
  if (solverTolerance > 0) v.options.solverTolerance = solverTolerance;
  if (convergence > 0) v.options.convergence = convergence;
  if (intermediateTolerance > 0) v.options.intermediateTolerance = intermediateTolerance;
  if (refactorSteps >= 0) v.options.refactorSteps = refactorSteps;
  if (lengthScale > 0) v.options.lengthScale = lengthScale;
  if (!stages.empty()) v.options.stages = stages;
  if (outlier >= 0) v.options.correspondenceOutlier = outlier;
  if (name == "lbfgs" || name == "lbfgs-no-ec") v.options.solver = FitSolver::LBFGS;
  if (name == "no-ec" || name == "lbfgs-no-ec") v.options.useCorrespondence = false;
  if (name == "no-ed") v.options.useNearest = false;
  if (name != "exact" && name != "lbfgs" && name != "no-ec" && name != "no-ed" &&
      name != "lbfgs-no-ec" && name != "true-ec")
    throw Error("unknown variant '" + name + "'");
  for (size_t k = 1; k < parts.size(); ++k)
  {
    const size_t eq = parts[k].find('=');
    if (eq == std::string::npos) throw Error("variant option '" + parts[k] + "' is not key=value");
    const std::string key = parts[k].substr(0, eq);
    const double value = std::stod(parts[k].substr(eq + 1));
    if (key == "reuse")
      v.options.nearestReuse = value;
    else if (key == "convergence")
      v.options.convergence = value;
    else if (key == "rounds")
      v.options.roundsPerStage = static_cast<int>(value);
    else if (key == "tolerance")
      v.options.solverTolerance = value;
    else if (key == "intermediate")
      v.options.intermediateTolerance = value;
    else if (key == "refactor")
      v.options.refactorSteps = value;
    else if (key == "cholmod")
      v.options.factorBackend = value != 0 ? FactorBackend::Cholmod : FactorBackend::Block;
    else
      throw Error("unknown variant option '" + key + "'");
  }
  return v;
}

struct Summary
{
  double mean = 0, p90 = 0, within10 = 0, worstFrame = 0, secondsPerFrame = 0;
  double roundsPerFrame = 0, stepsPerFrame = 0, factorisationsPerFrame = 0, searchesPerFrame = 0;
  double factorSeconds = 0, solveSeconds = 0; ///< per factorisation, per conjugate-gradient step
  std::vector<double> perFrame;
};

Summary evaluate(const Sequence& s, int j, const std::vector<FrameFit>& fits)
{
  Summary out;
  std::vector<double> errors;
  out.perFrame.assign(fits.size(), 0.0);
  double time = 0;
  for (size_t k = 0; k < fits.size(); ++k)
  {
    if (static_cast<int>(k) == j) continue;
    time += fits[k].seconds;
    out.roundsPerFrame += fits[k].rounds;
    out.stepsPerFrame += fits[k].iterations;
    out.factorisationsPerFrame += fits[k].factorisations;
    out.factorSeconds += fits[k].factorSeconds;
    out.solveSeconds += fits[k].solveSeconds;
    out.searchesPerFrame += fits[k].nearestSearches;
    double sum = 0;
    int count = 0;
    for (int v = 0; v < fits[k].positions.rows(); ++v)
    {
      Vec3 truth;
      if (!s.truthOf(j, v, static_cast<int>(k), truth)) continue;
      const double e = (fits[k].positions.row(v).transpose() - truth).norm();
      errors.push_back(e);
      sum += e;
      ++count;
    }
    out.perFrame[k] = sum / std::max(1, count);
    out.worstFrame = std::max(out.worstFrame, out.perFrame[k]);
  }
  for (double e : errors) out.mean += e, out.within10 += e <= 0.10;
  out.mean /= std::max<size_t>(1, errors.size());
  out.within10 *= 100.0 / std::max<size_t>(1, errors.size());
  if (!errors.empty())
  {
    std::nth_element(errors.begin(), errors.begin() + errors.size() * 9 / 10, errors.end());
    out.p90 = errors[errors.size() * 9 / 10];
  }
  out.factorSeconds /= std::max(1.0, out.factorisationsPerFrame); // totals so far
  out.solveSeconds /= std::max(1.0, out.stepsPerFrame);
  out.secondsPerFrame = time / std::max<size_t>(1, fits.size() - 1);
  out.roundsPerFrame /= std::max<size_t>(1, fits.size() - 1);
  out.stepsPerFrame /= std::max<size_t>(1, fits.size() - 1);
  out.factorisationsPerFrame /= std::max<size_t>(1, fits.size() - 1);
  out.searchesPerFrame /= std::max<size_t>(1, fits.size() - 1);
  return out;
}

/// Per-frame mean error of each variant finished so far, CSV (metres).
void writeCurve(const std::string& path, const std::vector<std::string>& variants,
                std::map<std::string, Summary>& results, int frames)
{
  std::ofstream out(path);
  out << "frame";
  for (const auto& name : variants)
    if (results.count(name)) out << "," << name;
  out << "\n";
  for (int k = 0; k < frames; ++k)
  {
    out << k;
    for (const auto& name : variants)
      if (results.count(name)) out << "," << results[name].perFrame[k];
    out << "\n";
  }
}

int run(Sequence& s, const std::vector<std::string>& variants, const std::string& curve,
        int forcedTemplate, int repeat)
{
  if (forcedTemplate >= static_cast<int>(s.captures.size()))
    throw Error("--template " + std::to_string(forcedTemplate) + " is past the last frame");
  const int j = forcedTemplate >= 0 ? forcedTemplate : chooseTemplate(s);
  const TriangleMesh& templ = s.captures[j];
  std::printf("template frame %d: %d vertices, %d faces; %d threads\n", j, templ.numVertices(),
              templ.numFaces(), threadCount());
  auto start = std::chrono::steady_clock::now();
  const TemplatePatches patches(templ, s.landmarks[j]);
  std::vector<VertexTargets> targets(s.captures.size());
  double matched = 0;
  for (size_t k = 0; k < s.captures.size(); ++k)
  {
    if (static_cast<int>(k) == j) continue;
    const FrameCorrespondence c = patches.correspond(s.captures[k], s.landmarks[k]);
    targets[k] = vertexTargets(c);
    matched += c.matchedFraction();
  }
  const int frames = static_cast<int>(s.captures.size());
  std::printf("correspondence: %.2f s/frame, %.1f %% of template vertices matched\n",
              seconds(start) / std::max(1, frames - 1), 100 * matched / std::max(1, frames - 1));
  // fit time/frame: one frame's fit; wall/frame: the whole stage over the fitted frames, the two
  // chains (before and after the template frame) side by side.
  std::printf(
      "| variant | mean error | p90 | within 10 cm | worst frame mean | fit time/frame | "
      "wall/frame | rounds/frame | solver steps/frame | factorisations/frame | searches/frame | "
      "s/factorisation | s/solver step |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::map<std::string, Summary> results;
  std::map<std::string, std::vector<double>> walls;
  // With --repeat the variants take turns, so that a slower spell of the machine falls on all.
  for (int turn = 0; turn < repeat; ++turn)
    for (const std::string& name : variants)
    {
      const Variant v = variant(name);
      // true-ec: the same matched vertices, each pointing at its true position (stage 3 alone).
      std::vector<VertexTargets> truthTargets;
      if (split(name, '/')[0] == "true-ec")
        for (int k = 0; k < frames; ++k)
        {
          VertexTargets t = targets[k];
          for (int i = 0; i < templ.numVertices() && k != j; ++i)
          {
            Vec3 truth;
            if (t.matched[i] && s.truthOf(j, i, k, truth))
              t.position.row(i) = truth.transpose();
            else
              t.matched[i] = 0;
          }
          truthTargets.push_back(std::move(t));
        }
      StartPrediction predict;
      if (predictRadius > 0)
        predict = [&](int k, int from, const Points& fit)
        {
          std::vector<Vec3> before, after;
          pairLandmarks(s.captures[from], s.landmarks[from], s.captures[k], s.landmarks[k], before,
                        after, predictOffset);
          return predictMotion(fit, before, after, predictRadius);
        };
      const auto fitStart = std::chrono::steady_clock::now();
      SequenceFitHooks hooks;
      hooks.frame = [&](int k) { return borrowedFrame(s.captures[k]); };
      hooks.targets = [&](int k) { return truthTargets.empty() ? &targets[k] : &truthTargets[k]; };
      hooks.start = predict;
      const auto fits = fitTemplateSequence(templ, j, frames, hooks, v.options);
      const double wall = seconds(fitStart) / std::max(1, frames - 1);
      const Summary r = evaluate(s, j, fits);
      std::printf("| %s | %.2f cm | %.2f cm | %.2f %% | %.2f cm | %.3f s | %.3f s | %.1f | %.1f | "
                  "%.2f | %.0f | %.4f s | %.4f s |\n",
                  name.c_str(), 100 * r.mean, 100 * r.p90, r.within10, 100 * r.worstFrame,
                  r.secondsPerFrame, wall, r.roundsPerFrame, r.stepsPerFrame,
                  r.factorisationsPerFrame, r.searchesPerFrame, r.factorSeconds, r.solveSeconds);
      std::fflush(stdout);
      results[name] = r;
      walls[name].push_back(wall);
      if (!curve.empty()) writeCurve(curve, variants, results, frames);
    }
  if (repeat > 1)
  {
    std::printf("\n| variant | wall/frame, median of %d | fastest | slowest |\n|---|---|---|---|\n",
                repeat);
    for (const std::string& name : variants)
    {
      std::vector<double>& w = walls[name];
      std::sort(w.begin(), w.end());
      std::printf("| %s | %.3f s | %.3f s | %.3f s |\n", name.c_str(), w[w.size() / 2], w.front(),
                  w.back());
    }
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    std::vector<std::string> args(argv + 1, argv + argc);
    int stride = 1, maxFrames = 0, forcedTemplate = -1, repeat = 1;
    std::vector<std::string> variants = {"exact"};
    std::string curve;
    std::vector<std::string> positional;
    for (size_t i = 0; i < args.size(); ++i)
    {
      auto value = [&]()
      {
        if (i + 1 >= args.size()) throw Error(args[i] + " needs a value");
        return args[++i];
      };
      if (args[i] == "--stride")
        stride = std::max(1, std::stoi(value()));
      else if (args[i] == "--template")
        forcedTemplate = std::stoi(value());
      else if (args[i] == "--frames")
        maxFrames = std::stoi(value());
      else if (args[i] == "--variants")
        variants = split(value());
      else if (args[i] == "--repeat")
        repeat = std::max(1, std::stoi(value()));
      else if (args[i] == "--curve")
        curve = value();
      else if (args[i] == "--tolerance")
        solverTolerance = std::stod(value());
      else if (args[i] == "--threads")
        setThreadCount(std::stoi(value()));
      else if (args[i] == "--intermediate-tolerance")
        intermediateTolerance = std::stod(value());
      else if (args[i] == "--refactor-steps")
        refactorSteps = std::stod(value());
      else if (args[i] == "--convergence")
        convergence = std::stod(value());
      else if (args[i] == "--length-scale")
        lengthScale = std::stod(value());
      else if (args[i] == "--predict-offset")
        predictOffset = std::stod(value());
      else if (args[i] == "--predict")
        predictRadius = std::stod(value());
      else if (args[i] == "--rounds")
        roundsPerStage = std::stoi(value());
      else if (args[i] == "--outlier")
        outlier = std::stod(value());
      else if (args[i] == "--stages")
        for (const std::string& stage : split(value(), ';'))
        {
          const auto w = split(stage, ',');
          if (w.size() != 4) throw Error("a stage is four weights wc,ws,wd,wt");
          stages.push_back({std::stod(w[0]), std::stod(w[1]), std::stod(w[2]), std::stod(w[3])});
        }
      else
        positional.push_back(args[i]);
    }
    for (const auto& v : variants) variant(v); // reject unknown names before the long work
    const std::string mode = positional.empty() ? "" : positional[0];
    if ((mode == "samba" || mode == "remesh") && positional.size() == 2)
    {
      Sequence s = directorySequence(positional[1], stride, maxFrames, mode == "remesh");
      return run(s, variants, curve, forcedTemplate, repeat);
    }
    if (mode == "synthetic" && positional.size() == 3)
    {
      Sequence s = syntheticSequence(positional[1], std::stoi(positional[2]), false);
      return run(s, variants, curve, forcedTemplate, repeat);
    }
    std::fprintf(stderr,
                 "usage: bench_template_fit samba|remesh DIR | synthetic PRESET FRAMES "
                 "[--stride S] [--frames N] [--template K] [--variants exact,lbfgs,no-ec,no-ed] "
                 "[--curve FILE] [--tolerance T] [--intermediate-tolerance T] [--refactor-steps S] "
                 "[--convergence M] [--rounds R] [--predict R] [--threads N] [--repeat N]\n"
                 "a variant may set options of its own: exact/reuse=0.0002/convergence=1e-3 (keys "
                 "reuse, convergence, rounds, tolerance, intermediate, refactor)\n");
    return 1;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "bench_template_fit: %s\n", e.what());
    return 1;
  }
}
