// Internal to the core: the one contact-solver kernel. One
// constraint-point type and the verbs every solver uses on it: ContactSolver's
// Gauss-Seidel sweeps, the World's substeps and the exact mode's LCP builders.
// Nothing outside this file builds a Newton target, clamps Coulomb friction
// or applies a contact impulse.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/vec2.h"
#include "scratch_buffer.h"

namespace collision2d
{
namespace detail
{
/// Velocity state of one body during a solve. Non-dynamic bodies carry zero
/// inverse mass and inertia, so impulses never change them.
struct BodyVelocity
{
  // What the soft rows read comes first, in two runs of four doubles that the
  // four-lane path loads whole (soft_rows_avx2.cpp).
  Vec2 v;
  double omega = 0.0;
  // Soft step only: the pose change since the frame's contacts were prepared.
  Vec2 moved;                ///< translation (m)
  double turned_cos = 1.0;   ///< rotation, as its cosine and sine (a disk's:
  double turned_sin = 0.0;   ///< 1 and the turn in rad, see follow_pose)
  double inv_mass = 0.0;
  double inv_inertia = 0.0;
};

/// Sets every field in place, unmoved. Filling a vector's element from a
/// returned temporary went through the stack in pieces and was read back
/// whole, a store the load could not forward (docs/performance.md).
inline void set_body_velocity(BodyVelocity& state, Vec2 v, double omega, double inv_mass, double inv_inertia)
{
  state.v = v;
  state.omega = omega;
  state.moved = Vec2{0.0, 0.0};
  state.turned_cos = 1.0;
  state.turned_sin = 0.0;
  state.inv_mass = inv_mass;
  state.inv_inertia = inv_inertia;
}

inline BodyVelocity body_velocity(Vec2 v, double omega, double inv_mass, double inv_inertia)
{
  BodyVelocity state;
  set_body_velocity(state, v, omega, inv_mass, inv_inertia);
  return state;
}

/// Soft-constraint coefficients of a contact, from a stiffness (Hz), a
/// damping ratio and the substep: a contact acts as a damped spring, so a
/// resting stack neither sinks nor is kicked apart by its corrections.
/// The update scales the whole rigid impulse by mass_scale, so the part of
/// the accumulated impulse a spring lets go (1 - mass_scale) needs no field.
struct Softness
{
  double bias_rate = 0.0;   ///< 1/s: push-out speed per metre of penetration
  double mass_scale = 1.0;  ///< dimensionless
};
Softness make_softness(double hertz, double damping_ratio, double h);

/// One contact point: geometry, the masses seen through it, the fixed Newton
/// target, the friction state and the accumulated impulses.
struct ContactPoint
{
  // The fields the solver passes read come first, so a point's pass touches
  // as few cache lines as possible; what only detection and prepare use follows.

  // Geometry.
  std::uint32_t a = 0;  ///< body index, a < b
  std::uint32_t b = 0;
  Vec2 normal;        ///< unit, from a to b
  Vec2 r_a;           ///< lever arm from a's centre to the point (m)
  Vec2 r_b;

  // Masses. Per point, because the World drops a body's inertia where it
  // cannot turn (rotation off, a smooth disk); 0 for static and kinematic bodies.
  double inv_mass_a = 0.0;     ///< 1/kg
  double inv_mass_b = 0.0;
  double inv_inertia_a = 0.0;  ///< 1/(kg m^2)
  double inv_inertia_b = 0.0;
  double k_n = 0.0;            ///< inverse effective mass along the normal (1/kg)
  double pair_tangent_mass = 0.0;  ///< 1 / K_t at a two-point manifold's midpoint (kg)

  // Friction state and impulses.
  double mu_s = 0.0;      ///< static friction coefficient
  double mu_k = 0.0;      ///< kinetic friction coefficient
  double lambda_n = 0.0;  ///< accumulated normal impulse (N s), >= 0
  double lambda_t = 0.0;  ///< accumulated tangential impulse on b along tangent (N s)

