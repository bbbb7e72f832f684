#include "collision2d/contact_solver.h"
#include "collision2d/exact_solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "contact_rows.h"
#include "pgs_solver.h"

namespace collision2d
{
namespace
{
void require(bool in_range, const char* name, double value, const char* range)
{
  // Written as a positive check so NaN (which fails every comparison) is rejected.
  if (!in_range)
    throw std::invalid_argument(std::string("ContactSolver: ") + name + " = " + std::to_string(value) +
                                " is not in " + range);
}

}  // namespace

ContactSolver::ContactSolver(double e, double mu, int iterations, double tol, double bias_factor, double slop)
  : e_(e), mu_(mu), iterations_(iterations), tol_(tol), bias_factor_(bias_factor), slop_(slop)
{
  require(e >= 0.0 && e <= 1.0, "e (restitution)", e, "[0, 1]");
  require(mu >= 0.0 && std::isfinite(mu), "mu (friction)", mu, "[0, inf)");
  require(iterations >= 1, "iterations", iterations, "[1, inf)");
  require(tol > 0.0 && std::isfinite(tol), "tol", tol, "(0, inf)");
  require(bias_factor >= 0.0 && bias_factor <= 1.0, "bias_factor", bias_factor, "[0, 1]");
  require(slop >= 0.0 && std::isfinite(slop), "slop", slop, "[0, inf)");
}

SolveReport ContactSolver::solve(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                                 std::vector<ContactImpulse>* impulses) const
{
  detail::validate_bodies(bodies);
  if (mode_ == SolverMode::Exact)
  {
    // solve_exact leaves every body untouched when any island fails to pivot,
    // so the iterative solve below starts from the same input.
    SolveReport exact = solve_exact(bodies, contacts, e_, mu_, tol_, impulses);
    if (!exact.exact_fallback)
      return exact;
    SolveReport fallback = solve_iterative(bodies, contacts, impulses);
    fallback.exact_fallback = true;
    return fallback;
  }
  return solve_iterative(bodies, contacts, impulses);
}

SolveReport ContactSolver::solve_iterative(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                                           std::vector<ContactImpulse>* impulses) const
{
  SolveReport report;
  report.contact_count = contacts.size();
  report.kinetic_energy_before = detail::total_kinetic_energy(bodies);

  // All working storage is sized here, once per call; the sweeps allocate nothing.
  detail::ContactProblem problem;
  detail::prepare_problem(bodies, contacts, e_, mu_, problem);
  std::vector<detail::BodyVelocity>& state = problem.state;
  detail::ContactPoints& rows = problem.rows;
  report.island_count = problem.islands.size();

  for (const detail::IslandRange& island : problem.islands)
  {
    const detail::IslandResult result = detail::solve_island_pgs(rows, island, state, mu_, iterations_, tol_);
    report.iterations = std::max(report.iterations, result.sweeps);
    report.max_residual = std::max(report.max_residual, result.residual);
    report.converged = report.converged && result.converged;
  }
  for (const detail::ContactPoint& row : rows)
    report.total_normal_impulse += row.lambda_n;

  detail::store_velocities(state, bodies);
  if (impulses != nullptr)
    detail::store_impulses(rows, contacts.size(), *impulses);
  report.kinetic_energy_after = detail::total_kinetic_energy(bodies);
  return report;
}

SolveReport ContactSolver::resolve(std::vector<Body>& bodies) const
{
  return detail::all_or_nothing(bodies, [&] { return resolve_here(bodies, 0.0, nullptr); });
}

SolveReport ContactSolver::resolve(std::vector<Body>& bodies, Resolution& out) const
{
  return detail::all_or_nothing(bodies, [&] { return resolve_here(bodies, 0.0, &out); });
}

SolveReport ContactSolver::resolve_here(std::vector<Body>& bodies, double touch_tolerance, Resolution* out) const
{
  std::vector<Contact> contacts = detect_contacts(bodies, touch_tolerance);
  const SolveReport report = solve(bodies, contacts, out != nullptr ? &out->impulses : nullptr);
  if (out != nullptr)
  {
    out->after_solve = bodies;
  }
  correct_positions(bodies, contacts);
  if (out != nullptr)
  {
    out->contacts = std::move(contacts);
    out->report = report;
  }
  return report;
}

}  // namespace collision2d
