#include "pgs_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collision2d
{
namespace detail
{
namespace
{
bool same_pair(const ContactPoint& l, const ContactPoint& r) { return l.a == r.a && l.b == r.b; }

/// One pass over the island; returns whether any impulse changed.
bool sweep(ContactPoints& rows, IslandRange island, std::vector<BodyVelocity>& state, double mu)
{
  bool changed = false;
  for (std::size_t i = island.begin; i < island.end;)
  {
    // Rows of one pair are adjacent; exactly two of them form a manifold.
    const bool manifold = i + 1 < island.end && same_pair(rows[i], rows[i + 1]) &&
                          (i + 2 == island.end || !same_pair(rows[i], rows[i + 2]));
    const std::size_t count = manifold ? 2 : 1;
    if (!manifold || !solve_normal_block(rows[i], rows[i + 1], state, changed))
      for (std::size_t k = i; k < i + count; ++k)
        changed = solve_normal(rows[k], state) || changed;
    if (mu > 0.0)
      for (std::size_t k = i; k < i + count; ++k)
        changed = solve_friction(rows[k], state) || changed;
    i += count;
  }
  return changed;
}

double island_residual(const ContactPoints& rows, IslandRange island,
                        const std::vector<BodyVelocity>& state, double mu)
{
  double residual = 0.0;
  for (std::size_t i = island.begin; i < island.end; ++i)
    residual = std::max(residual, point_residual(rows[i], state, mu));
  return residual;
}
}  // namespace

IslandResult solve_island_pgs(ContactPoints& rows, IslandRange island,
                                std::vector<BodyVelocity>& state, double mu, int max_sweeps, double tol)
{
  IslandResult result;
  result.residual = std::numeric_limits<double>::infinity();
  while (result.sweeps < max_sweeps)
  {
    const bool changed = sweep(rows, island, state, mu);
    ++result.sweeps;
    result.residual = island_residual(rows, island, state, mu);
    if (result.residual < tol)
    {
      result.converged = true;
      break;
    }
    if (!changed)
      break;  // a fixed point of the sweep in floating point: more sweeps repeat it
  }
  return result;
}

}  // namespace detail
}  // namespace collision2d