  // Soft step: the slip carried from earlier frames, and the gap at prepare
  // less the anchors' offset, so the current gap follows from the bodies'
  // pose changes.
  double anchor_drift = 0.0;     ///< tangential slip since the point last stuck, at prepare (m)
  double base_separation = 0.0;  ///< m
  double pair_k12 = 0.0;         ///< first point of a manifold: pair_coupling, fixed for the frame (1/kg)
  std::uint8_t count = 1;        ///< points in this pair's manifold (1 or 2)
  bool pair_block = false;       ///< first point of a manifold: whether its 2x2 block is solvable
  bool kinetic = false;          ///< slid before: the kinetic bound applies
  bool sliding = false;          ///< friction at its bound in the last solve
  bool active = true;            ///< World: false for a point the velocity prediction leaves out
  bool exact = false;            ///< World: solved by its island's LCP this substep
  bool position_solved = false;  ///< World: penetration corrected by its island's LCP
  bool kept = false;             ///< World, soft step: its manifold kept from an earlier frame (lever arms set)
  bool origin_known = false;     ///< World, soft step: the origin fields below are set
  bool against_static = false;   ///< World: one body is static (the soft step's stiffer spring, the Fx2D walk)
  std::uint32_t feature = 0;     ///< detection's feature id (beside the flags: no padding)

  // Detection.
  Vec2 point;               ///< world contact point at detection (m)
  double separation = 0.0;  ///< signed gap at detection (m): -depth, > 0 for a speculative point

  // Prepare: the tangent's own mass and the Newton target (the soft step
  // sets the target each substep it bounces).
  double k_t = 0.0;           ///< inverse effective mass along the tangent (1/kg)
  double target = 0.0;        ///< post-solve normal separation speed (m/s)
  double restitution = 0.0;   ///< the pair's e

  // World, soft step: where the point's manifold was detected, published
  // with the contact (its ContactOrigin; the lever arms there are r_a, r_b).
  double origin_separation = 0.0;  ///< m
  double origin_theta_a = 0.0;     ///< rad
  double origin_theta_b = 0.0;

  // Bookkeeping of the solvers that own the point.
  std::uint32_t contact = 0;  ///< index into the caller's contact list
  std::uint32_t island = 0;  ///< representative body of the coupled island

