// Internal to the core: an island's frictional LCP with one friction row per
// body pair instead of one per contact point (the World's exact mode).
//
// The two points of a manifold lie on one face and share its tangent; two
// friction rows there are one constraint twice. Their impulses may grow
// equal and opposite without changing any velocity, and at a 1e6 mass ratio
// that null space leaves pivoting with a singular basis and an answer far
// from the contract (on the heavy-on-light scene). One friction row at the pair's midpoint, against the cone of the
// pair's summed normal impulse, removes it: the same model as the World's
// iterative pair friction (world_solve.cpp, solve_friction_pair).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "island_jacobian.h"
#include "contact_rows.h"
#include "exact_island_lcp.h"

namespace collision2d
{
namespace detail
{
/// A friction group: the rows [first, first + count) of one body pair (count
/// 1 or 2, adjacent after partition_islands), sharing one friction row at
/// the midpoint of their contact points, with the first row's mu.
struct FrictionGroup
{
  std::size_t first = 0;
  std::size_t count = 1;
  Vec2 r_a;  ///< midpoint lever arms
  Vec2 r_b;
};

/// Work arrays of one island's grouped LCP.
///
/// Unknowns: every point's lambda_n, then per group lambda_t+, lambda_t- and
/// the sliding-speed slack beta. Rows complementary to them: vn - target;
/// beta + vt and beta - vt at the group's midpoint; mu sum(lambda_n) -
/// lambda_t+ - lambda_t-. Impulses are scaled by the square root of their
/// row's inverse effective mass and beta by its inverse (as in IslandLcp),
/// so the Delassus part has unit diagonal whatever the masses.
/// The jacobian has the point normal rows, then the group tangent rows.
struct GroupedLcp : IslandJacobian
{
  std::vector<FrictionGroup> groups;
  Eigen::VectorXd scale;  ///< per unknown: impulse = scale * z (beta: speed = scale * z)
  Eigen::MatrixXd M;
  Eigen::VectorXd q;
};

/// Unknowns of the island's grouped LCP: one per point, three per body pair.
std::size_t grouped_unknowns(const ContactPoints& rows, IslandRange island);

/// Fills groups, M and q for rows [island.begin, island.end) at the
/// pre-solve velocities in `state`.
void assemble_grouped_lcp(const ContactPoints& rows, IslandRange island,
                          const std::vector<BodyVelocity>& state, GroupedLcp& lcp);

/// Writes solution z into the rows: lambda_n per point, the group's
/// tangential impulse split in proportion to the normal impulses (each point
/// inside its share of the cone), sliding when the group slides.
void store_grouped_impulses(const Eigen::VectorXd& z, const GroupedLcp& lcp, IslandRange island,
                            ContactPoints& rows);

/// Residual (m/s) of the solved island at `state` (the velocities after the
/// impulses): per point the normal part of row_residual, per group its
/// friction part at the midpoint against the group's summed impulses.
double grouped_residual(const ContactPoints& rows, const GroupedLcp& lcp,
                        const std::vector<BodyVelocity>& state);

}  // namespace detail
}  // namespace collision2d
