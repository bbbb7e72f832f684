// Internal to the core: projected Gauss-Seidel on accumulated impulses for one
// coupled island of contact rows.
#pragma once

#include <vector>

#include "contact_rows.h"

namespace collision2d
{
namespace detail
{
struct IslandResult
{
  int sweeps = 0;
  double residual = 0.0;  ///< after the last sweep (m/s)
  bool converged = false;
};

/// Sweeps the island's rows until its residual is below `tol` or `max_sweeps`
/// sweeps are done (or a sweep changes no impulse, when more sweeps cannot
/// help). Normal impulses stay >= 0 and tangential ones inside mu times the
/// normal one. Allocates nothing.
IslandResult solve_island_pgs(ContactPoints& rows, IslandRange island,
                                std::vector<BodyVelocity>& state, double mu, int max_sweeps, double tol);

}  // namespace detail
}  // namespace collision2d