  /// The effective masses (kg), worked out where they are read: the same
  /// bits a stored copy held, 16 bytes less per point.
  double normal_mass() const { return 1.0 / k_n; }
  double tangent_mass() const { return 1.0 / k_t; }
  /// perp(normal): tangential impulses act on b along it.
  Vec2 tangent() const { return perp(normal); }
  /// Overlap at detection (m), >= 0: detection sets the gap as minus it.
  double depth() const { return std::max(0.0, -separation); }
};

/// A soft frame's two contact springs: the stiffer one against a static
/// body, so a stack is not pressed into the ground by its own weight, and
/// the other for the rest. A kinematic body gets the other: a body it
/// presses on the ground is squeezed between two springs, and pressed into
/// the ground by the stiffness ratio times the pusher's overlap; with equal
/// springs the two shared the squeeze and the body went through the ground.
struct ContactSprings
{
  /// The static spring's frequency over the other's (its stiffness goes
  /// with the square).
  static constexpr double kStaticHertzFactor = 2.0;
  /// A contact's frequency is capped at this fraction of the substep rate:
  /// a spring much stiffer than the substeps can follow would ring.
  static constexpr double kMaxHertzPerSubstepRate = 0.25;
  Softness moving;
  Softness on_static;
  /// A point's spring, from whether it touches a static body.
  const Softness& of(const ContactPoint& p) const { return p.against_static ? on_static : moving; }
};

/// The contact points of a frame or a solve: a per-frame buffer, written
/// in full by the stage that sizes it (scratch_buffer.h).
using ContactPoints = FrameBuffer<ContactPoint>;

/// Inverse effective mass of an impulse along `dir` at lever arms r_a, r_b (1/kg).
inline double inverse_effective_mass(const ContactPoint& p, Vec2 r_a, Vec2 r_b, Vec2 dir)
{
  const double arm_a = cross(r_a, dir);
  const double arm_b = cross(r_b, dir);
  return p.inv_mass_a + p.inv_mass_b + p.inv_inertia_a * arm_a * arm_a + p.inv_inertia_b * arm_b * arm_b;
}

/// Newton's rule: the post-solve separation speed is e times the approach
/// speed measured before the solve, when that exceeds `threshold` (m/s); a
/// separating, resting or slow contact gets 0.
inline double newton_target(double normal_speed, double restitution, double threshold)
{
  const double approach = -normal_speed;
  return restitution > 0.0 && approach > threshold ? restitution * approach : 0.0;
}

// The point verbs' innermost steps (the relative velocity, an impulse) are
// always inlined: a call costs more than their bodies, and left to the
// inliner a change elsewhere once made them calls (4% more instructions on a
// two-body frame).

/// Relative velocity of b with respect to a at lever arms r_a, r_b.
__attribute__((always_inline)) inline Vec2 relative_velocity_at(const ContactPoint& p, Vec2 r_a, Vec2 r_b,
                                                                const std::vector<BodyVelocity>& state)
{
  const BodyVelocity& a = state[p.a];
  const BodyVelocity& b = state[p.b];
  return b.v + cross(b.omega, r_b) - a.v - cross(a.omega, r_a);
}

__attribute__((always_inline)) inline Vec2 relative_velocity(const ContactPoint& p,
                                                             const std::vector<BodyVelocity>& state)
{
  return relative_velocity_at(p, p.r_a, p.r_b, state);
}

/// Applies `impulse` to b and its opposite to a at lever arms r_a, r_b, so
/// linear and angular momentum are unchanged.
__attribute__((always_inline)) inline void apply_impulse_at(const ContactPoint& p, Vec2 r_a, Vec2 r_b,
                                                            Vec2 impulse, std::vector<BodyVelocity>& state)
{
  BodyVelocity& a = state[p.a];
  BodyVelocity& b = state[p.b];
  if (p.inv_mass_a != 0.0)
  {
    a.v = a.v - p.inv_mass_a * impulse;
    a.omega = a.omega - p.inv_inertia_a * cross(r_a, impulse);
  }
  if (p.inv_mass_b != 0.0)
  {
    b.v = b.v + p.inv_mass_b * impulse;
    b.omega = b.omega + p.inv_inertia_b * cross(r_b, impulse);
  }
}

__attribute__((always_inline)) inline void apply_impulse(const ContactPoint& p, Vec2 impulse,
                                                        std::vector<BodyVelocity>& state)
{
  apply_impulse_at(p, p.r_a, p.r_b, impulse, state);
}

/// Fills the point's effective masses and its restitution. The caller sets
/// the lever arms and the per-point inverse masses first.
inline void prepare_masses(ContactPoint& p, double restitution)
{
  p.k_n = inverse_effective_mass(p, p.r_a, p.r_b, p.normal);
  p.k_t = inverse_effective_mass(p, p.r_a, p.r_b, p.tangent());
  p.pair_tangent_mass = p.tangent_mass();
  p.restitution = restitution;
}
/// prepare_masses, then the Newton target from the velocities now, before
/// any impulse.
void prepare_point(ContactPoint& p, const std::vector<BodyVelocity>& state, double restitution, double threshold);
/// The midpoint tangent mass of a two-point manifold, for its one friction row.
void prepare_pair(ContactPoint& first, const ContactPoint& second);

/// Applies the accumulated impulses (warm starting from a previous solve).
void warm_start(ContactPoint& p, std::vector<BodyVelocity>& state);

/// One Gauss-Seidel update of the normal impulse toward the target, kept
/// >= 0 (a contact pushes, never pulls): sets `change` to the impulse
/// applied and returns the normal speed before it (m/s).
double update_normal(ContactPoint& p, std::vector<BodyVelocity>& state, double& change);
/// update_normal, returning whether the impulse changed.
bool solve_normal(ContactPoint& p, std::vector<BodyVelocity>& state);
/// One update of the tangential impulse toward sticking, clamped to the cone.
/// `bias` (m/s) is added to the slip speed the update removes (the soft
/// step's pull back to a sticking point's anchor).
bool solve_friction(ContactPoint& p, std::vector<BodyVelocity>& state, double bias = 0.0);
/// The two normal rows of a manifold solved together as a 2x2 LCP. Returns
/// false, changing nothing, when the rows are nearly dependent; sets
/// `changed` when an impulse changed.
bool solve_normal_block(ContactPoint& first, ContactPoint& second, std::vector<BodyVelocity>& state, bool& changed);
/// A manifold's friction as one row at its midpoint against the summed normal
/// impulse, split in proportion to the normal impulses.
void solve_friction_pair(ContactPoint& first, ContactPoint& second, std::vector<BodyVelocity>& state,
                         double bias = 0.0);
/// Soft step: the offset between the point's anchors on its two bodies now
/// (m), from their pose changes since prepare; the gap and the slip follow.
inline Vec2 anchor_offset(const ContactPoint& p, const std::vector<BodyVelocity>& state)
{
  const BodyVelocity& a = state[p.a];
  const BodyVelocity& b = state[p.b];
  return b.moved - a.moved + rotate(p.r_b, b.turned_cos, b.turned_sin) - rotate(p.r_a, a.turned_cos, a.turned_sin);
}
/// The gap (m, < 0 overlapping) and the tangential slip since prepare (m) at
/// an anchor offset.
inline double separation_at(const ContactPoint& p, Vec2 offset) { return p.base_separation + dot(offset, p.normal); }
inline double slip_at(const ContactPoint& p, Vec2 offset) { return dot(offset - (p.r_b - p.r_a), p.tangent()); }
/// Soft step, a point whose normal or lever arms were moved during the
/// frame: its gap and its slip since it stuck set to these at the anchors'
/// offset now, which separation_at and slip_at then read.
inline void set_followed(ContactPoint& p, Vec2 offset, double gap, double drift)
{
  p.base_separation = gap - dot(offset, p.normal);
  p.anchor_drift = drift - slip_at(p, offset);
}
/// Both normals and the midpoint friction row solved at once assuming the pair
/// sticks; false, changing nothing, unless that keeps both normal impulses
/// >= 0 and the friction inside its cone.
bool solve_stick_block(ContactPoint& first, ContactPoint& second, std::vector<BodyVelocity>& state);

/// Coulomb's law with the stick/slip state: a sticking point holds up to
/// mu_s times `normal_impulse`, a sliding one is held at mu_k. Returns the
/// clamped `needed` and records whether it hit the bound.
double coulomb(ContactPoint& p, double needed, double normal_impulse);
/// The friction coefficient of the point's cone in its current state.
inline double cone(const ContactPoint& p) { return p.kinetic ? p.mu_k : p.mu_s; }
/// Whether the point has friction at all (either coefficient above 0).
inline bool has_friction(const ContactPoint& p) { return p.mu_s > 0.0 || p.mu_k > 0.0; }

/// Off-diagonal of a manifold's normal block: normal speed at one point per
/// unit normal impulse at the other (1/kg).
double pair_coupling(const ContactPoint& first, const ContactPoint& second);
/// The two-point LCP w = K y + q >= 0, y >= 0, y . w = 0 (K symmetric positive
/// definite) solved exactly by trying its four cases.
inline void solve_lcp2(double k11, double k12, double k22, double q1, double q2, double& y1, double& y2)
{
  const double det = k11 * k22 - k12 * k12;
  y1 = (k12 * q2 - k22 * q1) / det;  // both active
  y2 = (k12 * q1 - k11 * q2) / det;
  if (y1 >= 0.0 && y2 >= 0.0)
  {
    return;
  }
  y1 = std::max(0.0, -q1 / k11);  // only the first active
  y2 = 0.0;
  if (k12 * y1 + q2 >= 0.0)
  {
    return;
  }
  y1 = 0.0;  // only the second active, or neither
  y2 = std::max(0.0, -q2 / k22);
  if (!(k12 * y2 + q1 >= 0.0))
  {
    y2 = 0.0;
  }
}

/// Whether a 2x2 block with these entries is well enough conditioned to solve.
bool block_solvable(double k11, double k12, double k22);

/// Soft step: the point's gap now, from the bodies' pose changes since
/// prepare (m, < 0 overlapping).
double current_separation(const ContactPoint& p, const std::vector<BodyVelocity>& state);
/// Soft step: a gap at most this wide touches (m); one closed exactly within
/// a substep leaves only round-off.
constexpr double kTouchingGap = 1e-9;
/// One soft update of the normal impulse at the point's gap now (`gap`, its
/// separation_at the anchor offset, which the caller reads once for the
/// friction's pull too). A speculative point (gap > 0) only removes the
/// approach that would close its gap within the substep; an overlapping one,
/// with `use_bias`, is pushed out at most at `max_push` (m/s) through the
/// point's `spring`; without bias (the relax pass) it only stops the approach.
void solve_soft_normal(ContactPoint& p, const Softness& spring, double gap, std::vector<BodyVelocity>& state,
                       double inv_h, double max_push, bool use_bias);
/// A manifold's two points solved together (the 2x2 LCP of the rigid update,
/// each point's result scaled by the pair's `spring`), so neither point's impulse
/// tilts the body against the other; nearly dependent points go one by one.
/// Reads first.pair_k12 and first.pair_block, set when the frame is prepared.
void solve_soft_normal_block(ContactPoint& first, ContactPoint& second, const Softness& spring, double first_gap,
                             double second_gap, std::vector<BodyVelocity>& state, double inv_h, double max_push,
                             bool use_bias);
/// Where a point's accumulated normal and tangential impulses (N s) live
/// while it is solved: its lane of a row, or its own fields.
struct ImpulseSlots
{
  double* normal = nullptr;
  double* tangent = nullptr;
};
/// The point's impulses from their slots, for the point verbs.
inline void load_impulses(ContactPoint& p, ImpulseSlots slots)
{
  p.lambda_n = *slots.normal;
  p.lambda_t = *slots.tangent;
}
/// ... and back.
inline void store_impulses(const ContactPoint& p, ImpulseSlots slots)
{
  *slots.normal = p.lambda_n;
  *slots.tangent = p.lambda_t;
}
/// Takes back a point's whole impulse, normal and tangential.
void release_point(ContactPoint& p, std::vector<BodyVelocity>& state);
/// Drives a point toward its Newton target, of either sign (accumulated
/// normal impulse >= 0), and keeps its friction impulse inside the cone of
/// the normal one. Returns its residual before the update.
double apply_restitution(ContactPoint& p, std::vector<BodyVelocity>& state);

/// Normal residual (m/s): a pushing point must meet its target exactly, an
/// idle one must not fall short of it.
double normal_residual(const ContactPoint& p, const std::vector<BodyVelocity>& state);
/// The larger of the normal residual and the Coulomb residual for friction
/// coefficient mu (m/s); zero exactly at a solution with fixed targets.
double point_residual(const ContactPoint& p, const std::vector<BodyVelocity>& state, double mu);

}  // namespace detail
}  // namespace collision2d
