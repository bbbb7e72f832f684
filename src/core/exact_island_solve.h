// Internal to the core: solving one coupled island's LCP by pivoting and
// judging the answer from the velocities it produces. Shared by solve_exact
// (exact_solver.cpp) and the World's exact mode (world_exact.cpp).
#pragma once

#include <vector>

#include "collision2d/lcp.h"
#include "contact_rows.h"
#include "exact_island_lcp.h"

namespace collision2d
{
namespace detail
{
/// Lemke on M, q, and once more with conservative tolerances if that fails;
/// `pivots` counts both runs.
LcpResult pivot_with_retry(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, int& pivots);

/// Solves the island's LCP (with one conservative retry) and stores the
/// impulses in its rows (each contact's cone from row.mu). Returns false when
/// pivoting failed or the island has more than kMaxExactUnknowns unknowns;
/// sets `pivots` to the pivots done.
bool solve_island(ContactPoints& rows, IslandRange island, const std::vector<BodyVelocity>& state,
                   IslandLcp& lcp, int& pivots);

/// Largest contact speed (normal or tangential, or target) in the island at `state`.
double contact_speed_scale(const ContactPoints& rows, IslandRange island,
                           const std::vector<BodyVelocity>& state);

/// Largest speed change an impulse of the island causes on its own contact.
double impulse_speed_scale(const ContactPoints& rows, IslandRange island);

/// Largest row_residual over the island (each row against its own mu).
double island_residual(const ContactPoints& rows, IslandRange island,
                        const std::vector<BodyVelocity>& state);

}  // namespace detail
}  // namespace collision2d
