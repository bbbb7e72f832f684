// Extreme speeds: bodies at 1e4 m/s do not tunnel with time of
// impact on (ContactSolver::step and World with time_of_impact On or Auto),
// the same World scene with it Off does tunnel (so the check can fail), and
// spin at 1e4 rad/s stays finite without gaining energy. The soft step
// sweeps a body in the substep it turns fast, whether a contact or gravity
// makes it so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "extremes_support.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
constexpr double kSpeed = 1e4;  // m/s
constexpr double kSpin = 1e4;   // rad/s
constexpr double kWallX = 5.0;  // m, centre of the thin wall
constexpr double kWallThickness = 0.05;  // m
constexpr double kBulletRadius = 0.05;   // m
/// Allowed overlap at the time of impact: the touch tolerance (1e-9 of the
/// pair's size) plus round-off of p + t v at |v| = 1e4 (m).
constexpr double kTouchSlack = 1e-8;
/// Velocities after an impact against the formula, relative to kSpeed.
constexpr double kVelocityRelativeTol = 1e-9;

double wall_face() { return kWallX - 0.5 * kWallThickness; }

/// Largest x any point of `b` reaches.
double front(const Body& b)
{
  if (b.shape() == Shape::Disk)
  {
    return b.position().x + b.radius();
  }
  double x = -1e300;
  for (std::size_t i = 0; i < b.vertex_count(); ++i)
  {
    x = std::max(x, b.world_vertex(i).x);
  }
  return x;
}

std::vector<Body> bullet_and_wall(const Body& bullet)
{
  return {scenes::make_static_box(kWallThickness, 4.0, {kWallX, 0.0}), bullet};
}

/// Steps until the bullet has left; it must never pass the wall's face and
/// must come back at e times its speed.
void check_step_bounce(const Body& bullet, double e, const char* what)
{
  std::vector<Body> bodies = bullet_and_wall(bullet);
  const ContactSolver solver(e, 0.0);
  const SolveReport first = solver.step(bodies);
  const double overshoot = front(bodies[1]) - wall_face();
  EXPECT_GT(first.time_of_impact, 0.0) << what;
  EXPECT_LT(first.time_of_impact, 1.0) << what;
  EXPECT_LE(overshoot, kTouchSlack) << what;
  EXPECT_NEAR(bodies[1].velocity().x, -e * kSpeed, kVelocityRelativeTol * kSpeed) << what;
  for (int k = 0; k < 3; ++k)
  {
    solver.step(bodies);
    EXPECT_LE(front(bodies[1]) - wall_face(), kTouchSlack) << what << ", step " << k + 2;
  }
  std::printf("%s, e = %.1f: toi %.9f, overshoot at impact %.3g m (bound %.1g), vx after %.6g m/s\n", what, e,
              first.time_of_impact, overshoot, kTouchSlack, bodies[1].velocity().x);
}

TEST(ExtremesSpeed, StepDiskBulletDoesNotTunnel)
{
  for (double e : {0.0, 1.0})
  {
    check_step_bounce(Body(0.1, kBulletRadius, {0.0, 0.0}, {kSpeed, 0.0}), e, "disk at 1e4 m/s");
  }
}

TEST(ExtremesSpeed, StepSliverBulletDoesNotTunnel)
{
  // Aspect 1000, turned so it meets the wall corner first.
  const Body sliver(0.1, scenes::box_outline(0.5, 0.0005), {0.0, 0.0}, {kSpeed, 0.0}, 0.3);
  for (double e : {0.0, 1.0})
  {
    std::vector<Body> bodies = bullet_and_wall(sliver);
    ContactSolver(e, 0.0).step(bodies);
    const double overshoot = front(bodies[1]) - wall_face();
    EXPECT_LE(overshoot, kTouchSlack);
    EXPECT_LT(bodies[1].velocity().x, kSpeed) << "the impact must take speed off";
    EXPECT_TRUE(test::all_finite(bodies));
    std::printf("sliver at 1e4 m/s, e = %.1f: overshoot %.3g m, v after (%.6g, %.6g), w %.6g\n", e, overshoot,
                bodies[1].velocity().x, bodies[1].velocity().y, bodies[1].omega());
  }
}

