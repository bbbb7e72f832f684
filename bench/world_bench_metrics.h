// What collision2d_world_bench measures on one scene (see world_bench.cpp).
#pragma once

#include <string>

#include "collision2d/scene.h"

namespace collision2d
{
namespace bench
{
struct BenchOptions
{
  double seconds = 2.0;         ///< simulated time per timed repetition (s)
  int repetitions = 5;          ///< timed repetitions per mode; the median is reported
  double settle_seconds = 10.0; ///< simulated time of the accuracy run (s)
};

struct SceneMetrics
{
  std::string name;
  std::size_t bodies = 0;
  double ms_per_step_auto = 0.0;  ///< median wall time of one frame, effects on Auto (ms)
  double ms_per_step_on = 0.0;    ///< the same with every physics effect forced On (ms)
  /// Bodies start at rest on each other under gravity: drift is meaningful.
  bool resting = false;
  double drift = 0.0;             ///< largest displacement of a dynamic body after settle_seconds (m)
  double max_penetration = 0.0;   ///< largest depth left after correction in any frame (m)
  /// No gravity, e = 1 and mu = 0 everywhere: kinetic energy should be kept.
  bool conservative = false;
  double energy_error = 0.0;      ///< |KE_end - KE_0| / KE_0 after settle_seconds
  ActiveEffects auto_effects;     ///< effects Auto modelled during the accuracy run
};

/// Times the scene under Auto and under all-On (interleaved repetitions, so a
/// busy machine slows both alike), then runs it for settle_seconds to measure
/// drift, penetration and energy.
SceneMetrics measure_scene(const Scene& scene, const BenchOptions& options);

/// Every effect that adds physics forced On (sleeping, which removes work,
/// keeps the scene's setting).
WorldSettings all_effects_on(WorldSettings settings);

}  // namespace bench
}  // namespace collision2d
