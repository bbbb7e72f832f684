// Block solves for the two points of a manifold. Solved one after the other,
// the first point's impulse tilts the body and biases the second; two
// Gauss-Seidel passes do not remove that bias, and a resting box turns it
// into a slow creep. Solved together, a box on a floor or an incline is at
// rest after one pass.
#include <algorithm>
#include <cmath>

#include "collision2d/world.h"

namespace collision2d
{
namespace
{
/// A block solve needs det K > this fraction of the product of K's diagonal;
/// below it the rows act almost as one (no rotation, coincident arms) and are
/// solved one by one instead.
constexpr double kBlockConditionLimit = 1e-6;

/// One velocity constraint of a block: impulse direction and lever arms.
struct BlockRow
{
  Vec2 direction;
  Vec2 ra;
  Vec2 rb;
};

/// Solves k x = rhs (3x3) by Cramer's rule; false when k is near singular.
bool solve3(const double k[3][3], const double rhs[3], double x[3])
{
  auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double det = det3(k);
  if (!(std::abs(det) > kBlockConditionLimit * k[0][0] * k[1][1] * k[2][2]))
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    double m[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int q = 0; q < 3; ++q)
      {
        m[r][q] = q == c ? rhs[r] : k[r][q];
      }
    }
    x[c] = det3(m) / det;
  }
  return true;
}

/// Solves the two-point LCP w = K y + q >= 0, y >= 0, y . w = 0 (K symmetric
/// positive definite) exactly by trying its four cases: both points active,
/// only the first, only the second, neither.
void solve_lcp2(double k11, double k12, double k22, double q1, double q2, double& y1, double& y2)
{
  const double det = k11 * k22 - k12 * k12;
  y1 = (k12 * q2 - k22 * q1) / det;
  y2 = (k12 * q1 - k11 * q2) / det;
  if (y1 >= 0.0 && y2 >= 0.0)
  {
    return;
  }
  y1 = std::max(0.0, -q1 / k11);
  y2 = 0.0;
  if (k12 * y1 + q2 >= 0.0)
  {
    return;
  }
  y1 = 0.0;
  y2 = std::max(0.0, -q2 / k22);
  if (!(k12 * y2 + q1 >= 0.0))
  {
    y2 = 0.0;
  }
}

}  // namespace

double World::pair_coupling(const ContactRow& first, const ContactRow& second) const
{
  // Off-diagonal of the pair's normal block: speed at one point per unit
  // impulse at the other.
  const Vec2 n = first.normal;
  return first.inv_mass_a + first.inv_mass_b + first.inv_inertia_a * cross(first.ra, n) * cross(second.ra, n) +
         first.inv_inertia_b * cross(first.rb, n) * cross(second.rb, n);
}

bool World::correct_pair(const ContactRow& first, const ContactRow& second, double depth1, double depth2,
                         double softness)
{
  // The pair's two corrections solved together: each point alone would
  // spend most of its correction turning the body (K_n of a box corner is
  // 2.5 times its inverse mass), which the other point's turn undoes, so a
  // flat box is lifted by only 40% of its excess depth per pass.
  const double k11 = effective_inverse_mass(first, first.normal) + softness;
  const double k22 = effective_inverse_mass(second, second.normal) + softness;
  const double k12 = pair_coupling(first, second);
  if (!(k11 * k22 - k12 * k12 > kBlockConditionLimit * k11 * k22))
  {
    return false;
  }
  double y1 = 0.0;
  double y2 = 0.0;
  solve_lcp2(k11, k12, k22, settings_.slop - depth1, settings_.slop - depth2, y1, y2);
  displace(first.a, -y1, first.normal, first.ra, first.inv_mass_a, first.inv_inertia_a);
  displace(first.b, y1, first.normal, first.rb, first.inv_mass_b, first.inv_inertia_b);
  displace(second.a, -y2, second.normal, second.ra, second.inv_mass_a, second.inv_inertia_a);
  displace(second.b, y2, second.normal, second.rb, second.inv_mass_b, second.inv_inertia_b);
  return true;
}

