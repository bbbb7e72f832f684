#include "pgs_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collision2d
{
namespace detail
{
namespace
{
/// The two-point block solve is used only while its 2x2 matrix is well
/// conditioned (k11^2 < this * det, dimensionless); nearly coincident points
/// fall back to one row at a time.
constexpr double kMaxBlockCondition = 1000.0;

bool solve_normal(ContactRow& row, std::vector<BodyVelocity>& state)
{
  const double vn = dot(relative_velocity(row, state), row.normal);
  const double accumulated = std::max(0.0, row.lambda_n + (row.target - vn) / row.k_n);
  const double delta = accumulated - row.lambda_n;
  if (delta == 0.0)
    return false;
  row.lambda_n = accumulated;
  apply_impulse(row, delta * row.normal, state);
  return true;
}

bool solve_friction(ContactRow& row, std::vector<BodyVelocity>& state, double mu)
{
  const double vt = dot(relative_velocity(row, state), row.tangent);
  const double bound = mu * row.lambda_n;
  const double accumulated = std::clamp(row.lambda_t - vt / row.k_t, -bound, bound);
  const double delta = accumulated - row.lambda_t;
  if (delta == 0.0)
    return false;
  row.lambda_t = accumulated;
  apply_impulse(row, delta * row.tangent, state);
  return true;
}

/// Coupling of two normal rows of the same pair: velocity change of row 1 per
/// unit impulse on row 2 (1/kg).
double coupling(const ContactRow& r1, const ContactRow& r2, const std::vector<BodyVelocity>& state)
{
  const BodyVelocity& a = state[r1.a];
  const BodyVelocity& b = state[r1.b];
  return (a.inv_mass + b.inv_mass) * dot(r1.normal, r2.normal) +
         a.inv_inertia * cross(r1.r_a, r1.normal) * cross(r2.r_a, r2.normal) +
         b.inv_inertia * cross(r1.r_b, r1.normal) * cross(r2.r_b, r2.normal);
}

/// Solves the two normal rows of a two-point manifold together: the 2x2 linear
/// complementarity problem  w = K x + q, x >= 0, w >= 0, x.w = 0  (x the new
/// accumulated impulses, w the distance of each normal speed above its target)
/// by trying its four cases, exactly as the rows' own fixed point would
/// (other rows held fixed). Returns false when the matrix is ill conditioned or
/// round-off leaves no case valid, so the caller solves row by row.
bool solve_normal_block(ContactRow& r1, ContactRow& r2, std::vector<BodyVelocity>& state, bool& changed)
{
  const double k11 = r1.k_n;
  const double k22 = r2.k_n;
  const double k12 = coupling(r1, r2, state);
  const double det = k11 * k22 - k12 * k12;
  if (!(k11 * k11 < kMaxBlockCondition * det))
    return false;

  const double old1 = r1.lambda_n;
  const double old2 = r2.lambda_n;
  // q: the rows' distance above target with their current impulses removed.
  const double q1 = dot(relative_velocity(r1, state), r1.normal) - r1.target - (k11 * old1 + k12 * old2);
  const double q2 = dot(relative_velocity(r2, state), r2.normal) - r2.target - (k12 * old1 + k22 * old2);

  double x1 = (k12 * q2 - k22 * q1) / det;  // both active
  double x2 = (k12 * q1 - k11 * q2) / det;
  if (!(x1 >= 0.0 && x2 >= 0.0))
  {
    if (-q1 / k11 >= 0.0 && k12 * (-q1 / k11) + q2 >= 0.0)
    {
      x1 = -q1 / k11;  // only the first active
      x2 = 0.0;
    }
    else if (-q2 / k22 >= 0.0 && k12 * (-q2 / k22) + q1 >= 0.0)
    {
      x1 = 0.0;  // only the second active
      x2 = -q2 / k22;
    }
    else if (q1 >= 0.0 && q2 >= 0.0)
    {
      x1 = 0.0;  // both separate
      x2 = 0.0;
    }
    else
    {
      return false;
    }
  }

  const double d1 = x1 - old1;
  const double d2 = x2 - old2;
  r1.lambda_n = x1;
  r2.lambda_n = x2;
  if (d1 != 0.0)
    apply_impulse(r1, d1 * r1.normal, state);
  if (d2 != 0.0)
    apply_impulse(r2, d2 * r2.normal, state);
  changed = changed || d1 != 0.0 || d2 != 0.0;
  return true;
}

bool same_pair(const ContactRow& l, const ContactRow& r) { return l.a == r.a && l.b == r.b; }

/// One pass over the cluster; returns whether any impulse changed.
bool sweep(std::vector<ContactRow>& rows, ClusterRange cluster, std::vector<BodyVelocity>& state, double mu)
{
  bool changed = false;
  for (std::size_t i = cluster.begin; i < cluster.end;)
  {
    // Rows of one pair are adjacent; exactly two of them form a manifold.
    const bool manifold = i + 1 < cluster.end && same_pair(rows[i], rows[i + 1]) &&
                          (i + 2 == cluster.end || !same_pair(rows[i], rows[i + 2]));
    const std::size_t count = manifold ? 2 : 1;
    if (!manifold || !solve_normal_block(rows[i], rows[i + 1], state, changed))
      for (std::size_t k = i; k < i + count; ++k)
        changed = solve_normal(rows[k], state) || changed;
    if (mu > 0.0)
      for (std::size_t k = i; k < i + count; ++k)
        changed = solve_friction(rows[k], state, mu) || changed;
    i += count;
  }
  return changed;
}

double cluster_residual(const std::vector<ContactRow>& rows, ClusterRange cluster,
                        const std::vector<BodyVelocity>& state, double mu)
{
  double residual = 0.0;
  for (std::size_t i = cluster.begin; i < cluster.end; ++i)
    residual = std::max(residual, row_residual(rows[i], state, mu));
  return residual;
}
}  // namespace

ClusterResult solve_cluster_pgs(std::vector<ContactRow>& rows, ClusterRange cluster,
                                std::vector<BodyVelocity>& state, double mu, int max_sweeps, double tol)
{
  ClusterResult result;
  result.residual = std::numeric_limits<double>::infinity();
  while (result.sweeps < max_sweeps)
  {
    const bool changed = sweep(rows, cluster, state, mu);
    ++result.sweeps;
    result.residual = cluster_residual(rows, cluster, state, mu);
    if (result.residual < tol)
    {
      result.converged = true;
      break;
    }
    if (!changed)
      break;  // a fixed point of the sweep in floating point: more sweeps repeat it
  }
  return result;
}

}  // namespace detail
}  // namespace collision2d
