#include "Progress.h"

#include "Ranks.h"

#include <cstdio>
#include <unistd.h>

namespace clothtrack::app
{
Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()),
      interactive_(isatty(STDERR_FILENO) != 0)
{
}

void Progress::step(int done)
{
  if (!ranks::leader()) return; // one line for the processes of a run: the leader's
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double left = rate > 0 ? (total_ - done) / rate : 0.0;
  // A terminal gets one line rewritten in place; a log gets a line per step.
  std::fprintf(stderr, "%s%s: %d/%d frames, %.1f frames/s, %.0f s left%s", interactive_ ? "\r" : "",
               label_.c_str(), done, total_, rate, left, interactive_ ? "   " : "\n");
  std::fflush(stderr);
}

void Progress::finish()
{
  if (interactive_ && ranks::leader()) std::fprintf(stderr, "\n");
}
} // namespace clothtrack::app