TEST(ExtremesSpeed, StepHeadOnDisksExchangeVelocities)
{
  // 100 m apart, each at 1e4 m/s: one unit step would carry them through
  // each other many times over.
  std::vector<Body> bodies = {Body(1.0, 0.5, {0.0, 0.0}, {kSpeed, 0.0}), Body(1.0, 0.5, {100.0, 0.0}, {-kSpeed, 0.0})};
  const SolveReport report = ContactSolver(1.0, 0.0).step(bodies);
  const double gap = bodies[1].position().x - bodies[0].position().x - 1.0;
  EXPECT_NEAR(report.time_of_impact, 99.0 / (2.0 * kSpeed), 1e-12);
  EXPECT_GE(gap, -kTouchSlack);
  EXPECT_NEAR(bodies[0].velocity().x, -kSpeed, kVelocityRelativeTol * kSpeed);
  EXPECT_NEAR(bodies[1].velocity().x, kSpeed, kVelocityRelativeTol * kSpeed);
  std::printf("head-on at 2e4 m/s closing: toi %.12f, gap at impact %.3g m\n", report.time_of_impact, gap);
}

/// Frames of the bullet_wall scene at kSpeed; returns the largest overshoot
/// of the bullet past the wall's face seen after any frame (m).
double world_bullet_overshoot(Toggle toi, bool soft_step)
{
  Scene scene = scenes::bullet_wall(kSpeed);
  scene.settings.time_of_impact = toi;
  scene.settings.soft_step = soft_step;
  World world = make_world(scene);
  const BodyId bullet = 1;
  double worst = -1e300;
  constexpr int kFrames = 30;
  for (int f = 0; f < kFrames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    worst = std::max(worst, front(world.body(bullet)) - wall_face());
  }
  return worst;
}

TEST(ExtremesSpeed, WorldBulletDoesNotTunnelWithTimeOfImpact)
{
  for (bool soft_step : {true, false})
  {
    for (Toggle toi : {Toggle::On, Toggle::Auto})
    {
      const double overshoot = world_bullet_overshoot(toi, soft_step);
      // The world's position correction leaves up to its slop of overlap.
      const double bound = WorldSettings().slop + kTouchSlack;
      const std::string name = std::string(soft_step ? "soft step" : "Fx2D") + ", toi " + (toi == Toggle::On ? "On" : "Auto");
      EXPECT_LE(overshoot, bound) << name;
      test::print_figure("world bullet 1e4 m/s, " + name + ": overshoot (m)", overshoot, bound);
    }
  }
}

TEST(ExtremesSpeed, WorldBulletTunnelsWithTimeOfImpactOffInTheFx2dPipeline)
{
  // The control: the scene really is one where discrete steps tunnel.
  const double overshoot = world_bullet_overshoot(Toggle::Off, false);
  EXPECT_GT(overshoot, kWallThickness);
  std::printf("world bullet 1e4 m/s, Fx2D, toi Off: overshoot %.4g m (expected past the wall)\n", overshoot);
}

TEST(ExtremesSpeed, SoftStepBulletStopsEvenWithTimeOfImpactOff)
{
  // Collided once per frame with a margin as long as the frame's travel, the
  // bullet has its contact with the wall before it moves.
  const double overshoot = world_bullet_overshoot(Toggle::Off, true);
  const double bound = kTouchSlack;
  EXPECT_LE(overshoot, bound);
  test::print_figure("world bullet 1e4 m/s, soft step, toi Off: overshoot (m)", overshoot, bound);
}

