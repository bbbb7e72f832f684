// World settings: materials and the one table of the
// world's settings (WorldSettings) with their defaults, ranges, units and docs.
#pragma once

#include <cstddef>
#include <vector>

#include "collision2d/setting_table.h"

namespace collision2d
{
/// Per-body surface properties; a contact combines its two bodies' values by min.
struct Material
{
  double restitution = 0.0;       ///< Newton coefficient, [0, 1]
  double static_friction = 0.0;   ///< mu_s >= 0
  double kinetic_friction = 0.0;  ///< mu_k >= 0
};

// Why some knobs exist (the table's docs are one line each; their measured
// effects are in docs/performance.md):
//  - toi_displacement_fraction: a dynamic body is swept for time of impact when
//    its displacement in one substep exceeds this fraction of (its inner radius
//    + the smallest inner radius in the world); below it nothing is skipped.
//  - sleep_auto_min_bodies: Toggle::Auto sleeps only worlds with gravity and at
//    least this many dynamic bodies: smaller scenes gain little and keep exactly
//    reproducible trajectories; without gravity nothing rests against anything.
//  - position_iterations: in a stack the lift one contact gives is partly taken
//    back by the contact above it, so one pass leaves part of every substep's
//    gravity sag; passes after the first skip impacts.
//  - position_block: a two-point manifold's penetration as one 2x2 block lifts a
//    flat box fully (per point only part of the lift survives the turn it
//    causes) but lets a pyramid spread sideways: off.
//  - solver_mode: Exact solves each island as one LCP by pivoting, carrying mass
//    ratios no number of passes can; a failed island falls back to the passes
//    (StepReport::exact_fallbacks). It works in both pipelines.
//  - exact_position_correction (Fx2D): without it a position pass barely moves the
//    heavy body of an extreme mass ratio, which then keeps each substep's sag.
//  - warm_start_before_integration: poses advance with velocities predicted
//    from the previous substep's contacts, so a resting body is not first moved
//    by its gravity kick; needs warm starting, and >= 4x4 or 8x4 substeps x
//    passes (at 4x2 touching contacts come and go and a pyramid rattles).
//  - soft_step: the contacts are damped springs (contact_hertz,
//    contact_damping_ratio), found once per frame within speculative_margin.
//  - contact_reuse_distance (soft step): a pair's contact points are kept from
//    the frame that found them while the pair moves less than this relative to
//    then; their gaps follow the bodies. A tall column stands on kept points
//    (found again each frame, their normals tilt with it and it buckles).
//    Capped at speculative_margin: a feature that was out of reach then cannot
//    reach the other body before the pair is found again.

// The one table of the world's settings. Adding a setting is
// one line here; cfg/Collision2d.cfg reads these lines, so keep each entry
//   X(name, type, default, range, "unit", "doc")
// on one line with a plain default (a number, true/false, Toggle::X,
// SolverMode::X or (Vec2{x, y})). WorldConfig.msg needs a field of the same
// name (the conversion does not compile without it).
// clang-format off
#define COLLISION2D_WORLD_SETTINGS(X) \
  X(gravity, Vec2, (Vec2{0.0, -9.81}), kAnyFinite, "m/s^2", "Gravity") \
  X(dt, double, 1.0 / 60.0, kPositive, "s", "Frame length") \
  X(substeps, int, 4, kAtLeastOne, "", "Substeps per frame: more buys stiffer stacks") \
  X(velocity_iterations, int, 2, kAtLeastOne, "", "Fx2D order: passes over the contact points per substep (the soft step: soft_iterations)") \
  X(slop, double, 1e-3, kNonNegative, "m", "Contact error let be: penetration left uncorrected (Fx2D); slip a sticking contact takes before it slides (soft step)") \
  X(compliance, double, 1e-8, kNonNegative, "m/N", "Contact compliance: softens K_n by compliance/h^2 (exact position LCP: not against static bodies)") \
  X(restitution_threshold, double, 1e-3, kNonNegative, "m/s", "Approach speed below which restitution is ignored") \
  X(rotation, Toggle, Toggle::Auto, kAnyFinite, "", "Rotation of the bodies") \
  X(friction, Toggle, Toggle::Auto, kAnyFinite, "", "Coulomb friction") \
  X(restitution, Toggle, Toggle::Auto, kAnyFinite, "", "Newton restitution") \
  X(position_correction, Toggle, Toggle::Auto, kAnyFinite, "", "Penetration correction") \
  X(time_of_impact, Toggle, Toggle::Auto, kAnyFinite, "", "Sweeps of fast bodies to their time of impact") \
  X(warm_starting, Toggle, Toggle::Auto, kAnyFinite, "", "Solves start from the last substep's impulses") \
  X(sleeping, Toggle, Toggle::Auto, kAnyFinite, "", "Resting islands sleep") \
  X(toi_displacement_fraction, double, 0.5, kPositive, "", "Sweep a body moving more than this fraction of its size per substep") \
  X(sleep_linear_speed, double, 0.05, kNonNegative, "m/s", "A dynamic body rests below this speed") \
  X(sleep_angular_speed, double, 0.1, kNonNegative, "rad/s", "... and below this angular speed") \
  X(sleep_time, double, 0.5, kNonNegative, "s", "Rest this long before an island sleeps") \
  X(sleep_auto_min_bodies, std::size_t, 256, kNonNegative, "", "Auto sleeping only in worlds with gravity and this many dynamic bodies") \
  X(position_iterations, int, 4, kAtLeastOne, "", "Penetration-correction passes per substep") \
  X(position_block, bool, false, kAnyFinite, "", "Correct a two-point contact's penetration as one 2x2 block") \
  X(solver_mode, SolverMode, SolverMode::Iterative, kAnyFinite, "", "Velocity solve: iterative passes, or exact LCP per island") \
  X(exact_position_correction, bool, true, kAnyFinite, "", "Exact solver only: penetration also solved as one LCP per island") \
  X(warm_start_before_integration, bool, false, kAnyFinite, "", "Advance poses with velocities predicted from the last substep's contacts") \
  X(soft_step, bool, true, kAnyFinite, "", "Soft step (iterative mode): collide once per frame, soft contacts, relax, restitution each substep") \
  X(contact_hertz, double, 40.0, kNonNegative, "Hz", "Soft step: contact stiffness (at most a quarter of the substep rate; twice it against static bodies)") \
  X(contact_damping_ratio, double, 10.0, kNonNegative, "", "Soft step: damping ratio of the contact spring") \
  X(soft_iterations, int, 1, kAtLeastOne, "", "Soft step: solve passes, and relax passes, per substep (more hold tall stacks stiffer; each costs about one pass more)") \
  X(contact_push_speed, double, 3.0, kPositive, "m/s", "Soft step: fastest a penetration is pushed out") \
  X(speculative_margin, double, 0.02, kNonNegative, "m", "Soft step: pairs within this gap get contacts before they touch") \
  X(contact_reuse_distance, double, 0.02, kNonNegative, "m", "Soft step: a pair keeps its contact points while it moves less than this and speculative_margin since they were found (0: find them every frame)") \
  X(workers, int, 1, kWorkerCount, "", "Threads stepping the world (narrow phase, soft contact passes); trajectories are the same for any count")
// clang-format on

struct WorldSettings
{
  COLLISION2D_WORLD_SETTINGS(COLLISION2D_DECLARE_SETTING)
};

/// Calls visit(info, field) for every field of the table, in table order;
/// `Settings` is WorldSettings or const WorldSettings.
template <typename Settings, typename Visit>
void visit_world_settings(Settings& settings, Visit&& visit)
{
  COLLISION2D_WORLD_SETTINGS(COLLISION2D_VISIT_SETTING)
}

/// Settings that files of earlier versions name and this version does not
/// (add a line in world_settings.cpp when a setting is renamed or retired).
const std::vector<FormerSetting>& former_world_settings();

/// Throws std::invalid_argument naming the field for an out-of-range setting.
void validate_world_settings(const WorldSettings& settings);
/// Throws std::invalid_argument for an out-of-range or non-finite material.
void validate_material(const Material& material);

}  // namespace collision2d
