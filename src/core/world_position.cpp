// Penetration resolution of a substep (Fx2D step 3): positions
// only, each move paired with the previous-pose shift so it never becomes
// velocity. Several passes, an optional two-point block, and a sticking
// contact taking back the tangential part of its integration move.
#include <algorithm>
#include <cmath>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{

void WorldImpl::correct_positions(const StepContext& ctx, StepReport& report)
{
  const double softness = settings_.compliance / (ctx.h * ctx.h);
  const bool friction = ctx.effects.friction;
  moved_.assign(bodies_.size(), Vec2{0.0, 0.0});
  turned_.assign(bodies_.size(), 0.0);
  const bool exact = settings_.solver_mode == SolverMode::Exact && settings_.exact_position_correction;
  if (exact)
  {
    // Every static-friction hold first, then the islands' penetrations at once
    // (world_exact.cpp); a failed island is left to the passes below.
    hold_all_static_friction(friction);
    solve_position_islands(softness, report);
  }
  for (int pass = 0; pass < settings_.position_iterations; ++pass)
  {
    correct_pass(softness, !exact && friction && pass == 0, pass > 0);
  }
}

void WorldImpl::correct_pass(double softness, bool hold, bool resting_only)
{
  // The extra passes are for resting contacts, where each substep's gravity
  // sag accumulates. An impact (Newton target > 0) separates in the velocity
  // solve anyway; pushing it further apart changes which contacts the next
  // substep sees, and in the 16-disk elastic gas of test_extremes_long_runs
  // that let the Gauss-Seidel passes gain energy (6.9e-5 of it over 1e5
  // frames with 4 passes on every contact, none with this restriction).
  for_manifolds_kinematic_first([&](std::size_t k) {
    ContactPoint& row = points_[k];
    if (!row.active || row.position_solved || (resting_only && row.target > 0.0))
    {
      return;
    }
    const bool pair = row.count == 2;
    // Depths are taken after the corrections already made (so a stack's
    // correction travels up it in one pass instead of diffusing over many
    // substeps), and for both points of a pair before either moves (so the
    // first point's turn does not tilt the second).
    if (hold && !row.kinetic && row.mu_s > 0.0)
    {
      hold_static_friction(row, pair ? points_[k + 1] : row);
    }
    const double first = current_depth(row);
    const double second = pair ? current_depth(points_[k + 1]) : 0.0;
    if (pair && settings_.position_block && correct_pair(row, points_[k + 1], first, second, softness))
    {
      return;
    }
    correct_point(row, first, softness);
    if (pair)
    {
      correct_point(points_[k + 1], second, softness);
    }
  });
}

void WorldImpl::hold_all_static_friction(bool friction)
{
  for (std::size_t k = 0; friction && k < points_.size(); k += points_[k].count == 2 ? 2 : 1)
  {
    const ContactPoint& row = points_[k];
    if (row.active && !row.kinetic && row.mu_s > 0.0)
    {
      hold_static_friction(row, row.count == 2 ? points_[k + 1] : row);
    }
  }
}

Vec2 WorldImpl::integration_move(std::size_t i, Vec2 r) const
{
  // Pose change since the previous pose, shifted by this substep's
  // corrections: what the integration alone moved the material point at r.
  const Body& body = bodies_[i];
  const double turn = body.theta() - prev_theta_[i] - turned_[i];
  return body.position() - prev_position_[i] - moved_[i] + cross(turn, r);
}

