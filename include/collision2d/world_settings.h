// World settings (SPEC section 3.3): materials, the Auto/On/Off toggle of each
// effect and WorldSettings with its documented defaults.
#pragma once

#include <cstddef>

#include "collision2d/solver_mode.h"
#include "collision2d/vec2.h"

namespace collision2d
{
/// Per-body surface properties; a contact combines its two bodies' values by min.
struct Material
{
  double restitution = 0.0;       ///< Newton coefficient, [0, 1]
  double static_friction = 0.0;   ///< mu_s >= 0
  double kinetic_friction = 0.0;  ///< mu_k >= 0
};

/// Each physical effect is on when the scene needs it (Auto) unless forced.
enum class Toggle
{
  Auto,
  On,
  Off
};

struct WorldSettings
{
  Vec2 gravity{0.0, -9.81};               ///< m/s^2
  double dt = 1.0 / 60.0;                 ///< frame length (s)
  int substeps = 4;                       ///< substeps per frame
  int velocity_iterations = 2;            ///< passes over the contact points per substep
  double slop = 1e-3;                     ///< penetration left uncorrected (m)
  double compliance = 1e-8;               ///< contact compliance (m/N), softens K_n by compliance/h^2
  double restitution_threshold = 1e-3;    ///< approach speed below which e is ignored (m/s)
  Toggle rotation = Toggle::Auto;
  Toggle friction = Toggle::Auto;
  Toggle restitution = Toggle::Auto;
  Toggle position_correction = Toggle::Auto;
  Toggle time_of_impact = Toggle::Auto;
  Toggle warm_starting = Toggle::Auto;
  Toggle sleeping = Toggle::Auto;

