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

/// Ours: one knob at a time around the scene's settings, plus a substeps x
/// iterations grid on the headline scenes. `quick` thins every grid.
std::vector<RunSpec> world_runs(const BenchScene& scene, bool quick);
/// Box2D 2.4.1, Chipmunk and Box2D v3 (those built in): their defaults, and
/// matched to a few of our (substeps, iterations) points (Box2D v3: to their
/// substeps only); ours at the same points is in world_runs.
std::vector<RunSpec> peer_runs(const BenchScene& scene, bool quick);
/// Long runs of the stacks (pyramid, column) for the stand-for-60-s target.
std::vector<RunSpec> stand_runs(const BenchScene& scene, bool quick);
/// Mode x iterations x tolerance x mass ratio for the ContactSolver.
std::vector<SolverSweepPoint> solver_points(bool quick);

/// Whether WorldSettings has a solver mode in this build (it is swept if so).
bool world_has_solver_mode();

std::string toggle_name(Toggle toggle);
std::string mode_name(SolverMode mode);
/// The world's solver mode as text ("iterative" when the world has none).
std::string world_mode_name(const WorldSettings& settings);

}  // namespace bench
}  // namespace collision2d