/// A light disk at rest between a fast heavy one and a thin wall, in the
/// soft step with one substep a frame: the frame's contacts hold the heavy
/// disk's hit, not the light one's flight into the wall (it was at rest), so
/// the sweep stops it there, in the frame's last substep. A resting disk far
/// away comes first in body order. Returns the world as that frame left it.
World light_disk_stopped_at_the_wall(BodyId& far_disk, BodyId& light)
{
  constexpr double kRadius = 0.05;      // m
  constexpr double kHeavySpeed = 100.0;  // m/s: the light disk then travels past the wall in a frame
  Scene scene;
  scene.settings.gravity = Vec2{0.0, 0.0};
  scene.settings.substeps = 1;
  scene.settings.time_of_impact = Toggle::On;
  scene.bodies.push_back(SceneBody{Body(1.0, 0.5, {-50.0, 0.0}, {0.0, 0.0}), Material{}, "far"});
  scene.bodies.push_back(SceneBody{scenes::make_static_box(kWallThickness, 4.0, {kWallX, 0.0}), Material{}, "wall"});
  scene.bodies.push_back(SceneBody{Body(1e-3, kRadius, {kWallX - 1.0, 0.0}, {0.0, 0.0}), Material{}, "light"});
  scene.bodies.push_back(
      SceneBody{Body(1.0, kRadius, {kWallX - 1.0 - 3.0 * kRadius, 0.0}, {kHeavySpeed, 0.0}), Material{}, "heavy"});
  World world = make_world(scene);
  far_disk = world.body_ids()[0];
  light = world.body_ids()[2];
  for (int frame = 0; frame < 10; ++frame)
  {
    if (world.step().toi_clamps > 0)
    {
      return world;
    }
  }
  ADD_FAILURE() << "the light disk never stopped at its time of impact";
  return world;
}

TEST(ExtremesSpeed, EditsAfterAStopAtTheTimeOfImpactKeepWhatTheNextDetectionKnows)
{
  // The next detection keeps the stopped disk touching the wall. A body
  // removed before it in body order must not hand the disk another body's
  // record (its trajectory is the one without the edit: the far disk meets
  // nothing), nor may a body added next to the wall read past the records'
  // end (scripts/sanitize.sh checks every index).
  BodyId far_disk = 0;
  BodyId light = 0;
  const World stopped = light_disk_stopped_at_the_wall(far_disk, light);
  World kept = stopped;
  World removed = stopped;
  removed.remove_body(far_disk);
  World added = stopped;
  // Overlapping the wall's face a little, far above the light disk: a pair with the wall.
  constexpr double kDiskRadius = 0.1;  // m
  added.add_body(Body(1.0, kDiskRadius, {kWallX - 0.5 * kWallThickness - kDiskRadius + 1e-4, 1.5}, {0.0, 0.0}),
                 Material{});
  for (int frame = 0; frame < 30; ++frame)
  {
    for (World* w : {&kept, &removed, &added})
    {
      w->step();
    }
    const Body& a = kept.body(light);
    for (const World* w : {&removed, &added})
    {
      const Body& b = w->body(light);
      ASSERT_TRUE(a.position() == b.position() && a.velocity() == b.velocity())
          << (w == &removed ? "far disk removed" : "disk added") << ", frame " << frame;
    }
  }
}

TEST(ExtremesSpeed, SpinningBoxOnGroundStaysFiniteAndLosesEnergy)
{
  // A 1 m box spinning at 1e4 rad/s dropped onto rough ground: the corners
  // move at 7e3 m/s and turn 40 rad per substep.
  Scene scene;
  const scenes::GroundParams ground;
  scenes::add_ground(scene, ground);
  scene.bodies.push_back(
      SceneBody{scenes::make_box(1.0, 1.0, 1.0, {0.0, 2.0}, 0.0, {0.0, 0.0}, kSpin), scenes::rough_material(), "box"});
  World world = make_world(scene);
  const BodyId box = 1;
  const double g = -scene.settings.gravity.y;
  auto total_energy = [&] {
    const Body& b = world.body(box);
    return b.kinetic_energy() + b.mass() * g * b.position().y;
  };
  const double start = total_energy();
  const long frames = test::sized(600, 120, "spinning box frames");
  double worst_rise = 0.0;
  double lowest = 1e300;
  for (long f = 0; f < frames; ++f)
  {
    world.step();
    ASSERT_TRUE(test::all_finite(world)) << "frame " << f;
    worst_rise = std::max(worst_rise, (total_energy() - start) / start);
    // The spin may throw the box off the ground's end; only over the ground
    // can it sink.
    const Body& b = world.body(box);
    if (std::abs(b.position().x - ground.x) < 0.5 * ground.width)
    {
      lowest = std::min(lowest, b.position().y);
    }
  }
  // Contacts only dissipate here (e = 0, friction); allow round-off.
  constexpr double kEnergyRiseTol = 1e-9;
  constexpr double kLowestCentre = 0.5 - 0.1;  // m: half the box, less a tenth of its size of sinking
  EXPECT_LE(worst_rise, kEnergyRiseTol);
  EXPECT_GE(lowest, kLowestCentre);
  std::printf("box spinning at 1e4 rad/s on ground, %ld frames:\n", frames);
  test::print_figure("largest rise of kinetic + potential energy (relative)", worst_rise, kEnergyRiseTol);
  test::print_figure("lowest centre height (m), at least", lowest, kLowestCentre);
  test::print_figure("spin at the end (rad/s)", world.body(box).omega(), kSpin);
}