  // Knobs of the individual effects (additions beyond SPEC section 3).
  /// Fraction of the cached impulses applied when warm starting, [0, 1].
  double warm_start_factor = 1.0;
  /// SPEC section 3 warm-starts only a frame's first substep (false gives
  /// exactly that). The later substeps then start cold, and two Gauss-Seidel
  /// passes cannot carry the weight of a tall stack from zero: a 20-box
  /// column sinks metres into itself. With true (default) every later substep
  /// also starts from the previous substep's impulses, matched the same way
  /// by (body ids, feature).
  bool warm_start_every_substep = true;
  /// A dynamic body is swept for time of impact when its displacement in one
  /// substep exceeds this fraction of (its inner radius + the smallest inner
  /// radius in the world); inner radius = radius of a disk, least centroid-to-face
  /// distance of a polygon. Below it the body cannot skip over anything. > 0.
  double toi_displacement_fraction = 0.5;
  /// A dynamic body rests (and may sleep) below this speed (m/s), >= 0.
  double sleep_linear_speed = 0.05;
  /// ... and below this angular speed (rad/s), >= 0.
  double sleep_angular_speed = 0.1;
  /// Time every body of an island must have rested before the island sleeps (s), >= 0.
  double sleep_time = 0.5;
  /// Toggle::Auto sleeps only worlds with gravity and at least this many
  /// dynamic bodies: smaller scenes gain little and keep exactly reproducible
  /// trajectories; without gravity nothing rests against anything.
  std::size_t sleep_auto_min_bodies = 256;
  /// Penetration-resolution passes per substep (SPEC step 3 is one pass).
  /// Each pass moves a body by its share of each contact's depth beyond slop,
  /// and in a stack the lift a contact gives is partly taken back by the
  /// contact above it: one pass leaves part of every substep's gravity sag in
  /// each contact, so a tall stack rests deeper than slop (the 20-box column
  /// 0.15 m after 10 s with one pass, 0.054 m with four; the base-20 pyramid
  /// 0.056 m and 0.029 m; measured in test_world_stacking.cpp). The passes
  /// after the first skip impacts (contacts with a Newton target), which
  /// separate in the velocity solve. >= 1.
  int position_iterations = 4;
  /// A two-point manifold's penetration solved as one 2x2 block (true)
  /// instead of SPEC's per-point lambda = (d - slop) / (count K_n) (false).
  /// Per point, a flat box is lifted by only 40% of its excess depth per pass
  /// (K_n of a box corner is 2.5 times the inverse mass: most of the
  /// correction turns the box and the other point turns it back); the block
  /// lifts it fully. It sinks the column 0.052 m at one pass, but lets the
  /// pyramid, whose boxes each rest on two half faces, spread sideways
  /// (2.4 cm at one pass, 16 cm at two), so it is off by default.
  bool position_block = false;
  /// Velocity resolution. Iterative: velocity_iterations Gauss-Seidel passes.
  /// Exact: each island's contacts (dynamic bodies linked by contacts) are
  /// solved as one LCP by pivoting, with each contact's Newton target and
  /// Coulomb cone, so mass ratios no number of passes can carry (a 1e6 kg box
  /// on a 1 kg one) are resolved in one solve; an island whose pivoting fails
  /// (or that has more unknowns than kMaxExactUnknowns) is solved by the
  /// iterative passes instead and counted in StepReport::exact_fallbacks. The
  /// position pass is the same in both modes. See world_exact.cpp.
  SolverMode solver_mode = SolverMode::Iterative;
  /// Exact mode only: also solve each island's penetration correction as one
  /// LCP (true), instead of the Gauss-Seidel position pass of iterative mode
  /// (false). A position pass barely moves the heavy body of an extreme mass
  /// ratio, so with false a 1e6 kg box on a 1 kg box keeps each substep's
  /// gravity sag and sinks steadily even though its velocities are exact.
  bool exact_position_correction = true;
  /// Advance the poses in step 1 with velocities predicted from the previous
  /// substep's contacts (warm-started with the impulses they carried, then
  /// solved with velocity_iterations passes), as Box2D moves its poses with
  /// solved velocities. In SPEC's order a resting body first moves by its
  /// gravity kick g h^2 and the position passes, which carry a lift up a
  /// stack only in part, must lift it back every substep. After detection the
  /// velocities are set back to their values after the gravity kick, so
  /// Newton targets, the velocity solve, friction state and contacts not
  /// found again are exactly those of the default order; only poses differ.
  /// Needs warm starting (nothing happens on a substep that starts cold);
  /// works in both solver modes.
  /// Measured over 1 s to 10 s (drift, default 4 position passes):
  ///  - 20-box column: 4x2 8.1e-3 -> 2.8e-4 m, 4x8 7.9e-3 -> 7.1e-6 m,
  ///    8x4 2.8e-3 -> 6.8e-6 m;
  ///  - base-20 pyramid: 4x8 1.5e-3 -> 1.7e-5 m, 8x4 1.9e-4 -> 3.0e-6 m,
  ///    but 4x2 1.5e-3 -> 0.15 m: resting bodies no longer press into each
  ///    other, touching contacts come and go, each starts cold, and two
  ///    passes cannot carry the pyramid from cold (it rattles and its top
  ///    slides off). Use it with >= 4 substeps x >= 4 iterations or 8x4.
  /// Cost: one more velocity solve per substep (pyramid 8x4 +12%, 4x8 +30%).
  /// Rebounds, the cradle and an elastic gas are unchanged; a box below the
  /// friction angle no longer creeps (4e-4 m in 10 s before), one sliding
  /// above it keeps g (sin - mu_k cos) but tilts by 1e-4 rad; a 100 kg box on
  /// a 1 kg one sinks less (4 mm, not 19) but drifts more (2.0e-3 m, not 3.2e-4).
  bool warm_start_before_integration = false;
};

/// Throws std::invalid_argument naming the field for an out-of-range setting.
void validate_world_settings(const WorldSettings& settings);
/// Throws std::invalid_argument for an out-of-range or non-finite material.
void validate_material(const Material& material);

}  // namespace collision2d
