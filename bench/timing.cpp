// Wall-clock helpers (see timing.h).
#include "timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kMillisecondsPerSecond = 1e3;
}

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

double time_frames(Engine& engine, int frames)
{
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f)
  {
    engine.step_frame();
  }
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(stop - start).count() * kMillisecondsPerSecond / frames;
}

}  // namespace bench
}  // namespace collision2d
