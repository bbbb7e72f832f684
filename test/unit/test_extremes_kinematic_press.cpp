// A kinematic body pressing a body onto the ground (a robot's link pushing
// a part down on a table). The push cannot be resisted, so something must
// give; the ground must not: the part stays on it and the link overlaps the
// part instead. In the soft step the part sits between two contact springs,
// the link's and the ground's, which is kStaticHertzFactor (ContactSprings)
// times faster (its stiffness goes with the square). The ground's spring carries
// at most what the link's spring and damper push with (the link closing at
// most at its own speed) and the part's weight, so the part's overlap with
// the ground is at most that force over the ground's stiffness; checked
// every frame while the link is above the part's centre. Before the
// ground's spring was given only to static contacts, a kinematic body got it
// too, the two springs shared the squeeze, and at 1 m/s the part went
// through the ground (its centre 0.33 m below it with gravity, 0.76 m
// without). Without gravity, where heights give no order, the ground's
// contact must also be solved last (soft_rows_colour.cpp): with the springs
// alone the part still went through (0.66 m below at 1 m/s).
// The Fx2D order's contacts are rigid; there a kinematic body's contacts
// are solved and corrected first, so the ground's correction comes last and
// leaves the part overlapping it by `slop` and the compliance's share of
// the push. In point order the part went through the ground (1.49 m below
// at 1 m/s without gravity).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"
#include "contact_kernel.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
constexpr double kRadius = 0.4;      // m, the part: a disk
constexpr double kMass = 6.3;        // kg
constexpr double kBarHalf = 0.05;    // m, half the link's thickness
constexpr double kBarLength = 3.0;   // m
constexpr int kFrames = 60;
constexpr double kPi = 3.14159265358979323846;
/// Round-off allowed beyond what the ground may give (m).
constexpr double kBalanceTol = 1e-9;
constexpr double kGroundHalfWidth = 20.0;  // m
constexpr double kGroundDepth = 1.0;       // m

/// A world of `s` on a static ground, its top at y = 0.
World world_on_ground(const WorldSettings& s, const Material& material = Material())
{
  World world(s);
  Body ground = scenes::make_box(1.0, 2.0 * kGroundHalfWidth, kGroundDepth, {0.0, -0.5 * kGroundDepth});
  ground.set_type(BodyType::Static);
  world.add_body(ground, material);
  return world;
}

/// A kinematic box (the link) of length x thickness (m) at `at`, turned by
/// `theta` (rad), moving at `velocity` (m/s) and turning at `spin` (rad/s).
BodyId add_link(World& world, double length, double thickness, Vec2 at, double theta, Vec2 velocity, double spin,
                const Material& material = Material())
{
  Body bar = scenes::make_box(1.0, length, thickness, at, theta, velocity, spin);
  bar.set_type(BodyType::Kinematic);
  return world.add_body(bar, material);
}

/// Steps kFrames; the body's lowest centroid height while it is over the
/// ground, `size` (m) from its ends (a body flung off them falls freely).
double lowest_over_ground(World& world, BodyId body, double size)
{
  double lowest = 1e300;
  for (int f = 0; f < kFrames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    const Vec2 at = world.body(body).position();
    if (std::abs(at.x) < kGroundHalfWidth - size)
    {
      lowest = std::min(lowest, at.y);
    }
  }
  return lowest;
}

struct Press
{
  double lowest_centre = 1e300;  ///< the part's centre above the ground, least (m)
  double worst_excess = -1e300;  ///< ground overlap less the balance, most (m)
  double deepest_bar = 0.0;      ///< the link's deepest overlap checked (m)
};

/// The link's contact spring's angular frequency (rad/s); the ground's is
/// kStaticHertzFactor times it.
double link_omega(const WorldSettings& s)
{
  return 2.0 * kPi * std::min(s.contact_hertz, detail::ContactSprings::kMaxHertzPerSubstepRate * s.substeps / s.dt);
}

