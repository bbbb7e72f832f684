// Internal to the core: the velocity Jacobian of one coupled island and its
// Delassus matrix, shared by the two LCP builders of the exact mode
// (exact_island_lcp: a row pair per contact; grouped_friction_lcp: a normal
// row per point and one tangent row per body pair).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact_rows.h"

namespace collision2d
{
namespace detail
{
/// Work arrays kept across islands, so a solve allocates only when a bigger
/// island arrives.
struct IslandJacobian
{
  Eigen::MatrixXd jacobian;           ///< one row per impulse direction; 3 columns (vx, vy, w) per dynamic body
  Eigen::VectorXd body_inverse_mass;  ///< diagonal of W matching the jacobian's columns
  Eigen::MatrixXd delassus;           ///< J W J^T: velocity change per unit impulse
  std::vector<int> local_body;        ///< body index -> first jacobian column, -1 outside the island
};

/// Numbers the island's dynamic bodies (static and kinematic ones get no
/// columns: their velocities never change), fills W and sets the jacobian to
/// zero with `directions` rows.
void begin_jacobian(const ContactPoints& rows, IslandRange island, const std::vector<BodyVelocity>& state,
                    Eigen::Index directions, IslandJacobian& j);

/// Writes sign * (dir, r x dir) into row `row` at the body's columns; nothing
/// for a body without columns.
void add_jacobian_entry(IslandJacobian& j, Eigen::Index row, std::size_t body, double sign, Vec2 dir, Vec2 r);

/// Computes the Delassus matrix and forgets the numbering, leaving
/// local_body all -1 for the next island.
void finish_jacobian(const ContactPoints& rows, IslandRange island, IslandJacobian& j);

}  // namespace detail
}  // namespace collision2d