void World::solve_pair(ContactRow& first, ContactRow& second, bool rough)
{
  if (rough && solve_stick_pair(first, second))
  {
    return;
  }
  if (!solve_normal_pair(first, second))
  {
    solve_normal(first);
    solve_normal(second);
  }
  if (rough)
  {
    solve_friction_pair(first, second);
  }
}

bool World::solve_stick_pair(ContactRow& first, ContactRow& second)
{
  // Both normals and the pair's friction row (at the midpoint, see
  // solve_friction_pair) solved at once assuming the pair sticks; accepted
  // only when that keeps both normal impulses >= 0 and the friction inside
  // its cone, otherwise the caller clamps row by row.
  const Vec2 n = first.normal;
  const Vec2 t = perp(n);
  const Vec2 ra = 0.5 * (first.ra + second.ra);
  const Vec2 rb = 0.5 * (first.rb + second.rb);
  const BlockRow rows[3] = {{n, first.ra, first.rb}, {n, second.ra, second.rb}, {t, ra, rb}};
  // Each row's lever terms once, not once per matrix entry.
  double arm_a[3];
  double arm_b[3];
  for (int u = 0; u < 3; ++u)
  {
    arm_a[u] = cross(rows[u].ra, rows[u].direction);
    arm_b[u] = cross(rows[u].rb, rows[u].direction);
  }
  const double inv_mass = first.inv_mass_a + first.inv_mass_b;
  double k[3][3];
  for (int u = 0; u < 3; ++u)
  {
    for (int v = 0; v < 3; ++v)
    {
      k[u][v] = inv_mass * dot(rows[u].direction, rows[v].direction) + first.inv_inertia_a * arm_a[u] * arm_a[v] +
                first.inv_inertia_b * arm_b[u] * arm_b[v];
    }
  }
  const double rhs[3] = {first.target - dot(relative_velocity(first), n),
                         second.target - dot(relative_velocity(second), n),
                         -dot(relative_velocity_at(first, ra, rb), t)};
  double delta[3];
  if (!solve3(k, rhs, delta))
  {
    return false;
  }
  const double x1 = first.impulse.normal + delta[0];
  const double x2 = second.impulse.normal + delta[1];
  const double y = first.impulse.tangent + second.impulse.tangent + delta[2];
  const double limit = (first.kinetic ? first.mu_k : first.mu_s) * (x1 + x2);
  if (!(x1 >= 0.0 && x2 >= 0.0 && std::abs(y) <= limit))
  {
    return false;
  }
  apply_impulse(first, delta[0] * n);
  apply_impulse(second, delta[1] * n);
  apply_impulse_at(first, ra, rb, delta[2] * t);
  first.impulse.normal = x1;
  second.impulse.normal = x2;
  // Split in proportion to the normal impulses: each point inside its cone.
  const double share = x1 + x2 > 0.0 ? x1 / (x1 + x2) : 0.5;
  first.impulse.tangent = share * y;
  second.impulse.tangent = y - first.impulse.tangent;
  first.sliding = false;
  second.sliding = false;
  return true;
}

bool World::solve_normal_pair(ContactRow& first, ContactRow& second)
{
  // Two-point LCP on the accumulated impulses x >= 0 with residual
  // w = K x + q >= 0, x . w = 0.
  const Vec2 n = first.normal;
  const double k11 = 1.0 / first.normal_mass;
  const double k22 = 1.0 / second.normal_mass;
  const double k12 = pair_coupling(first, second);
  if (!(k11 * k22 - k12 * k12 > kBlockConditionLimit * k11 * k22))
  {
    return false;  // nearly dependent points (no rotation, or coincident arms)
  }
  const double x1 = first.impulse.normal;
  const double x2 = second.impulse.normal;
  const double q1 = dot(relative_velocity(first), n) - first.target - (k11 * x1 + k12 * x2);
  const double q2 = dot(relative_velocity(second), n) - second.target - (k12 * x1 + k22 * x2);
  double y1 = 0.0;
  double y2 = 0.0;
  solve_lcp2(k11, k12, k22, q1, q2, y1, y2);
  first.impulse.normal = y1;
  second.impulse.normal = y2;
  apply_impulse(first, (y1 - x1) * n);
  apply_impulse(second, (y2 - x2) * n);
  return true;
}

}  // namespace collision2d