/// The most the ground may give under the part (m), with the link
/// overlapping it by `bar_overlap` and closing at `speed`.
double allowed_ground_overlap(const WorldSettings& s, double speed, double bar_overlap)
{
  if (s.soft_step)
  {
    // Per unit of the part's mass (both contacts move only the part): the
    // link pushes with stiffness w^2 and damping 2 zeta w, the ground holds
    // with stiffness (F w)^2.
    const double w = link_omega(s);
    const double ground_stiffness = std::pow(detail::ContactSprings::kStaticHertzFactor * w, 2);
    const double damper_push = 2.0 * s.contact_damping_ratio * w * speed;
    return (w * w * bar_overlap + damper_push + std::abs(s.gravity.y)) / ground_stiffness;
  }
  if (s.solver_mode == SolverMode::Exact)
  {
    // Fx2D's exact mode: the island's position LCP takes no compliance on
    // the ground's contact (world_exact.cpp), so it ends each substep within
    // `slop` of the ground; the link's contact takes the squeeze.
    return s.slop;
  }
  // Fx2D: each correction pass moves the part out of the ground by its depth
  // beyond `slop` less the compliance's share, c/h^2 over 1/m + c/h^2; the
  // link, corrected first, pushes it in by at most its overlap a pass.
  const double h = s.dt / s.substeps;
  const double soft = s.compliance / (h * h);
  const double share = soft / (1.0 / kMass + soft);
  return s.slop + s.position_iterations * share * bar_overlap;
}

Press press(double speed, double gravity, bool soft_step, SolverMode mode)
{
  WorldSettings s;
  s.gravity = {0.0, -gravity};
  s.soft_step = soft_step;
  s.solver_mode = mode;
  World world = world_on_ground(s);
  const BodyId part = world.add_body(Body(kMass, kRadius, {0.0, kRadius}, {0.0, 0.0}));
  const BodyId bar_id =
      add_link(world, kBarLength, 2.0 * kBarHalf, {0.0, 2.0 * kRadius + kBarHalf}, 0.0, {0.0, -speed}, 0.0);
  Press out;
  for (int f = 0; f < kFrames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    const double centre = world.body(part).position().y;
    const double bar_bottom = world.body(bar_id).position().y - kBarHalf;
    out.lowest_centre = std::min(out.lowest_centre, centre);
    if (bar_bottom <= centre)
    {
      continue;  // past the centre the link's push turns up
    }
    const double bar_overlap = std::max(0.0, centre + kRadius - bar_bottom);
    const double ground_overlap = std::max(0.0, kRadius - centre);
    out.deepest_bar = std::max(out.deepest_bar, bar_overlap);
    out.worst_excess = std::max(out.worst_excess, ground_overlap - allowed_ground_overlap(s, speed, bar_overlap));
  }
  return out;
}

void expect_ground_holds(bool soft_step, SolverMode mode = SolverMode::Iterative)
{
  const std::string pipeline =
      std::string(soft_step ? "soft step" : "Fx2D") + (mode == SolverMode::Exact ? ", exact mode" : "");
  for (double gravity : {0.0, 9.81})
  {
    for (double speed : {0.5, 1.0, 2.0, 5.0, 20.0})
    {
      SCOPED_TRACE(pipeline + ", bar at " + std::to_string(speed) + " m/s, gravity " + std::to_string(gravity) +
                   " m/s^2");
      const Press out = press(speed, gravity, soft_step, mode);
      std::printf("%s: bar %g m/s down, gravity %g m/s^2, deepest bar overlap %.3f m:\n", pipeline.c_str(), speed,
                  gravity, out.deepest_bar);
      test::print_figure("part's centre above the ground, least (m)", out.lowest_centre, 0.0);
      test::print_figure("ground overlap beyond what it may give, most (m)", out.worst_excess, kBalanceTol);
      EXPECT_GT(out.lowest_centre, 0.0) << "the part went through the ground";
      EXPECT_LE(out.worst_excess, kBalanceTol) << "the ground gave more than it may";
    }
  }
}

TEST(ExtremesKinematicPress, SoftStepGroundHoldsAPartAKinematicBarPresses) { expect_ground_holds(true); }

// The exact mode's island LCP has no solution here (two bodies that cannot
// move squeeze a third); the island falls back to the passes, which walk the
// manifolds without colours, a kinematic body's first. Before, they walked in
// point order and the part went through the ground (0.66 m below at 1 m/s,
// without gravity).
TEST(ExtremesKinematicPress, SoftStepExactGroundHoldsAPartAKinematicBarPresses)
{
  expect_ground_holds(true, SolverMode::Exact);
}

