// World settings (SPEC section 3.3): materials and the one table of the
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

// Why some knobs exist and what they cost (the table's docs are one line each):
//  - warm_start_every_substep: SPEC section 3 warm-starts only a frame's first
//    substep (false gives exactly that). The later substeps then start cold, and
//    two Gauss-Seidel passes cannot carry the weight of a tall stack from zero: a
//    20-box column sinks metres into itself. With true every later substep also
//    starts from the previous substep's impulses, matched by (body ids, feature).
//  - toi_displacement_fraction: a dynamic body is swept for time of impact when
//    its displacement in one substep exceeds this fraction of (its inner radius +
//    the smallest inner radius in the world); inner radius = radius of a disk,
//    least centroid-to-face distance of a polygon. Below it nothing is skipped.
//  - sleep_auto_min_bodies: Toggle::Auto sleeps only worlds with gravity and at
//    least this many dynamic bodies: smaller scenes gain little and keep exactly
//    reproducible trajectories; without gravity nothing rests against anything.
//  - position_iterations (SPEC step 3 is one pass): each pass moves a body by its
//    share of each contact's depth beyond slop, and in a stack the lift a contact
//    gives is partly taken back by the contact above it, so one pass leaves part
//    of every substep's gravity sag (the 20-box column 0.15 m after 10 s with one
//    pass, 0.054 m with four; the base-20 pyramid 0.056 m and 0.029 m; measured in
//    test_world_stacking.cpp). Passes after the first skip impacts.
//  - position_block: a two-point manifold's penetration solved as one 2x2 block
//    instead of SPEC's per-point lambda = (d - slop) / (count K_n). Per point a
//    flat box is lifted by only 40% of its excess depth per pass; the block lifts
//    it fully (column 0.052 m at one pass) but lets the pyramid, whose boxes rest
//    on two half faces, spread sideways (2.4 cm at one pass, 16 cm at two): off.
//  - solver_mode: Iterative runs velocity_iterations Gauss-Seidel passes. Exact
//    solves each island as one LCP by pivoting (with Newton targets and Coulomb
//    cones), carrying mass ratios no number of passes can (1e6 kg on 1 kg); an
//    island whose pivoting fails (or has more than kMaxExactUnknowns unknowns)
//    falls back to the passes, counted in StepReport::exact_fallbacks.
//  - exact_position_correction: with false a position pass barely moves the
//    heavy body of an extreme mass ratio, so a 1e6 kg box on a 1 kg box keeps each
//    substep's gravity sag and sinks steadily although its velocities are exact.
//  - warm_start_before_integration: in SPEC's order a resting body first moves by
//    its gravity kick g h^2 and the position passes, which carry a lift up a stack
//    only in part, must lift it back every substep; predicting the velocities
//    from the previous substep's contacts (as Box2D moves poses with solved
//    velocities) removes that. Velocities are set back after detection, so only
//    poses differ from the default order. Needs warm starting. Over 1 s to 10 s:
//    20-box column 4x2 8.1e-3 -> 2.8e-4 m, 4x8 7.9e-3 -> 7.1e-6 m, 8x4 2.8e-3 ->
//    6.8e-6 m; base-20 pyramid 4x8 1.5e-3 -> 1.7e-5 m, 8x4 1.9e-4 -> 3.0e-6 m, but
//    4x2 1.5e-3 -> 0.15 m (touching contacts come and go and start cold): use it
//    with >= 4 substeps x >= 4 iterations or 8x4. Cost: one more velocity solve
//    per substep (pyramid 8x4 +12%, 4x8 +30%). A 100 kg box on a 1 kg one sinks
//    less (4 mm, not 19) but drifts more (2.0e-3 m, not 3.2e-4).

// The one table of the world's settings (SPEC section 3.3). Adding a setting is
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
  X(velocity_iterations, int, 2, kAtLeastOne, "", "Passes over the contact points per substep") \
  X(slop, double, 1e-3, kNonNegative, "m", "Penetration left uncorrected") \
  X(compliance, double, 1e-8, kNonNegative, "m/N", "Contact compliance: softens K_n by compliance/h^2") \
  X(restitution_threshold, double, 1e-3, kNonNegative, "m/s", "Approach speed below which restitution is ignored") \
  X(rotation, Toggle, Toggle::Auto, kAnyFinite, "", "Rotation of the bodies") \
  X(friction, Toggle, Toggle::Auto, kAnyFinite, "", "Coulomb friction") \
  X(restitution, Toggle, Toggle::Auto, kAnyFinite, "", "Newton restitution") \
  X(position_correction, Toggle, Toggle::Auto, kAnyFinite, "", "Penetration correction") \
  X(time_of_impact, Toggle, Toggle::Auto, kAnyFinite, "", "Sweeps of fast bodies to their time of impact") \
  X(warm_starting, Toggle, Toggle::Auto, kAnyFinite, "", "Solves start from the last substep's impulses") \
  X(sleeping, Toggle, Toggle::Auto, kAnyFinite, "", "Resting islands sleep") \
  X(warm_start_factor, double, 1.0, kUnitInterval, "", "Fraction of the cached impulses applied when warm starting") \
  X(warm_start_every_substep, bool, true, kAnyFinite, "", "Warm-start every substep, not just a frame's first (tall stacks need it)") \
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
  X(soft_step, bool, false, kAnyFinite, "", "Soft step (iterative mode): collide once per frame, soft contacts, relax, restitution last") \
  X(contact_hertz, double, 30.0, kNonNegative, "Hz", "Soft step: contact stiffness (at most a quarter of the substep rate; twice it against static bodies)") \
  X(contact_damping_ratio, double, 10.0, kNonNegative, "", "Soft step: damping ratio of the contact spring") \
  X(contact_push_speed, double, 3.0, kPositive, "m/s", "Soft step: fastest a penetration is pushed out") \
  X(speculative_margin, double, 0.02, kNonNegative, "m", "Soft step: pairs within this gap get contacts before they touch")
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
/// (none yet: add a line in world_settings.cpp when a setting is renamed or retired).
const std::vector<FormerSetting>& former_world_settings();

/// Throws std::invalid_argument naming the field for an out-of-range setting.
void validate_world_settings(const WorldSettings& settings);
/// Throws std::invalid_argument for an out-of-range or non-finite material.
void validate_material(const Material& material);

}  // namespace collision2d
