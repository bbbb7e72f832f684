// Exact contact solve (SolverMode::Exact): every coupled island of contacts
// is one linear complementarity problem solved by pivoting (lcp.h), so the
// fixed point that the iterative solver approaches is found directly.
#pragma once

#include <cstddef>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/contact_solver.h"

namespace collision2d
{
/// Islands with more unknowns than this (4 per contact with friction, 1
/// without) are not attempted: the dense tableau takes about 40 n^2 bytes
/// and O(n^2) per pivot, so beyond this the iterative solver is the tool.
constexpr std::size_t kMaxExactUnknowns = 1200;

/// A solved island whose residual, recomputed from the final velocities,
/// exceeds this fraction of its velocity scale is treated as a pivoting
/// failure (a well-posed island lands near 1e-15).
constexpr double kTrustedResidual = 1e-6;

/// Velocity solve with the same contract as ContactSolver::solve: Newton targets e * (approach speed) fixed from the velocities
/// before the solve (0 for separating or resting contacts), normal impulses
/// that only push, complementarity against those targets, and Coulomb
/// friction, which in 2D is exact: per contact the cone is two half-planes,
/// modelled with lambda_t+ >= 0, lambda_t- >= 0 and a sliding-speed slack
/// beta >= 0 (Stewart-Trinkle / Anitescu-Potra form). mu = 0 keeps only the
/// normal rows. Impulses act at the contact points, equal and opposite.
///
/// Islands are the connected components of contacts over dynamic bodies
/// (bodies with inverse mass 0 do not couple); contacts between two bodies
/// with inverse mass 0 get no impulse.
///
/// Failure and fallback: if pivoting fails on any island (an infeasible
/// problem such as a body pinched between approaching walls, the pivot cap,
/// a numerically unusable basis even after a retry with conservative
/// tolerances, an island larger than kMaxExactUnknowns, or a recomputed
/// residual above kTrustedResidual), NO body is modified, `impulses` (if
/// given) is all zeros, and the report has `exact_fallback = true` and
/// `converged = false`. The caller then runs the iterative solver on the same
/// untouched input and keeps `exact_fallback = true` in its report.
///
/// Report on success: `iterations` = pivots of the island that needed the
/// most; `max_residual` (m/s) is recomputed from the final velocities and
/// impulses: per contact the worst of target violation, push-only violation,
/// normal complementarity, Coulomb cone violation, stick/slide
/// complementarity and friction direction, impulses converted to speeds by
/// the contact's effective inverse mass. `converged` is true when that
/// residual is at most tol times the island's velocity scale (the largest
/// contact speed before or after, or impulse over effective mass, so that
/// extreme mass ratios are judged against the speeds they actually produce).
///
/// e in [0, 1], mu >= 0 and tol > 0 are expected (ContactSolver validates
/// them); `impulses` is resized to contacts.size().
SolveReport solve_exact(std::vector<Body>& bodies, const std::vector<Contact>& contacts, double e, double mu,
                        double tol, std::vector<ContactImpulse>* impulses = nullptr);

}  // namespace collision2d
