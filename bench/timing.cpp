// Wall-clock helpers (see timing.h).
#include "timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kMillisecondsPerSecond = 1e3;

double thread_cpu_seconds()
{
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int frames_for(double seconds, double dt)
{
  return std::max(1, static_cast<int>(std::lround(seconds / dt)));
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

FrameTime time_frames(Engine& engine, int frames)
{
  const double cpu_start = thread_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f)
  {
    engine.step_frame();
  }
  const auto stop = std::chrono::steady_clock::now();
  const double cpu_stop = thread_cpu_seconds();
  const double wall = std::chrono::duration<double>(stop - start).count();
  return FrameTime{wall * kMillisecondsPerSecond / frames, (cpu_stop - cpu_start) * kMillisecondsPerSecond / frames};
}

}  // namespace bench
}  // namespace collision2d