/// Disks at rest far from a scene: enough bodies that the soft step checks
/// only the touched ones for speed each substep, not every body.
void add_spectators(Scene& scene)
{
  constexpr int kSpectators = 16;
  constexpr double kRadius = 0.5;  // m: thicker than the scene's thinnest body
  for (int k = 0; k < kSpectators; ++k)
  {
    const Vec2 at{-1000.0 - 4.0 * kRadius * k, 0.0};
    scene.bodies.push_back(SceneBody{Body(1.0, kRadius, at, {0.0, 0.0}), Material{}, "spectator"});
  }
}

/// A wide disk too slow to be swept hits a small one of the same mass at
/// rest (e = 1: they swap velocities), which flies into a thin wall within
/// the same frame, at the defaults (time of impact Auto, 4 substeps). The
/// frame began with the small disk at rest, so its pair with the wall has no
/// contact: only the sweep, which checks each substep the bodies a contact
/// touches, can stop it. Returns the small disk's largest overshoot past the
/// wall's face (m); `totals` gathers the frames' sweeps.
double small_disk_launched_at_the_wall(Toggle toi, StepReport& totals)
{
  constexpr double kWideRadius = 1.0;  // m
  constexpr double kMass = 1e-3;       // kg, both disks
  constexpr double kSpeed = 50.0;      // m/s
  constexpr double kGap = 0.3;         // m, small disk to wall: far past the margin, within a frame's flight
  Scene scene;
  scene.settings.gravity = Vec2{0.0, 0.0};
  scene.settings.time_of_impact = toi;
  const Material elastic{1.0, 0.0, 0.0};
  const double small_x = wall_face() - kGap - kBulletRadius;
  const Vec2 wide_at{small_x - kBulletRadius - 0.01 - kWideRadius, 0.0};
  scene.bodies.push_back(SceneBody{scenes::make_static_box(kWallThickness, 4.0, {kWallX, 0.0}), Material{}, "wall"});
  scene.bodies.push_back(SceneBody{Body(kMass, kBulletRadius, {small_x, 0.0}, {0.0, 0.0}), elastic, "small"});
  scene.bodies.push_back(SceneBody{Body(kMass, kWideRadius, wide_at, {kSpeed, 0.0}), elastic, "wide"});
  add_spectators(scene);
  // The wide disk moves less than its sweep reach in a substep (a fraction
  // of its and the wall's half-widths): it is never swept itself.
  const double substep = scene.settings.dt / scene.settings.substeps;
  EXPECT_LT(kSpeed * substep, scene.settings.toi_displacement_fraction * (kWideRadius + 0.5 * kWallThickness));
  World world = make_world(scene);
  const BodyId small = world.body_ids()[1];
  double worst = -1e300;
  for (int f = 0; f < 3; ++f)
  {
    const StepReport report = world.step();
    totals.swept_bodies += report.swept_bodies;
    totals.toi_clamps += report.toi_clamps;
    worst = std::max(worst, front(world.body(small)) - wall_face());
  }
  return worst;
}

