// Internal to the core: one coupled cluster of contact rows written as a
// linear complementarity problem (for the exact solver mode).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "cluster_jacobian.h"
#include "contact_rows.h"

namespace collision2d
{
namespace detail
{
/// Work arrays for one cluster's LCP; kept across clusters so a solve call
/// allocates only when a bigger cluster arrives.
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
struct ClusterLcp : ClusterJacobian
{
  Eigen::MatrixXd M;
  Eigen::VectorXd q;
};

/// Unknowns per contact: lambda_n alone without friction; with it also
/// lambda_t+, lambda_t- and beta.
constexpr int kFrictionlessUnknowns = 1;
constexpr int kFrictionalUnknowns = 4;
inline int unknowns_per_contact(double mu) { return mu > 0.0 ? kFrictionalUnknowns : kFrictionlessUnknowns; }

/// True when any row of the cluster has a friction cone (row.mu > 0): the
/// cluster is then assembled with friction unknowns for every contact, and a
/// row with mu = 0 gets a cone that admits no tangential impulse.
bool cluster_has_friction(const std::vector<ContactPoint>& rows, ClusterRange cluster);

/// Unknowns of the cluster's LCP.
std::size_t cluster_unknowns(const std::vector<ContactPoint>& rows, ClusterRange cluster);

/// Fills lcp.M and lcp.q for rows [cluster.begin, cluster.end) at the
/// velocities in `state` (the pre-solve ones: targets are already fixed in
/// the rows). Each contact's cone uses its row.mu.
void assemble_cluster_lcp(const std::vector<ContactPoint>& rows, ClusterRange cluster,
                          const std::vector<BodyVelocity>& state, ClusterLcp& lcp);

/// Writes the impulses of solution z into the rows' lambda_n, lambda_t and
/// sliding. A sliding contact (beta > 0) is put exactly on its cone,
/// |lambda_t| = mu lambda_n: the LCP says so, and the solve's round-off must
/// not move it strictly inside, where the contact would count as sticking.
void store_cluster_impulses(const Eigen::VectorXd& z, ClusterRange cluster, std::vector<ContactPoint>& rows);

}  // namespace detail
}  // namespace collision2d
