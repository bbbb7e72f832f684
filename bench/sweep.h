// The grids of the sweep benchmark: which knob values each scene runs with,
// in ours and in the peers.
#pragma once

#include <string>
#include <vector>

#include "bench_scenes.h"
#include "engine.h"
#include "solver_metrics.h"

namespace collision2d
{
namespace bench
{
struct RunSpec
{
  std::string knob;    ///< which knob this run varies ("baseline", "iterations", ...)
  std::string value;   ///< its value, as text
  EngineConfig config;
  double seconds = 0.0;  ///< accuracy run length; 0 takes the scene's own
};

/// The World's two step pipelines (WorldSettings::soft_step). Every run of
/// ours sets soft_step explicitly, so the sweep does not depend on which one
/// is the default.
enum class Pipeline
{
  Soft,  ///< soft_step on: collide once per frame, soft contacts, relax, restitution
  Fx2d   ///< soft_step off: detect, correct positions, solve velocities every substep
};

/// Ours, once per pipeline: one knob at a time around the scene's settings
/// (the exact solver mode in both), plus a substeps x iterations grid on the
/// headline scenes. Knobs of one
/// pipeline only (Fx2D: position passes, position block, the warm-start
/// variants, exact position correction; soft step: contact stiffness,
/// damping, push speed, speculative margin) are swept in that pipeline only.
/// `quick` thins every grid.
std::vector<RunSpec> world_runs(const BenchScene& scene, bool quick);
/// Box2D 2.4.1, Chipmunk and Box2D v3 (those built in): their defaults, and
/// matched to a few of our (substeps, iterations) points (Box2D v3: to their
/// substeps only); ours at the same points in both pipelines.
std::vector<RunSpec> peer_runs(const BenchScene& scene, bool quick);
/// Long runs of the stacks (pyramid, column) for the stand-for-60-s target,
/// in both pipelines.
std::vector<RunSpec> stand_runs(const BenchScene& scene, bool quick);
/// Mode x iterations x tolerance x mass ratio for the ContactSolver.
std::vector<SolverSweepPoint> solver_points(bool quick);

/// `settings` with soft_step set for `pipeline`.
WorldSettings with_pipeline(WorldSettings settings, Pipeline pipeline);
/// Solve and relax passes of the stiff soft step (with_stiff_contacts).
constexpr int kStiffPasses = 2;
/// The soft step for tall stacks: 6 substeps and 90 Hz contacts, the
/// stiffness cap at 6 substeps of a 60 Hz frame (a quarter of the substep
/// rate), damping ratio 15, held by `passes` solve and relax passes a
/// substep (soft_iterations).
WorldSettings with_stiff_contacts(WorldSettings settings, int passes = kStiffPasses);
/// The pipeline these settings step with: "soft" or "fx2d" (the exact solver
/// mode works in both).
std::string pipeline_name(const WorldSettings& settings);
/// pipeline_name of a default-constructed WorldSettings in this build.
std::string default_pipeline_name();

std::string toggle_name(Toggle toggle);
std::string mode_name(SolverMode mode);
/// The world's solver mode as text.
std::string world_mode_name(const WorldSettings& settings);

}  // namespace bench
}  // namespace collision2d
