#include "collision2d/exact_solver.h"

#include <algorithm>
#include <cmath>

#include "collision2d/lcp.h"
#include "contact_rows.h"
#include "exact_cluster_lcp.h"

namespace collision2d
{
namespace
{
/// A second pivoting run after a failure, with tolerances that treat more
/// near-zero tableau entries as zero: on clusters with many redundant
/// contacts round-off can steer the first run into a false ray.
LemkeSettings conservative_settings()
{
  LemkeSettings settings;
  settings.pivot_tolerance = 1e-9;
  settings.tie_tolerance = 1e-9;
  return settings;
}

/// Solves one cluster's LCP (with one conservative retry) and stores the
/// impulses in its rows. Returns false when pivoting failed or the cluster is
/// too large; adds the pivots done to `pivots`.
bool solve_cluster(std::vector<detail::ContactRow>& rows, detail::ClusterRange cluster,
                   const std::vector<detail::BodyVelocity>& state, double mu, detail::ClusterLcp& lcp,
                   int& pivots)
{
  const std::size_t unknowns = (cluster.end - cluster.begin) * detail::unknowns_per_contact(mu);
  if (unknowns > kMaxExactUnknowns)
    return false;
  detail::assemble_cluster_lcp(rows, cluster, state, mu, lcp);
  LcpResult result = LemkeSolver().solve(lcp.M, lcp.q);
  pivots = result.pivots;
  if (!result.solved())
  {
    result = LemkeSolver(conservative_settings()).solve(lcp.M, lcp.q);
    pivots += result.pivots;
  }
  if (!result.solved())
    return false;
  detail::store_cluster_impulses(result.z, mu, cluster, rows);
  return true;
}

double total_kinetic_energy(const std::vector<Body>& bodies)
{
  double energy = 0.0;
  for (const Body& body : bodies)
    energy += body.kinetic_energy();
  return energy;
}

/// Largest contact speed (normal or tangential) in the cluster at `state`.
double contact_speed_scale(const std::vector<detail::ContactRow>& rows, detail::ClusterRange cluster,
                           const std::vector<detail::BodyVelocity>& state)
{
  double scale = 0.0;
  for (std::size_t r = cluster.begin; r < cluster.end; ++r)
  {
    const Vec2 dv = detail::relative_velocity(rows[r], state);
    scale = std::max({scale, std::abs(dot(dv, rows[r].normal)), std::abs(dot(dv, rows[r].tangent)),
                      rows[r].target});
  }
  return scale;
}

/// Largest speed change an impulse of the cluster causes on its own contact.
double impulse_speed_scale(const std::vector<detail::ContactRow>& rows, detail::ClusterRange cluster)
{
  double scale = 0.0;
  for (std::size_t r = cluster.begin; r < cluster.end; ++r)
    scale = std::max({scale, rows[r].lambda_n * rows[r].k_n, std::abs(rows[r].lambda_t) * rows[r].k_t});
  return scale;
}

double cluster_residual(const std::vector<detail::ContactRow>& rows, detail::ClusterRange cluster,
                        const std::vector<detail::BodyVelocity>& state, double mu)
{
  double residual = 0.0;
  for (std::size_t r = cluster.begin; r < cluster.end; ++r)
    residual = std::max(residual, detail::row_residual(rows[r], state, mu));
  return residual;
}

void store_velocities(const std::vector<detail::BodyVelocity>& state, std::vector<Body>& bodies)
{
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    if (state[i].inv_mass <= 0.0)
      continue;  // static and kinematic bodies keep their velocities
    bodies[i].set_velocity(state[i].v);
    bodies[i].set_omega(state[i].omega);
  }
}

/// The documented failure signal: nothing applied, caller falls back.
SolveReport failed_report(SolveReport report, std::size_t contact_count, std::vector<ContactImpulse>* impulses)
{
  report.exact_fallback = true;
  report.converged = false;
  report.total_normal_impulse = 0.0;
  report.max_residual = 0.0;
  report.kinetic_energy_after = report.kinetic_energy_before;
  if (impulses != nullptr)
    impulses->assign(contact_count, ContactImpulse{});
  return report;
}
}  // namespace

SolveReport solve_exact(std::vector<Body>& bodies, const std::vector<Contact>& contacts, double e, double mu,
                        double tol, std::vector<ContactImpulse>* impulses)
{
  SolveReport report;
  report.contact_count = contacts.size();
  report.kinetic_energy_before = total_kinetic_energy(bodies);

  std::vector<detail::BodyVelocity> state;
  std::vector<detail::ContactRow> rows;
  std::vector<detail::ClusterRange> clusters;
  std::vector<std::size_t> parent;
  detail::load_velocities(bodies, state);
  detail::build_rows(bodies, state, contacts, e, rows);
  detail::partition_clusters(state, rows, clusters, parent);
  report.cluster_count = clusters.size();

  // Every cluster is solved before any impulse is applied, so a failure
  // leaves the bodies exactly as they came in.
  detail::ClusterLcp lcp;
  lcp.local_body.assign(bodies.size(), -1);
  std::vector<double> speed_before(clusters.size());
  for (std::size_t c = 0; c < clusters.size(); ++c)
  {
    int pivots = 0;
    const bool solved = solve_cluster(rows, clusters[c], state, mu, lcp, pivots);
    report.iterations = std::max(report.iterations, pivots);
    if (!solved)
      return failed_report(report, contacts.size(), impulses);
    speed_before[c] = contact_speed_scale(rows, clusters[c], state);
  }

  // Applied to the working copy only: the bodies change once all is checked.
  for (const detail::ContactRow& row : rows)
  {
    detail::apply_impulse(row, row.lambda_n * row.normal + row.lambda_t * row.tangent, state);
    report.total_normal_impulse += row.lambda_n;
  }
  for (std::size_t c = 0; c < clusters.size(); ++c)
  {
    // Judged against the speeds the cluster actually involves: at a 1e6 mass
    // ratio the light body's velocity is a difference of impulse effects a
    // million times larger, and double precision is relative to those.
    const double scale = std::max({speed_before[c], contact_speed_scale(rows, clusters[c], state),
                                   impulse_speed_scale(rows, clusters[c])});
    const double residual = cluster_residual(rows, clusters[c], state, mu);
    if (!(residual <= kTrustedResidual * scale))
      return failed_report(report, contacts.size(), impulses);
    report.max_residual = std::max(report.max_residual, residual);
    report.converged = report.converged && residual <= tol * scale;
  }

  store_velocities(state, bodies);
  if (impulses != nullptr)
  {
    impulses->assign(contacts.size(), ContactImpulse{});
    for (const detail::ContactRow& row : rows)
      (*impulses)[row.contact] = {row.lambda_n, row.lambda_t};
  }
  report.kinetic_energy_after = total_kinetic_energy(bodies);
  return report;
}

}  // namespace collision2d