// A thin heavy box with friction, pressed onto the ground by a bar tilted
// 0.05 rad (friction 0.4 holds it against the wedge's squeeze). Its LCP is
// nearly singular: pivoting answered with normal impulses that cancel each
// other, huge enough to pass the residual check scaled by them, and their
// friction flung the box (at 6471 m/s with the bar at 5 m/s). An island
// whose solve raises its contact speeds more than tenfold now falls back to
// the passes. Checked: the box never moves faster than the bar.
TEST(ExtremesKinematicPress, SoftStepExactThinBoxUnderAKinematicBarIsNotFlung)
{
  constexpr double kBoxMass = 114.0;   // kg
  constexpr double kBoxLength = 0.5;   // m
  const Material rough{0.0, 0.4, 0.3};
  double fastest_of_all = 0.0;
  for (double thickness : {0.005, 0.05})
  {
    for (double speed : {1.0, 5.0, 20.0})
    {
      SCOPED_TRACE("box " + std::to_string(thickness) + " m thick, bar at " + std::to_string(speed) + " m/s");
      WorldSettings s;
      s.gravity = {0.0, -10.0};
      s.solver_mode = SolverMode::Exact;
      World world = world_on_ground(s, rough);
      const BodyId box =
          world.add_body(scenes::make_box(kBoxMass, kBoxLength, thickness, {0.0, 0.5 * thickness}), rough);
      add_link(world, kBarLength, 2.0 * kBarHalf, {0.3, thickness + 0.25}, 0.05, {0.0, -speed}, 0.0, rough);
      double fastest = 0.0;
      for (int f = 0; f < kFrames; ++f)
      {
        world.step();
        EXPECT_TRUE(test::all_finite(world));
        const Body& b = world.body(box);
        fastest = std::max(fastest, length(b.velocity()) + std::abs(b.omega()) * b.radius());
      }
      EXPECT_LE(fastest, speed) << "the box was flung";
      fastest_of_all = std::max(fastest_of_all, fastest / speed);
    }
  }
  test::print_figure("thin box's fastest point over the bar's speed, most", fastest_of_all, 1.0);
}

TEST(ExtremesKinematicPress, Fx2dGroundHoldsAPartAKinematicBarPresses) { expect_ground_holds(false); }

// The Fx2D order's exact mode solves the island's penetrations as one LCP.
// With the compliance on both contacts it split the squeeze between the
// ground and the link: the part's centre came down to 0.15 m at 0.5 m/s and
// 0.042 m below the ground's top at 1 m/s.
TEST(ExtremesKinematicPress, Fx2dExactGroundHoldsAPartAKinematicBarPresses)
{
  expect_ground_holds(false, SolverMode::Exact);
}

// A rod thinner than `slop` lying on the ground may rest with its centroid
// up to `slop` inside it; a bar turning about a point above it sweeps its
// tip into the ground and strikes the rod (Fx2D, where a fast face pushes
// what it strikes, world_kinematic_push.cpp). The static-crossing check
// took such a centroid for one already inside the ground, left it to the
// contacts and let the push carry the rod through: 5.76 m below the top at
// 100 rad/s (found by a random stress run). It now takes a centroid within
// `slop` of the face as on it. Checked: while over the ground, the rod's
// centroid never passes below the ground's top by more than slop. (At
// 30 rad/s the bar flings it, frictionless, off the ground's end, where it
// falls: this test once took that fall for a press into the ground.)
TEST(ExtremesKinematicPress, Fx2dTurningBarDoesNotPushAThinRodThroughTheGround)
{
  constexpr double kRodHalf = 0.0008;  // m, thinner than slop
  constexpr double kRodLength = 1.7;   // m
  constexpr double kSink = 0.0005;     // m, the rod's centroid inside the ground at rest
  for (const double spin : {-30.0, -100.0, -267.0})
  {
    SCOPED_TRACE("bar at " + std::to_string(spin) + " rad/s");
    WorldSettings s;
    s.gravity = {0.0, -9.81};
    s.soft_step = false;
    World world = world_on_ground(s);
    const BodyId rod = world.add_body(scenes::make_box(1.0, kRodLength, 2.0 * kRodHalf, {0.0, -kSink}));
    add_link(world, 3.06, 0.05, {-1.25, 1.27}, 0.3, {0.35, 0.0}, spin);  // its tip reaches 0.26 m below the ground's top
    const double lowest = lowest_over_ground(world, rod, kRodLength);
    std::printf("Fx2D: bar turning at %g rad/s over a thin rod:\n", spin);
    test::print_figure("rod's centroid over the ground, lowest (m)", lowest, -s.slop);
    EXPECT_GT(lowest, -s.slop) << "the rod's centroid went into the ground";
  }
}

