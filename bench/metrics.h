// What one run of one scene in one engine measures (see docs/performance.md).
#pragma once

#include "bench_scenes.h"
#include "engine.h"
#include "timing.h"

namespace collision2d
{
namespace bench
{
struct RunOptions
{
  double timing_seconds = 0.5;  ///< simulated time of each timed repetition (s)
  int repetitions = 5;          ///< timed repetitions at least; the median is reported
  /// ... and more, until they add up to this much wall time (ms): a small
  /// scene's repetition lasts microseconds, and one interrupt would be a
  /// large share of a handful of them.
  double min_timed_ms = 50.0;
  double settle_seconds = 1.0;  ///< Resting: drift is measured from this time on (s)
  double seconds = 0.0;         ///< accuracy run length; 0 takes the scene's own (s)
};

struct RunMetrics
{
  double ms_per_step = 0.0;      ///< median wall time of one frame (ms)
  double cpu_ms_per_step = 0.0;  ///< median thread CPU time of one frame (ms)
  double max_penetration = 0.0;  ///< largest overlap any pair showed at a frame end (m)
  double drift = NAN;            ///< Resting: largest move of a dynamic body after settling (m)
  double sink = NAN;             ///< Resting: largest move while settling (m)
  double energy_error = NAN;     ///< Conservative: largest |KE - KE0| / KE0 at a frame end
  double bounce_error = NAN;     ///< Bounce: largest |measured e - e| over the disks
  double incline_error = NAN;    ///< Incline: |measured - analytic acceleration| (m/s^2)
  double tunnelled = NAN;        ///< Bullet: 1 if the bullet ended beyond the wall
  double error = NAN;            ///< the scene's main error (one of the above)
};

/// Median frame time over fresh runs: `repetitions` of them, or more until
/// they add up to `min_timed_ms`.
FrameTime time_run(const BenchScene& scene, const EngineConfig& config, const RunOptions& options);
/// time_run, then one more run for the accuracy metrics; every engine is
/// measured by the same code from its body states.
RunMetrics measure_run(const BenchScene& scene, const EngineConfig& config, const RunOptions& options);

}  // namespace bench
}  // namespace collision2d
