#pragma once
// One updating progress line on stderr: items done, rate and time left.
#include <chrono>
#include <string>

namespace clothtrack::app
{
class Progress
{
public:
  Progress(std::string label, int total);
  void step(int done);
  void finish();

private:
  std::string label_;
  int total_;
  std::chrono::steady_clock::time_point start_;
  double lastPrinted_ = -1e9;
  bool interactive_;
};
} // namespace clothtrack::app
