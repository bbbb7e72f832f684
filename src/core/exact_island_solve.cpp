#include "exact_island_solve.h"

#include <algorithm>
#include <cmath>

#include "collision2d/exact_solver.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A second pivoting run after a failure, with tolerances that treat more
/// near-zero tableau entries as zero: on islands with many redundant
/// contacts round-off can steer the first run into a false ray.
LemkeSettings conservative_settings()
{
  LemkeSettings settings;
  settings.pivot_tolerance = 1e-9;
  settings.tie_tolerance = 1e-9;
  return settings;
}
}  // namespace

LcpResult pivot_with_retry(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, int& pivots)
{
  LcpResult result = LemkeSolver().solve(M, q);
  pivots = result.pivots;
  if (!result.solved())
  {
    result = LemkeSolver(conservative_settings()).solve(M, q);
    pivots += result.pivots;
  }
  return result;
}

bool solve_island(ContactPoints& rows, IslandRange island, const std::vector<BodyVelocity>& state,
                   IslandLcp& lcp, int& pivots)
{
  pivots = 0;
  if (island_unknowns(rows, island) > kMaxExactUnknowns)
    return false;
  assemble_island_lcp(rows, island, state, lcp);
  const LcpResult result = pivot_with_retry(lcp.M, lcp.q, pivots);
  if (!result.solved())
    return false;
  store_island_impulses(result.z, island, rows);
  return true;
}

double contact_speed_scale(const ContactPoints& rows, IslandRange island,
                           const std::vector<BodyVelocity>& state)
{
  double scale = 0.0;
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    const Vec2 dv = relative_velocity(rows[r], state);
    scale = std::max({scale, std::abs(dot(dv, rows[r].normal)), std::abs(dot(dv, rows[r].tangent())),
                      rows[r].target});
  }
  return scale;
}

double impulse_speed_scale(const ContactPoints& rows, IslandRange island)
{
  double scale = 0.0;
  for (std::size_t r = island.begin; r < island.end; ++r)
    scale = std::max({scale, rows[r].lambda_n * rows[r].k_n, std::abs(rows[r].lambda_t) * rows[r].k_t});
  return scale;
}

double island_residual(const ContactPoints& rows, IslandRange island,
                        const std::vector<BodyVelocity>& state)
{
  double residual = 0.0;
  for (std::size_t r = island.begin; r < island.end; ++r)
    residual = std::max(residual, point_residual(rows[r], state, cone(rows[r])));
  return residual;
}

}  // namespace detail
}  // namespace collision2d
