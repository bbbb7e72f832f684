// Timing helpers (see timing.h).
#include "timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kMillisecondsPerSecond = 1e3;
/// Blocks below this come from the heap, never from a mapping of their own
/// (bytes; the largest value glibc accepts on 64-bit systems).
constexpr int kMmapThresholdBytes = 32 * 1024 * 1024;
/// Free memory at the heap's top is kept up to this much (bytes).
constexpr int kTrimThresholdBytes = 64 * 1024 * 1024;

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

FrameTime time_paced_frames(Engine& engine, int frames, double period_ms)
{
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double, std::milli>(period_ms));
  double wall = 0.0;
  double cpu = 0.0;
  auto tick = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f)
  {
    tick += period;
    std::this_thread::sleep_until(tick);
    const double cpu_start = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    engine.step_frame();
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpu += thread_cpu_seconds() - cpu_start;
  }
  return FrameTime{wall * kMillisecondsPerSecond / frames, cpu * kMillisecondsPerSecond / frames};
}

void fix_allocator_thresholds()
{
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
  mallopt(M_TRIM_THRESHOLD, kTrimThresholdBytes);
#endif
}

}  // namespace bench
}  // namespace collision2d
