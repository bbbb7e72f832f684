// Internal to the core: one coupled island of contact rows written as a
// linear complementarity problem (for the exact solver mode).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "island_jacobian.h"
#include "contact_rows.h"

namespace collision2d
{
namespace detail
{
/// Work arrays for one island's LCP; kept across islands so a solve call
/// allocates only when a bigger island arrives.
///
/// Unknowns per contact c, in this order: lambda_n, lambda_t+, lambda_t-
/// (>= 0, tangential impulse lambda_t+ - lambda_t-) and the sliding-speed
/// slack beta (friction only). Complementary rows: vn - target, beta + vt,
/// beta - vt, mu lambda_n - lambda_t+ - lambda_t-. Every unknown and row is
/// scaled symmetrically by the contact's normal effective mass k_n (impulses
/// times sqrt(k_n), speeds over sqrt(k_n)): the scaled Delassus block stays
/// positive semidefinite with unit diagonal, the friction coupling stays
/// skew, and extreme mass ratios do not spread the entries over many decades.
/// The jacobian has rows n, t per contact.
struct IslandLcp : IslandJacobian
{
  Eigen::MatrixXd M;
  Eigen::VectorXd q;
};

/// Unknowns per contact: lambda_n alone without friction; with it also
/// lambda_t+, lambda_t- and beta.
constexpr int kFrictionlessUnknowns = 1;
constexpr int kFrictionalUnknowns = 4;
inline int unknowns_per_contact(double mu) { return mu > 0.0 ? kFrictionalUnknowns : kFrictionlessUnknowns; }

/// True when any row of the island has a friction cone (row.mu > 0): the
/// island is then assembled with friction unknowns for every contact, and a
/// row with mu = 0 gets a cone that admits no tangential impulse.
bool island_has_friction(const ContactPoints& rows, IslandRange island);

/// Unknowns of the island's LCP.
std::size_t island_unknowns(const ContactPoints& rows, IslandRange island);

/// Fills lcp.M and lcp.q for rows [island.begin, island.end) at the
/// velocities in `state` (the pre-solve ones: targets are already fixed in
/// the rows). Each contact's cone uses its row.mu.
void assemble_island_lcp(const ContactPoints& rows, IslandRange island,
                          const std::vector<BodyVelocity>& state, IslandLcp& lcp);

/// Writes the impulses of solution z into the rows' lambda_n, lambda_t and
/// sliding. A sliding contact (beta > 0) is put exactly on its cone,
/// |lambda_t| = mu lambda_n: the LCP says so, and the solve's round-off must
/// not move it strictly inside, where the contact would count as sticking.
void store_island_impulses(const Eigen::VectorXd& z, IslandRange island, ContactPoints& rows);

}  // namespace detail
}  // namespace collision2d
