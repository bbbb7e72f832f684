// The instantaneous ContactSolver on random contact islands (random_scenes.h):
// time per solve and the residuals of its contract, recomputed from the
// velocities and impulses it returns.
#pragma once

#include <cstddef>
#include <cstdint>

#include "collision2d/contact_solver.h"

namespace collision2d
{
namespace bench
{
struct SolverSweepPoint
{
  SolverMode mode = SolverMode::Iterative;
  int iterations = 64;
  double tolerance = 1e-12;
  double max_mass_ratio = 100.0;  ///< of the random scenes
};

struct SolverMetrics
{
  std::size_t scenes = 0;
  std::size_t contacts = 0;
  double us_per_solve = 0.0;           ///< median over the scenes (microseconds)
  /// Largest shortfall below the fixed Newton target, max(0, target - v_n) (m/s).
  double max_target_residual = 0.0;
  /// Largest min(|v_n - target|, j_n w_n): the natural residual of the
  /// normal complementarity, in speed units (w_n: effective inverse mass, m/s).
  double max_complementarity = 0.0;
  double mean_complementarity = 0.0;
  /// Largest Coulomb bound excess, max(0, |j_t| - mu j_n) w_t (m/s).
  double max_coulomb_excess = 0.0;
  double converged_fraction = 0.0;     ///< scenes whose report says converged
  std::size_t exact_fallbacks = 0;     ///< scenes whose exact solve fell back
};

/// Solves `scenes` random scenes drawn from `seed` (the same draws for every point).
SolverMetrics measure_solver(const SolverSweepPoint& point, std::size_t scenes, std::uint64_t seed);

}  // namespace bench
}  // namespace collision2d
