#include "SequenceFit.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

namespace clothtrack
{
namespace
{
/// State shared by the two chains and the thread that reports progress.
struct Chains
{
  Chains(const TriangleMesh& templ, int j, const SequenceFitHooks& h, const TemplateFitOptions& o,
         std::vector<FrameFit>& f)
      : templateMesh(templ), templateFrame(j), hooks(h), options(o), fits(f)
  {
  }
  const TriangleMesh& templateMesh;
  int templateFrame;
  const SequenceFitHooks& hooks;
  const TemplateFitOptions& options;
  std::vector<FrameFit>& fits;
  std::mutex mutex;
  std::condition_variable changed;
  int done = 0;
  int total = 0; ///< frames of the chains this call fits, the template frame included
  bool stop = false;
  /// One chain after the other on the calling thread, which then reports progress itself.
  bool reportInline = false;
  /// Threads of the whole fit, shared by the chains still running: once one chain ends (the
  /// template frame is rarely in the middle), the other gets them all.
  int threads = threadCount();
  std::atomic<int> runningChains{1};
  std::exception_ptr failure;

  /// Frame k's inputs, or its earlier result, read under the lock.
  struct Inputs
  {
    FramePtr frame;
    std::optional<VertexTargets> targets;
    Points start;
    Points neighbour; ///< the neighbour's fit, when the start was predicted from it
  };

  /// Fits frame k from `in`; with a judge, a doubtful fit is tried again from other starts and
  /// the best judged one kept.
  FrameFit fitFrame(const TemplateFitter& fitter, int k, const Inputs& in) const
  {
    const ThreadBudget budget(std::max(1, threads / runningChains.load()));
    const VertexTargets* targets = in.targets ? &*in.targets : nullptr;
    FrameFit best = fitter.fit(in.start, *in.frame, targets);
    if (!hooks.judge) return best;
    best.doubt = hooks.judge(k, *in.frame, best);
    struct Alternative
    {
      const char* name;
      const Points* start;
      bool withTargets;
    };
    const bool predicted = in.neighbour.rows() > 0;
    const Alternative alternatives[] = {
        {"the neighbour's fit as start", predicted ? &in.neighbour : nullptr, true},
        {"nearest points alone", targets ? &in.start : nullptr, false},
        {"the neighbour's fit, nearest points alone",
         predicted && targets ? &in.neighbour : nullptr, false}};
    int attempts = 1;
    double seconds = best.seconds;
    for (const Alternative& alternative : alternatives)
    {
      if (!(best.doubt > std::max(1.0, hooks.retryAbove))) break;
      if (!alternative.start) continue;
      FrameFit other =
          fitter.fit(*alternative.start, *in.frame, alternative.withTargets ? targets : nullptr);
      ++attempts;
      seconds += other.seconds;
      other.doubt = hooks.judge(k, *in.frame, other);
      if (other.doubt < best.doubt)
      {
        best = std::move(other);
        best.recovery = alternative.name;
      }
    }
    best.attempts = attempts;
    best.seconds = seconds; // every attempt's
    return best;
  }

  /// Drops frame k's per-vertex results unless they are kept (SequenceFitHooks::keepFits); the
  /// template frame's stay, both chains start from them.
  void release(int k)
  {
    if (hooks.keepFits || k < 0 || k >= static_cast<int>(fits.size()) || k == templateFrame) return;
    FrameFit& f = fits[k];
    if (f.meanSurfaceDistance < 0 && f.surfaceDistance.size() > 0)
      f.meanSurfaceDistance = f.surfaceDistance.mean();
    f.positions = Points();
    f.used = {};
    f.surfaceDistance = Eigen::VectorXd();
  }

  /// Takes an earlier run's result for frame k; false when there is none.
  bool resume(int k)
  {
    if (!hooks.resumed) return false;
    std::optional<FrameFit> earlier = hooks.resumed(k);
    if (!earlier) return false;
    fits[k] = std::move(*earlier);
    fits[k].resumed = true;
    return true;
  }

  void finish(int k, bool fitted)
  {
    if (fitted && hooks.fitted) hooks.fitted(k, fits[k]);
    ++done;
    changed.notify_all();
    if (reportInline && hooks.progress && !hooks.progress(static_cast<double>(done) / total))
      throw Error("Template fit: cancelled.");
  }

  /// Fits the chain's frames; its first starts from the template frame's fit.
  void run(const FitChain& chain)
  {
    const int from = chain.first, to = chain.end, direction = chain.direction;
    try
    {
      TemplateFitter fitter(templateMesh, options);
      for (int k = from; k != to; k += direction)
      {
        Inputs in;
        std::optional<TemplateFitterState> earlierState; // after the last resumed frame
        {
          const std::lock_guard<std::mutex> lock(mutex);
          if (stop) return;
          if (resume(k))
          {
            finish(k, false);
            continue;
          }
          const int previous = k == from ? templateFrame : k - direction;
          if (k != from && fits[previous].resumed && hooks.resumedState)
            earlierState = hooks.resumedState(previous);
          in.frame = hooks.frame(k);
          if (!in.frame) throw Error("Frame " + std::to_string(k) + ": no frame to fit.");
          if (hooks.targets)
            if (const VertexTargets* t = hooks.targets(k)) in.targets = *t;
          in.start = hooks.start ? hooks.start(k, previous, fits[previous].positions)
                                 : fits[previous].positions;
          if (hooks.start && hooks.judge) in.neighbour = fits[previous].positions;
          release(previous);
        }
        FrameFit fit;
        try
        {
          if (earlierState) fitter.restore(*earlierState); // factorises: outside the lock
          fit = fitFrame(fitter, k, in);
        }
        catch (const Error& e)
        {
          throw Error("Frame " + std::to_string(k) + ": " + e.what());
        }
        const std::lock_guard<std::mutex> lock(mutex);
        if (hooks.fitterState) hooks.fitterState(k, fitter.state());
        fits[k] = std::move(fit);
        finish(k, true);
      }
      const std::lock_guard<std::mutex> lock(mutex);
      release(to - direction);
    }
    catch (...)
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
      changed.notify_all();
    }
  }

