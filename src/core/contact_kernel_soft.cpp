// The contact-solver kernel's verbs of the soft step: soft coefficients, the
// gap from pose changes, the soft normal update (one point or a manifold's
// two) and restitution after the substeps.
#include <algorithm>
#include <cmath>

#include "contact_kernel.h"

namespace collision2d
{
namespace detail
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Softness make_softness(double hertz, double damping_ratio, double h)
{
  if (hertz == 0.0)
  {
    return Softness{0.0, 1.0};  // rigid
  }
  const double omega = 2.0 * kPi * hertz;
  const double a1 = 2.0 * damping_ratio + h * omega;
  const double a2 = h * omega * a1;
  return Softness{omega / a1, a2 * (1.0 / (1.0 + a2))};
}

double current_separation(const ContactPoint& p, const std::vector<BodyVelocity>& state)
{
  return separation_at(p, anchor_offset(p, state));
}

namespace
{
/// The soft terms of one point at gap s: its push-out bias (m/s) and mass
/// scale. A speculative point (gap > 0) may approach by its gap within the substep.
void soft_terms(const Softness& spring, double s, double inv_h, double max_push, bool use_bias, double& bias,
                double& mass_scale)
{
  bias = 0.0;
  mass_scale = 1.0;
  if (s > 0.0)
  {
    bias = s * inv_h;
  }
  else if (use_bias)
  {
    bias = std::max(spring.mass_scale * spring.bias_rate * s, -max_push);
    mass_scale = spring.mass_scale;
  }
}

void set_soft_impulse(ContactPoint& p, double total, std::vector<BodyVelocity>& state)
{
  const double applied = total - p.lambda_n;
  p.lambda_n = total;
  apply_impulse(p, applied * p.normal, state);
}

/// bias / mass_scale (m/s): the rigid update drives the normal speed to
/// minus this. The relax pass's scale is exactly 1, and x / 1 is x: no
/// division there (as the rows).
double aimed_speed(double bias, double mass_scale, bool use_bias) { return use_bias ? bias / mass_scale : bias; }
}  // namespace

// A soft update is mass_scale times the rigid update toward the speed
// -bias / mass_scale: lambda' = ms max(0, lambda - (vn + bias / ms) / k).
void solve_soft_normal(ContactPoint& p, const Softness& spring, double gap, std::vector<BodyVelocity>& state,
                       double inv_h, double max_push, bool use_bias)
{
  double bias = 0.0;
  double mass_scale = 1.0;
  soft_terms(spring, gap, inv_h, max_push, use_bias, bias, mass_scale);
  const double vn = dot(relative_velocity(p, state), p.normal);
  const double rigid = p.lambda_n - (vn + aimed_speed(bias, mass_scale, use_bias)) * p.normal_mass();
  set_soft_impulse(p, mass_scale * std::max(0.0, rigid), state);
}

void solve_soft_normal_block(ContactPoint& first, ContactPoint& second, const Softness& spring, double first_gap,
                             double second_gap, std::vector<BodyVelocity>& state, double inv_h, double max_push,
                             bool use_bias)
{
  const double k11 = first.k_n;
  const double k22 = second.k_n;
  const double k12 = first.pair_k12;  // prepared with the frame (world_soft_step.cpp)
  if (!first.pair_block)
  {
    solve_soft_normal(first, spring, first_gap, state, inv_h, max_push, use_bias);
    solve_soft_normal(second, spring, second_gap, state, inv_h, max_push, use_bias);
    return;
  }
  double bias1 = 0.0;
  double bias2 = 0.0;
  double scale1 = 1.0;
  double scale2 = 1.0;
  soft_terms(spring, first_gap, inv_h, max_push, use_bias, bias1, scale1);
  soft_terms(spring, second_gap, inv_h, max_push, use_bias, bias2, scale2);
  const double x1 = first.lambda_n;
  const double x2 = second.lambda_n;
  const double q1 =
      dot(relative_velocity(first, state), first.normal) + aimed_speed(bias1, scale1, use_bias) - (k11 * x1 + k12 * x2);
  const double q2 =
      dot(relative_velocity(second, state), first.normal) + aimed_speed(bias2, scale2, use_bias) - (k12 * x1 + k22 * x2);
  double y1 = 0.0;
  double y2 = 0.0;
  solve_lcp2(k11, k12, k22, q1, q2, y1, y2);
  set_soft_impulse(first, scale1 * y1, state);
  set_soft_impulse(second, scale2 * y2, state);
}

void release_point(ContactPoint& p, std::vector<BodyVelocity>& state)
{
  const Vec2 applied = -(p.lambda_n * p.normal + p.lambda_t * p.tangent());
  p.lambda_n = 0.0;
  p.lambda_t = 0.0;
  apply_impulse(p, applied, state);
}

double apply_restitution(ContactPoint& p, std::vector<BodyVelocity>& state)
{
  double change = 0.0;
  const double vn = update_normal(p, state, change);
  // A normal impulse driven down leaves the friction it carried outside the
  // cone: that part comes back off (alone, it spun a light disk to 1.6e4 rad/s).
  const double limit = cone(p) * p.lambda_n;
  const double kept = std::clamp(p.lambda_t, -limit, limit);
  if (kept != p.lambda_t)
  {
    apply_impulse(p, (kept - p.lambda_t) * p.tangent(), state);
    p.lambda_t = kept;
  }
  return p.lambda_n > 0.0 ? std::abs(vn - p.target) : std::max(0.0, p.target - vn);
}

}  // namespace detail
}  // namespace collision2d