TEST(ExtremesSpeed, SoftStepSweepsABodyOnlyAContactMakesFast)
{
  StepReport swept;
  const double overshoot = small_disk_launched_at_the_wall(Toggle::Auto, swept);
  const double bound = WorldSettings().slop + kTouchSlack;
  EXPECT_LE(overshoot, bound);
  EXPECT_GT(swept.swept_bodies, 0u);
  EXPECT_GT(swept.toi_clamps, 0u);
  test::print_figure("small disk launched at a thin wall, soft step, toi Auto: overshoot (m)", overshoot, bound);
  // The control: without the sweep the small disk passes the wall.
  StepReport none;
  const double tunnelled = small_disk_launched_at_the_wall(Toggle::Off, none);
  EXPECT_GT(tunnelled, kWallThickness);
  std::printf("the same with toi Off: overshoot %.4g m (expected past the wall)\n", tunnelled);
}

TEST(ExtremesSpeed, SoftStepSweepsAFreeBodyFromTheSubstepItTurnsFast)
{
  // A disk falling far from a box that rests on the ground: its speed
  // crosses its sweep reach per substep within the first frame under gravity
  // alone. Each substep it counts as swept when its move exceeds its reach
  // (the fraction of its and the thinnest body's inner radii), whether or
  // not a contact touches it.
  constexpr double kRadius = 0.1;  // m, the thinnest body: the disk itself
  Scene scene;
  const double substep = scene.settings.dt / scene.settings.substeps;
  const double reach = scene.settings.toi_displacement_fraction * (kRadius + kRadius);
  const double kick = -scene.settings.gravity.y * substep;  // m/s a substep
  const double start_speed = reach / substep - 1.5 * kick;  // fast from the second substep
  scene.bodies.push_back(SceneBody{scenes::make_static_box(20.0, 2.0, {0.0, -1.0}), Material{}, "ground"});
  scene.bodies.push_back(SceneBody{scenes::make_box(1.0, 2.0, 2.0, {0.0, 1.0}), Material{}, "box"});
  scene.bodies.push_back(SceneBody{Body(1.0, kRadius, {500.0, 1000.0}, {0.0, -start_speed}), Material{}, "disk"});
  add_spectators(scene);
  World world = make_world(scene);
  std::size_t expected = 0;
  for (int k = 0; k < scene.settings.substeps; ++k)
  {
    const double move = (start_speed + (k + 1) * kick) * substep;  // after the substep's kick
    expected += move > reach ? 1 : 0;
  }
  ASSERT_GT(expected, 0u);
  ASSERT_LT(expected, static_cast<std::size_t>(scene.settings.substeps));
  const StepReport report = world.step();
  EXPECT_EQ(report.swept_bodies, expected);
  std::printf("disk turning fast under gravity: %zu of %d substeps swept (expected %zu)\n", report.swept_bodies,
              scene.settings.substeps, expected);
}

TEST(ExtremesSpeed, SpinningBodiesInContactSolveFinite)
{
  // Two boxes spinning at +-1e4 rad/s, overlapping: one solve and one step.
  for (double e : {0.0, 1.0})
  {
    std::vector<Body> bodies = {scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.0}, 0.0, {}, kSpin),
                                scenes::make_box(1.0, 1.0, 1.0, {0.99, 0.1}, 0.0, {}, -kSpin)};
    const double before = test::total_kinetic_energy(bodies);
    const Vec2 p_before = test::total_momentum(bodies);
    const double l_before = test::total_angular_momentum(bodies);
    // solve only: position correction moves bodies, which changes the
    // angular momentum about the origin.
    const SolveReport report = ContactSolver(e, 0.5).solve(bodies, ContactSolver::detect_contacts(bodies));
    ASSERT_TRUE(test::all_finite(bodies));
    const double scale = kSpin;  // momentum scale: I w ~ 1e4 / 6, m v ~ r w
    EXPECT_LE(length(test::total_momentum(bodies) - p_before), 1e-12 * scale);
    EXPECT_NEAR(test::total_angular_momentum(bodies), l_before, 1e-12 * scale);
    EXPECT_LE(report.kinetic_energy_after, before * (1.0 + 1e-12)) << "e " << e;
    std::printf("boxes spinning at +-1e4 rad/s, e = %.0f: energy %.6g -> %.6g J, %d sweeps, residual %.3g\n", e,
                before, report.kinetic_energy_after, report.iterations, report.max_residual);
    ContactSolver(e, 0.5).step(bodies);
    EXPECT_TRUE(test::all_finite(bodies));
  }
}

}  // namespace
}  // namespace collision2d
