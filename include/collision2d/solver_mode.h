// How a velocity solve treats a coupled island of contacts; shared by the
// instantaneous ContactSolver and the World's settings.
#pragma once

namespace collision2d
{
/// Iterative: projected Gauss-Seidel on accumulated impulses, island by
/// island, until the residual is below tol. Exact: each coupled island solved
/// as a linear complementarity problem by pivoting.
enum class SolverMode
{
  Iterative,
  Exact
};

}  // namespace collision2d