// A fast-turning bar whose tips dip into the ground, moving along it, strikes
// a box resting there again and again (Fx2D: a fast face pushes what it
// strikes, world_kinematic_push.cpp). Each push was shorter than the move
// the static-crossing check sweeps (half the box's inner radius a substep),
// and they added up: at 46.51 rad/s from a turn of 0.5 rad the box went
// through the ground (24.8 m below it). A pushed body is now swept however
// little it moved (found by a random stress run). Checked for several
// phases and spins: while over the ground, the box's centroid never passes
// below the ground's top by more than slop.
TEST(ExtremesKinematicPress, Fx2dTurningBarDoesNotPushABoxThroughTheGround)
{
  constexpr double kBoxMass = 9.58;          // kg
  constexpr double kBoxWidth = 0.96;         // m
  constexpr double kBoxHeight = 0.767;       // m
  constexpr double kBarSpeed = -2.728;       // m/s along the ground
  constexpr int kSubsteps = 5;
  for (const double spin : {46.51, 100.0})
  {
    for (const double phase : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5})
    {
      SCOPED_TRACE("bar at " + std::to_string(spin) + " rad/s from " + std::to_string(phase) + " rad");
      WorldSettings s;
      s.gravity = {0.0, -10.0};
      s.soft_step = false;
      s.substeps = kSubsteps;
      World world = world_on_ground(s);
      add_link(world, 3.34, 0.185, {0.987, 1.217}, phase, {kBarSpeed, 0.0}, spin);  // its tips reach 0.45 m below
      const BodyId box = world.add_body(scenes::make_box(kBoxMass, kBoxWidth, kBoxHeight, {-0.88, 0.5 * kBoxHeight}));
      const double lowest = lowest_over_ground(world, box, kBoxWidth);
      std::printf("Fx2D: bar turning at %g rad/s from %g rad over a box:\n", spin, phase);
      test::print_figure("box's centroid over the ground, lowest (m)", lowest, -s.slop);
      EXPECT_GT(lowest, -s.slop) << "the box's centroid went into the ground";
    }
  }
}

// A rod 36 mm thick lying on the ground, struck by a bar turning at 100 or
// 204.5 rad/s whose tips dip 0.88 m into the ground. The contacts pressed
// its centroid a few mm into the ground, deeper than `slop`; the
// static-crossing check took it for one already inside, and the next push
// carried the rod through (29 to 51 m below at 2 and 4 substeps; found by
// a random stress run). It now takes a centroid less than its inner radius
// inside as on the face, so it moves no deeper. Checked in both pipelines:
// the rod's centroid stays within its inner radius of the ground's top.
TEST(ExtremesKinematicPress, TurningBarDoesNotPushAPressedRodThroughTheGround)
{
  constexpr double kRodThickness = 0.036;  // m: its inner radius is half this
  constexpr double kRodLength = 2.0;       // m
  constexpr double kRodMass = 9.39;        // kg
  double lowest_of_all = 1e300;
  for (const bool soft_step : {false, true})
  {
    for (const int substeps : {2, 4})
    {
      for (const double spin : {100.0, 204.5})
      {
        for (const double phase : {0.0, 0.5, 1.5, 2.5})
        {
          SCOPED_TRACE(std::string(soft_step ? "soft step" : "Fx2D") + ", " + std::to_string(substeps) +
                       " substeps, bar at " + std::to_string(spin) + " rad/s from " + std::to_string(phase) + " rad");
          WorldSettings s;
          s.gravity = {0.0, 0.0};
          s.soft_step = soft_step;
          s.substeps = substeps;
          World world = world_on_ground(s);
          add_link(world, 3.74, 0.2, {-0.04, 1.086}, phase, {-4.0, 0.0}, spin);  // its tips reach 0.88 m below
          const BodyId rod =
              world.add_body(scenes::make_box(kRodMass, kRodLength, kRodThickness, {-1.2, 0.5 * kRodThickness}));
          const double lowest = lowest_over_ground(world, rod, kRodLength);
          EXPECT_GT(lowest, -0.5 * kRodThickness) << "the rod's centroid went deeper than its inner radius";
          lowest_of_all = std::min(lowest_of_all, lowest);
        }
      }
    }
  }
  test::print_figure("rod's centroid over the ground, lowest of all runs (m)", lowest_of_all, -0.5 * kRodThickness);
}

}  // namespace
}  // namespace collision2d
