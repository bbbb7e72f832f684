// How a velocity solve treats a coupled cluster of contacts; shared by the
// instantaneous ContactSolver and the World's settings.
#pragma once

namespace collision2d
{
/// Iterative: projected Gauss-Seidel on accumulated impulses, cluster by
/// cluster, until the residual is below tol. Exact: each coupled cluster solved
/// as a linear complementarity problem by pivoting.
enum class SolverMode
{
  Iterative,
  Exact
};

}  // namespace collision2d