void WorldImpl::hold_static_friction(const ContactPoint& first, const ContactPoint& second)
{
  // Integration moves a resting body by its gravity kick before the
  // velocity solve stops it; on a slope part of that move runs along the
  // surface, and undone only in the normal direction it would become a creep
  // of g h sin(theta) downhill. A sticking contact therefore also takes back
  // the tangential move, as long as it stays inside the static cone of the
  // normal approach it came with (Coulomb at the position level, as position-based
  // static friction).
  const Vec2 ra = 0.5 * (first.r_a + second.r_a);
  const Vec2 rb = 0.5 * (first.r_b + second.r_b);
  const Vec2 slip = integration_move(first.b, rb) - integration_move(first.a, ra);
  const Vec2 t = perp(first.normal);
  const double tangential = dot(slip, t);
  const double approach = -dot(slip, first.normal);
  if (tangential == 0.0 || std::abs(tangential) > first.mu_s * std::max(0.0, approach))
  {
    return;
  }
  // The slip of a resting body is its gravity kick, a translation, so it is
  // taken back by translation: a turn would tilt the body, the normal
  // correction would level it again and leave part of the slip in place.
  const double lambda = -tangential / (first.inv_mass_a + first.inv_mass_b);
  displace(first.a, -lambda, t, ra, first.inv_mass_a, 0.0);
  displace(first.b, lambda, t, rb, first.inv_mass_b, 0.0);
}

double WorldImpl::current_depth(const ContactPoint& row) const
{
  const double approach = dot(moved_[row.b] - moved_[row.a], row.normal) + turned_[row.b] * cross(row.r_b, row.normal) -
                          turned_[row.a] * cross(row.r_a, row.normal);
  return row.depth() - approach;
}

void WorldImpl::correct_point(const ContactPoint& row, double depth, double softness)
{
  if (depth <= settings_.slop)
  {
    return;
  }
  // Each point of a manifold takes its share, so a pair is corrected once.
  const double k = inverse_effective_mass(row, row.r_a, row.r_b, row.normal) + softness;
  const double lambda = (depth - settings_.slop) / (row.count * k);
  // Moving the pose without touching the velocity is the previous-pose
  // shift: the correction never turns into velocity.
  displace(row.a, -lambda, row.normal, row.r_a, row.inv_mass_a, row.inv_inertia_a);
  displace(row.b, lambda, row.normal, row.r_b, row.inv_mass_b, row.inv_inertia_b);
}

void WorldImpl::displace(std::size_t i, double lambda, Vec2 n, Vec2 r, double inv_mass, double inv_inertia)
{
  if (inv_mass == 0.0)
  {
    return;
  }
  Body& body = bodies_[i];
  const Vec2 move = (inv_mass * lambda) * n;
  body.set_position(body.position() + move);
  moved_[i] += move;
  if (inv_inertia != 0.0)
  {
    const double turn = inv_inertia * lambda * cross(r, n);
    body.set_theta(body.theta() + turn);
    turned_[i] += turn;
  }
}

bool WorldImpl::correct_pair(const ContactPoint& first, const ContactPoint& second, double depth1, double depth2,
                         double softness)
{
  // The pair's two corrections solved together: each point alone would
  // spend most of its correction turning the body (K_n of a box corner is
  // 2.5 times its inverse mass), which the other point's turn undoes, so a
  // flat box is lifted by only 40% of its excess depth per pass.
  const double k11 = inverse_effective_mass(first, first.r_a, first.r_b, first.normal) + softness;
  const double k22 = inverse_effective_mass(second, second.r_a, second.r_b, second.normal) + softness;
  const double k12 = pair_coupling(first, second);
  if (!block_solvable(k11, k12, k22))
  {
    return false;
  }
  double y1 = 0.0;
  double y2 = 0.0;
  solve_lcp2(k11, k12, k22, settings_.slop - depth1, settings_.slop - depth2, y1, y2);
  displace(first.a, -y1, first.normal, first.r_a, first.inv_mass_a, first.inv_inertia_a);
  displace(first.b, y1, first.normal, first.r_b, first.inv_mass_b, first.inv_inertia_b);
  displace(second.a, -y2, second.normal, second.r_a, second.inv_mass_a, second.inv_inertia_a);
  displace(second.b, y2, second.normal, second.r_b, second.inv_mass_b, second.inv_inertia_b);
  return true;
}

}  // namespace detail
}  // namespace collision2d