  /// Reports progress until both chains have ended; a cancel stops them.
  void report()
  {
    std::unique_lock<std::mutex> lock(mutex);
    int reported = -1;
    while (runningChains > 0)
    {
      if (done != reported && !stop && hooks.progress)
      {
        reported = done;
        if (!hooks.progress(static_cast<double>(reported) / total))
        {
          failure = std::make_exception_ptr(Error("Template fit: cancelled."));
          stop = true;
        }
        continue;
      }
      changed.wait(lock);
    }
  }
};
} // namespace

std::vector<FitChain> sequenceChains(int numFrames, int templateFrame, int count)
{
  if (count < 1) throw Error("Template fit: " + std::to_string(count) + " chains.");
  const int before = templateFrame, after = numFrames - templateFrame - 1;
  if (before + after == 0) return {};
  // Up to two: one chain on each side that has frames (the paper's). More: in proportion to each
  // side's frames, at least one on a side that has frames, at most one per frame.
  int backward = before > 0, forward = after > 0;
  if (count > 2)
  {
    backward = before == 0  ? 0
               : after == 0 ? count
                            : std::clamp(static_cast<int>(std::lround(static_cast<double>(count) *
                                                                      before / (before + after))),
                                         1, count - 1);
    forward = after == 0 ? 0 : count - backward;
    backward = std::min(backward, before);
    forward = std::min(forward, after);
  }
  std::vector<FitChain> chains;
  // Backward: the segment next to the template first, each fitted from its template-side end.
  for (int c = 0; c < backward; ++c)
  {
    const int high = before - static_cast<int>(static_cast<long long>(before) * c / backward);
    const int low = before - static_cast<int>(static_cast<long long>(before) * (c + 1) / backward);
    chains.push_back({high - 1, low - 1, -1});
  }
  for (int c = 0; c < forward; ++c)
  {
    const int low =
        templateFrame + 1 + static_cast<int>(static_cast<long long>(after) * c / forward);
    const int high =
        templateFrame + 1 + static_cast<int>(static_cast<long long>(after) * (c + 1) / forward);
    chains.push_back({low, high, +1});
  }
  return chains;
}

std::vector<FrameFit> fitTemplateSequence(const TriangleMesh& templateMesh, int templateFrame,
                                          int numFrames, const SequenceFitHooks& hooks,
                                          const TemplateFitOptions& options)
{
  if (templateFrame < 0 || templateFrame >= numFrames)
    throw Error("Template fit: the template frame " + std::to_string(templateFrame) +
                " is not in the sequence of " + std::to_string(numFrames) + " frames.");
  if (!hooks.frame) throw Error("Template fit: no frame source.");
  std::vector<FrameFit> fits(numFrames);
  Chains chains(templateMesh, templateFrame, hooks, options, fits);
  const std::vector<FitChain> all = sequenceChains(numFrames, templateFrame, hooks.chainCount);
  std::vector<FitChain> own;
  for (int c = 0; c < static_cast<int>(all.size()); ++c)
    if (hooks.fitChains.empty() ||
        std::find(hooks.fitChains.begin(), hooks.fitChains.end(), c) != hooks.fitChains.end())
      own.push_back(all[c]);
  // The call that fits the first chain (or, in a sequence of one frame, every call) reports the
  // template frame; every call starts from it.
  const bool reportsTemplate =
      hooks.fitChains.empty() || all.empty() ||
      std::find(hooks.fitChains.begin(), hooks.fitChains.end(), 0) != hooks.fitChains.end();
  chains.total = reportsTemplate;
  for (const FitChain& c : own) chains.total += c.frames();
  if (!reportsTemplate)
    fits[templateFrame].positions = templateMesh.V;
  else
  {
    const std::lock_guard<std::mutex> lock(chains.mutex);
    if (!chains.resume(templateFrame))
    {
      FrameFit& self = fits[templateFrame];
      self.positions = templateMesh.V;
      self.used.assign(templateMesh.numVertices(), 0);
      self.surfaceDistance = Eigen::VectorXd::Zero(templateMesh.numVertices());
      self.meanSurfaceDistance = 0.0;
      chains.finish(templateFrame, true);
    }
    else
      chains.finish(templateFrame, false);
  }
  auto chain = [&](const FitChain& c)
  {
    chains.run(c);
    const std::lock_guard<std::mutex> lock(chains.mutex);
    --chains.runningChains;
    chains.changed.notify_all();
  };
  if (threadCount() > 1 && own.size() > 1)
  {
    chains.runningChains = static_cast<int>(own.size());
    std::vector<std::thread> threads;
    for (const FitChain& c : own) threads.emplace_back(chain, c);
    chains.report();
    for (std::thread& t : threads) t.join();
  }
  else
  {
    chains.reportInline = true;
    for (const FitChain& c : own) chains.run(c);
  }
  if (chains.failure) std::rethrow_exception(chains.failure);
  if (hooks.progress) hooks.progress(1.0);
  return fits;
}
} // namespace clothtrack
