// Timing helpers shared by the benchmarks: clocks and medians, and the
// allocator setting that keeps repeated builds of a world comparable.
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
/// As time_frames, but each frame starts at the next tick of a clock of
/// `period_ms`, the way a ROS timer steps a world: only the steps are timed,
/// not the waits between them (a step longer than the period starts the
/// next at once). Threads that sleep between frames are timed waking up.
FrameTime time_paced_frames(Engine& engine, int frames, double period_ms);

/// Fixes the C library's thresholds for returning memory to the system, for
/// the whole process. By default they move with what the process has freed
/// so far, so a run that builds and frees a world per repetition either
/// reuses its pages or maps and faults them in again, by the history of the
/// process rather than by the engine's work (docs/performance.md). Call it
/// before the first engine is built. Does nothing on other C libraries.
void fix_allocator_thresholds();

}  // namespace bench
}  // namespace collision2d
