#include "contact_kernel.h"

#include <algorithm>
#include <cmath>

namespace collision2d
{
namespace detail
{
namespace
{
/// A block solve needs det K > this fraction of the product of K's diagonal
/// (dimensionless); below it the rows act almost as one (no rotation,
/// coincident arms) and are solved one by one instead.
constexpr double kBlockConditionLimit = 1e-6;

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

/// One velocity constraint of a block: impulse direction and lever arms.
struct BlockRow
{
  Vec2 direction;
  Vec2 r_a;
  Vec2 r_b;
};

Vec2 midpoint_arm_a(const ContactPoint& first, const ContactPoint& second) { return 0.5 * (first.r_a + second.r_a); }
Vec2 midpoint_arm_b(const ContactPoint& first, const ContactPoint& second) { return 0.5 * (first.r_b + second.r_b); }

}  // namespace

void prepare_point(ContactPoint& p, const std::vector<BodyVelocity>& state, double restitution, double threshold)
{
  prepare_masses(p, restitution);
  // Measured once, before any impulse: later impulses never move the target.
  p.target = newton_target(dot(relative_velocity(p, state), p.normal), restitution, threshold);
}

void prepare_pair(ContactPoint& first, const ContactPoint& second)
{
  first.pair_tangent_mass =
      1.0 / inverse_effective_mass(first, midpoint_arm_a(first, second), midpoint_arm_b(first, second), first.tangent());
}

void warm_start(ContactPoint& p, std::vector<BodyVelocity>& state)
{
  if (p.lambda_n != 0.0 || p.lambda_t != 0.0)
  {
    apply_impulse(p, p.lambda_n * p.normal + p.lambda_t * p.tangent(), state);
  }
}

double update_normal(ContactPoint& p, std::vector<BodyVelocity>& state, double& change)
{
  const double vn = dot(relative_velocity(p, state), p.normal);
  const double total = std::max(0.0, p.lambda_n + (p.target - vn) * p.normal_mass());
  change = total - p.lambda_n;
  p.lambda_n = total;
  apply_impulse(p, change * p.normal, state);
  return vn;
}

bool solve_normal(ContactPoint& p, std::vector<BodyVelocity>& state)
{
  double change = 0.0;
  update_normal(p, state, change);
  return change != 0.0;
}

double coulomb(ContactPoint& p, double needed, double normal_impulse)
{
  // A point that stuck before holds up to the static cone; past it, it is
  // clamped there and slides from the next solve on, at the kinetic bound,
  // until the impulse that stops it fits inside the kinetic cone again.
  // (Deciding stick or slip from one Gauss-Seidel pass's estimate instead lets
  // a transient overshoot drop a sticking point to the kinetic bound, from
  // where it never recovers.)
  const double limit = cone(p) * normal_impulse;
  p.sliding = std::abs(needed) > limit;
  return std::max(-limit, std::min(limit, needed));
}

bool solve_friction(ContactPoint& p, std::vector<BodyVelocity>& state, double bias)
{
  const double slip = dot(relative_velocity(p, state), p.tangent());
  const double vt = bias == 0.0 ? slip : slip + bias;
  const double total = coulomb(p, p.lambda_t - vt * p.tangent_mass(), p.lambda_n);
  const double change = total - p.lambda_t;
  p.lambda_t = total;
  apply_impulse(p, change * p.tangent(), state);
  return change != 0.0;
}

double pair_coupling(const ContactPoint& first, const ContactPoint& second)
{
  const Vec2 n = first.normal;
  return first.inv_mass_a + first.inv_mass_b + first.inv_inertia_a * cross(first.r_a, n) * cross(second.r_a, n) +
         first.inv_inertia_b * cross(first.r_b, n) * cross(second.r_b, n);
}

bool block_solvable(double k11, double k12, double k22)
{
  return k11 * k22 - k12 * k12 > kBlockConditionLimit * k11 * k22;
}

bool solve_normal_block(ContactPoint& first, ContactPoint& second, std::vector<BodyVelocity>& state, bool& changed)
{
  // Solved one after the other, the first point's impulse tilts the body and
  // biases the second; solved together, a box on a floor rests after one pass.
  const Vec2 n = first.normal;
  // K's diagonal as 1 / normal_mass(), the rounding the per-point passes'
  // masses carry (the Fx2D pipeline's golden trajectories are pinned with it).
  const double k11 = 1.0 / first.normal_mass();
  const double k22 = 1.0 / second.normal_mass();
  const double k12 = pair_coupling(first, second);
  if (!block_solvable(k11, k12, k22))
  {
    return false;
  }
  const double x1 = first.lambda_n;
  const double x2 = second.lambda_n;
  // q: each row's distance above its target with the current impulses removed.
  const double q1 = dot(relative_velocity(first, state), n) - first.target - (k11 * x1 + k12 * x2);
  const double q2 = dot(relative_velocity(second, state), n) - second.target - (k12 * x1 + k22 * x2);
  double y1 = 0.0;
  double y2 = 0.0;
  solve_lcp2(k11, k12, k22, q1, q2, y1, y2);
  first.lambda_n = y1;
  second.lambda_n = y2;
  apply_impulse(first, (y1 - x1) * n, state);
  apply_impulse(second, (y2 - x2) * n, state);
  changed = changed || y1 != x1 || y2 != x2;
  return true;
}

void solve_friction_pair(ContactPoint& first, ContactPoint& second, std::vector<BodyVelocity>& state, double bias)
{
  // Both points lie on one face: they share the tangent and, for a rigid
  // pair, the slip speed, so two friction rows would be one constraint twice
  // with no unique split. Splitting the midpoint row's impulse in proportion
  // to the normal impulses keeps each point inside its own cone.
  const Vec2 t = first.tangent();
  const Vec2 r_a = midpoint_arm_a(first, second);
  const Vec2 r_b = midpoint_arm_b(first, second);
  const double slip = dot(relative_velocity_at(first, r_a, r_b, state), t);
  const double vt = bias == 0.0 ? slip : slip + bias;
  const double normal_sum = first.lambda_n + second.lambda_n;
  const double old_total = first.lambda_t + second.lambda_t;
  const double total = coulomb(first, old_total - vt * first.pair_tangent_mass, normal_sum);
  second.sliding = first.sliding;
  apply_impulse_at(first, r_a, r_b, (total - old_total) * t, state);
  const double share = normal_sum > 0.0 ? first.lambda_n / normal_sum : 0.5;
  first.lambda_t = share * total;
  second.lambda_t = total - first.lambda_t;
}

bool solve_stick_block(ContactPoint& first, ContactPoint& second, std::vector<BodyVelocity>& state)
{
  const Vec2 n = first.normal;
  const Vec2 t = first.tangent();
  const Vec2 r_a = midpoint_arm_a(first, second);
  const Vec2 r_b = midpoint_arm_b(first, second);
  const BlockRow rows[3] = {{n, first.r_a, first.r_b}, {n, second.r_a, second.r_b}, {t, r_a, r_b}};
  double arm_a[3];
  double arm_b[3];
  for (int u = 0; u < 3; ++u)
  {
    arm_a[u] = cross(rows[u].r_a, rows[u].direction);
    arm_b[u] = cross(rows[u].r_b, rows[u].direction);
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
  const double rhs[3] = {first.target - dot(relative_velocity(first, state), n),
                         second.target - dot(relative_velocity(second, state), n),
                         -dot(relative_velocity_at(first, r_a, r_b, state), t)};
  double delta[3];
  if (!solve3(k, rhs, delta))
  {
    return false;
  }
  const double x1 = first.lambda_n + delta[0];
  const double x2 = second.lambda_n + delta[1];
  const double y = first.lambda_t + second.lambda_t + delta[2];
  if (!(x1 >= 0.0 && x2 >= 0.0 && std::abs(y) <= cone(first) * (x1 + x2)))
  {
    return false;
  }
  apply_impulse(first, delta[0] * n, state);
  apply_impulse(second, delta[1] * n, state);
  apply_impulse_at(first, r_a, r_b, delta[2] * t, state);
  first.lambda_n = x1;
  second.lambda_n = x2;
  const double share = x1 + x2 > 0.0 ? x1 / (x1 + x2) : 0.5;
  first.lambda_t = share * y;
  second.lambda_t = y - first.lambda_t;
  first.sliding = false;
  second.sliding = false;
  return true;
}

double normal_residual(const ContactPoint& p, const std::vector<BodyVelocity>& state)
{
  const double gap = dot(relative_velocity(p, state), p.normal) - p.target;
  return p.lambda_n > 0.0 ? std::abs(gap) : std::max(0.0, -gap);
}

// Friction part (mu > 0 only):
//  - lambda_n == 0: no friction may act; |lambda_t| * k_t is the velocity
//    change the stray impulse causes;
//  - strictly inside the cone: the point sticks, |vt|;
//  - on the cone: it must slide against the impulse, max(0, vt sign(lambda_t)),
//    plus (|lambda_t| - mu lambda_n) k_t for any excursion outside the cone.
double point_residual(const ContactPoint& p, const std::vector<BodyVelocity>& state, double mu)
{
  const double normal = normal_residual(p, state);
  if (mu <= 0.0)
  {
    return normal;
  }
  const double vt = dot(relative_velocity(p, state), p.tangent());
  const double bound = mu * p.lambda_n;
  const double magnitude = std::abs(p.lambda_t);
  double friction = 0.0;
  if (p.lambda_n <= 0.0)
  {
    friction = magnitude * p.k_t;
  }
  else if (magnitude < bound)
  {
    friction = std::abs(vt);
  }
  else
  {
    const double along_impulse = p.lambda_t > 0.0 ? vt : (p.lambda_t < 0.0 ? -vt : 0.0);
    friction = std::max(0.0, along_impulse) + (magnitude - bound) * p.k_t;
  }
  return std::max(normal, friction);
}

}  // namespace detail
}  // namespace collision2d
