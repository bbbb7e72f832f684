// Wall-clock helpers shared by the benchmarks.
#pragma once

#include <vector>

#include "engine.h"

namespace collision2d
{
namespace bench
{
/// Frames in `seconds` of frames of `dt` (at least one).
int frames_for(double seconds, double dt);
/// Median of the values (the mean of the middle two for an even count).
double median(std::vector<double> values);
/// Mean time of one frame over a run of frames (ms).
struct FrameTime
{
  double wall_ms = 0.0;  ///< steady_clock
  /// This thread's CPU time: what the work costs when other processes share
  /// the cores (wall time then also counts time spent preempted).
  double cpu_ms = 0.0;
};

FrameTime time_frames(Engine& engine, int frames);

}  // namespace bench
}  // namespace collision2d
