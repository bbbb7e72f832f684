#include "collision2d/exact_solver.h"

#include <algorithm>
#include <cmath>

#include "contact_rows.h"
#include "exact_island_lcp.h"
#include "exact_island_solve.h"

namespace collision2d
{
namespace
{
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
  report.kinetic_energy_before = detail::total_kinetic_energy(bodies);

  detail::ContactProblem problem;
  detail::prepare_problem(bodies, contacts, e, mu, problem);
  std::vector<detail::BodyVelocity>& state = problem.state;
  detail::ContactPoints& rows = problem.rows;
  const std::vector<detail::IslandRange>& islands = problem.islands;
  report.island_count = islands.size();

  // Every island is solved before any impulse is applied, so a failure
  // leaves the bodies exactly as they came in.
  detail::IslandLcp lcp;
  lcp.local_body.assign(bodies.size(), -1);
  std::vector<double> speed_before(islands.size());
  for (std::size_t c = 0; c < islands.size(); ++c)
  {
    int pivots = 0;
    const bool solved = detail::solve_island(rows, islands[c], state, lcp, pivots);
    report.iterations = std::max(report.iterations, pivots);
    if (!solved)
      return failed_report(report, contacts.size(), impulses);
    speed_before[c] = detail::contact_speed_scale(rows, islands[c], state);
  }

  // Applied to the working copy only: the bodies change once all is checked.
  for (const detail::ContactPoint& row : rows)
  {
    detail::apply_impulse(row, row.lambda_n * row.normal + row.lambda_t * row.tangent(), state);
    report.total_normal_impulse += row.lambda_n;
  }
  for (std::size_t c = 0; c < islands.size(); ++c)
  {
    // Judged against the speeds the island actually involves: at a 1e6 mass
    // ratio the light body's velocity is a difference of impulse effects a
    // million times larger, and double precision is relative to those.
    const double scale = std::max({speed_before[c], detail::contact_speed_scale(rows, islands[c], state),
                                   detail::impulse_speed_scale(rows, islands[c])});
    const double residual = detail::island_residual(rows, islands[c], state);
    if (!(residual <= kTrustedResidual * scale))
      return failed_report(report, contacts.size(), impulses);
    report.max_residual = std::max(report.max_residual, residual);
    report.converged = report.converged && residual <= tol * scale;
  }

  // Impulses that overflowed (a mass ratio beyond double precision in a
  // deep overlap) solved nothing: the documented fallback, bodies unchanged.
  for (const detail::BodyVelocity& body : state)
  {
    if (body.inv_mass > 0.0 && !(is_finite(body.v) && std::isfinite(body.omega)))
      return failed_report(report, contacts.size(), impulses);
  }
  detail::store_velocities(state, bodies);
  if (impulses != nullptr)
    detail::store_impulses(rows, contacts.size(), *impulses);
  report.kinetic_energy_after = detail::total_kinetic_energy(bodies);
  return report;
}

}  // namespace collision2d
