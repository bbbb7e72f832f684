// Instantaneous contact resolution: detection, a velocity
// solve with per-contact Newton restitution and Coulomb friction iterated to a
// consistent fixed point, position correction and exact time of impact.
#pragma once

#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/solver_mode.h"

namespace collision2d
{
struct SolveReport
{
  int iterations = 0;                 ///< sweeps done (largest over coupled islands)
  double max_residual = 0.0;          ///< complementarity residual at exit (m/s)
  double total_normal_impulse = 0.0;  ///< sum of normal impulses (N s)
  bool converged = true;              ///< residual fell below tol before the cap
  // Additions beyond the four original fields.
  std::size_t contact_count = 0;
  std::size_t island_count = 0;         ///< coupled islands solved
  double kinetic_energy_before = 0.0;    ///< J
  double kinetic_energy_after = 0.0;     ///< J
  double time_of_impact = 1.0;           ///< step(): the time moved to, in [0, 1]
  bool exact_fallback = false;           ///< exact mode: pivoting failed, iterative result used
};

/// Everything one resolve() or step() computed, for callers that report more
/// than the bodies (the ROS service, the command-line tool).
struct Resolution
{
  std::vector<Contact> contacts;         ///< the contacts solved, at the poses they were detected at
  std::vector<ContactImpulse> impulses;  ///< one per contact (N s)
  std::vector<Body> after_solve;         ///< the bodies after the velocity solve, before position correction
  SolveReport report;
};

/// Every entry point rejects non-finite bodies or contacts with
/// std::invalid_argument naming the body or contact. Finite input far beyond
/// the README's supported ranges can overflow mid-solve: the call then throws
/// std::overflow_error naming the body and leaves the bodies as they came in
/// (solve, correct_positions, resolve and step are each all-or-nothing).
class ContactSolver
{
public:
  /// e in [0,1], mu >= 0, iterations >= 1, tol > 0, bias_factor in [0,1],
  /// slop >= 0; anything else (or non-finite) throws std::invalid_argument.
  ContactSolver(double e, double mu, int iterations = 64, double tol = 1e-12, double bias_factor = 0.2,
                double slop = 1e-3);

  /// All contacts at the current poses (broad phase, then narrow phase),
  /// ordered by (a, b). Throws std::runtime_error for an undefined normal.
  static std::vector<Contact> detect_contacts(const std::vector<Body>& bodies);
  /// As above, but pairs whose gap is at most touch_tolerance * (radius_a +
  /// radius_b) also count, with zero penetration (step() uses this at the time
  /// of impact, where the impacting pair touches exactly).
  static std::vector<Contact> detect_contacts(const std::vector<Body>& bodies, double touch_tolerance);

  /// Velocity solve. Writes the applied impulses per contact to `impulses`
  /// when given. In SolverMode::Exact each coupled island is solved by
  /// pivoting; if pivoting fails the iterative solve is used and the report's
  /// exact_fallback is set.
  SolveReport solve(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                    std::vector<ContactImpulse>* impulses = nullptr) const;
  /// Positions only: penetration beyond slop reduced by bias_factor, split by
  /// inverse mass, once per pair.
  void correct_positions(std::vector<Body>& bodies, const std::vector<Contact>& contacts) const;
  /// detect, solve, correct.
  SolveReport resolve(std::vector<Body>& bodies) const;
  /// The same, also handing back the contacts, their impulses and the bodies
  /// between solve and correction in `out`.
  SolveReport resolve(std::vector<Body>& bodies, Resolution& out) const;
  /// Earliest t in [0, 1] at which any pair first touches when every body
  /// translates by its velocity over one unit step.
  static double time_of_impact(const std::vector<Body>& bodies);
  /// Move every body to the time of impact, then resolve contacts there
  /// (pairs within a tiny relative tolerance of touching count as contacts).
  SolveReport step(std::vector<Body>& bodies) const;
  /// The same, with everything computed in `out` (contacts at the time of impact).
  SolveReport step(std::vector<Body>& bodies, Resolution& out) const;

  double restitution() const { return e_; }
  double friction() const { return mu_; }
  int max_iterations() const { return iterations_; }
  double tolerance() const { return tol_; }
  double bias_factor() const { return bias_factor_; }
  double slop() const { return slop_; }
  SolverMode mode() const { return mode_; }
  void set_mode(SolverMode mode) { mode_ = mode; }

private:
  /// Detect, solve and correct at the current poses; fills `out` when given.
  SolveReport resolve_here(std::vector<Body>& bodies, double touch_tolerance, Resolution* out) const;
  SolveReport solve_iterative(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                              std::vector<ContactImpulse>* impulses) const;

  double e_;
  double mu_;
  int iterations_;
  double tol_;
  double bias_factor_;
  double slop_;
  SolverMode mode_ = SolverMode::Iterative;
};

}  // namespace collision2d
