// Impacts, friction, energy and tunnelling in the stepped world, each checked
// against its closed-form physics: Newton rebound height, Coulomb on an
// incline and on a tilting platform, energy of an elastic gas, a bullet
// against a thin wall, free bodies' centre of mass moving with their momentum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
using test::kinetic_energy;

constexpr double kPi = 3.14159265358979323846;

TEST(WorldDynamics, DroppedDiskReboundsToESquaredOfItsDropHeight)
{
  constexpr double kE = 0.8;
  constexpr double kRadius = 0.25;     // m
  constexpr double kDropHeight = 2.0;  // m, from touching to the disk's bottom
  WorldSettings settings;
  // The rebound is resolved to within the substep: its height error is of
  // order g h / v_impact, so this test asks for h = 1/960 s.
  settings.substeps = 16;
  World world(settings);
  const Material bouncy{kE, 0.0, 0.0};
  world.add_body(scenes::make_static_box(10.0, 1.0, {0.0, -0.5}), bouncy);  // top face at y = 0
  const BodyId disk = world.add_body(Body(1.0, kRadius, {0.0, kRadius + kDropHeight}, {0.0, 0.0}), bouncy);
  constexpr int kMaxFrames = 240;  // 4 s: the drop and the rebound take under 2 s
  const double apex = test::first_rebound_apex(world, disk, kMaxFrames);
  ASSERT_TRUE(std::isfinite(apex)) << "the disk did not bounce";
  const double rebound = apex - kRadius;
  std::printf("rebound %.5f m of a %.1f m drop: ratio %.5f, e^2 = %.5f\n", rebound, kDropHeight, rebound / kDropHeight,
              kE * kE);
  EXPECT_NEAR(rebound / kDropHeight, kE * kE, 0.01 * kE * kE);
}

/// Speed along the downhill direction of the incline scene's slab.
double downhill_speed(const Body& box, double angle)
{
  return -dot(box.velocity(), Vec2{std::cos(angle), std::sin(angle)});
}

TEST(WorldDynamics, BoxOnInclineStaysPutBelowStaticFriction)
{
  const double angle = 0.4;  // tan = 0.423 < mu_s
  const double mu_s = 0.5;
  ASSERT_LT(std::tan(angle), mu_s);
  World world = make_world(scenes::incline(angle, mu_s, 0.3));
  const BodyId box = world.body_ids().back();
  world.step();  // settle onto the slop
  const Vec2 settled = world.body(box).position();
  world.step(600);
  const double moved = length(world.body(box).position() - settled);
  std::printf("incline below mu_s: moved %.3g m in 10 s\n", moved);
  EXPECT_LT(moved, world.settings().slop);
}

// The tilt at which a box on a kinematic platform turning at `omega`, both
// starting level and turning together, first slips faster than kSlip
// relative to the platform's surface under it (rad; -1 if it never does).
double slip_tilt(bool soft_step, double mu, double omega)
{
  constexpr double kSlip = 1e-3;        // m/s
  constexpr int kSettleFrames = 30;     // the first half second carries it along
  constexpr double kLastTilt = 1.2;     // rad, past any friction angle asked here
  WorldSettings settings;
  settings.soft_step = soft_step;
  settings.sleeping = Toggle::Off;
  World world(settings);
  const Material material{0.0, mu, mu};
  Body platform = scenes::make_box(1.0, 10.0, 0.5, Vec2{0.0, 0.0}, 0.0, Vec2{}, omega);
  platform.set_type(BodyType::Kinematic);
  const BodyId p = world.add_body(platform, material);
  // On the platform's top face at its centre, moving with it.
  const BodyId b = world.add_body(scenes::make_box(1.0, 0.5, 0.5, Vec2{0.0, 0.5}, 0.0, Vec2{-0.5 * omega, 0.0}, omega),
                                  material);
  for (int frame = 0; world.body(p).theta() < kLastTilt; ++frame)
  {
    world.step();
    const Body& pl = world.body(p);
    const Body& box = world.body(b);
    const Vec2 r = box.position() - pl.position();
    const Vec2 surface_velocity{-pl.omega() * r.y, pl.omega() * r.x};
    const Vec2 along{std::cos(pl.theta()), std::sin(pl.theta())};
    if (frame > kSettleFrames && std::abs(dot(box.velocity() - surface_velocity, along)) > kSlip)
    {
      return pl.theta();
    }
  }
  return -1.0;
}

TEST(WorldDynamics, BoxOnATiltingPlatformSlipsAtTheFrictionAngle)
{
  // Coulomb: a box held by friction slips once tan(tilt) exceeds mu_s. Here
  // the platform and the box turn together, so the pair hardly moves relative
  // to each other: a contact normal kept from an earlier frame would not turn
  // with them and would hold the box past its angle.
  constexpr double kOmega = 0.05;                   // rad/s: 0.05 degree a frame
  constexpr double kTolerance = 1.0 * kPi / 180.0;  // rad
  for (const bool soft_step : {true, false})
  {
    for (const double mu : {0.1, 0.3, 0.6, 1.0})
    {
      const double tilt = slip_tilt(soft_step, mu, kOmega);
      std::printf("%s mu %.1f: slipped at %.2f degrees, atan(mu) %.2f\n", soft_step ? "soft step" : "Fx2D", mu,
                  tilt * 180.0 / kPi, std::atan(mu) * 180.0 / kPi);
      EXPECT_NEAR(tilt, std::atan(mu), kTolerance) << (soft_step ? "soft step" : "Fx2D") << ", mu " << mu;
    }
  }
}

TEST(WorldDynamics, BoxOnInclineSlidesWithKineticFriction)
{
  const double angle = 0.6;  // tan = 0.684 > mu_s
  const double mu_s = 0.5;
  const double mu_k = 0.3;
  ASSERT_GT(std::tan(angle), mu_s);
  const Scene scene = scenes::incline(angle, mu_s, mu_k);
  World world = make_world(scene);
  const BodyId box = world.body_ids().back();
  const double g = length(scene.settings.gravity);
  const double expected = g * (std::sin(angle) - mu_k * std::cos(angle));
  world.step(30);  // past the start of the slide
  const double v0 = downhill_speed(world.body(box), angle);
  const double t0 = world.time();
  world.step(60);
  const double v1 = downhill_speed(world.body(box), angle);
  const double measured = (v1 - v0) / (world.time() - t0);
  std::printf("incline above mu_s: a = %.5f m/s^2, g (sin - mu_k cos) = %.5f\n", measured, expected);
  EXPECT_NEAR(measured, expected, 0.01 * expected);
  // Slides flat, does not tip: friction's torque compresses the soft step's
  // contact springs unevenly, which tilts the box by a few 1e-5 rad.
  constexpr double kTipTolerance = 1e-4;  // rad
  EXPECT_NEAR(world.body(box).theta(), angle, kTipTolerance);
}

/// Relative change of the kinetic energy of a 300-disk elastic gas over 5 s.
double gas_energy_change(bool soft_step, int velocity_iterations)
{
  Scene gas = scenes::elastic_gas(300, 11);
  gas.settings.soft_step = soft_step;
  gas.settings.velocity_iterations = velocity_iterations;
  World world = make_world(gas);
  const double before = kinetic_energy(world);
  world.step(300);
  const double after = kinetic_energy(world);
  std::printf("elastic gas, %s, %d iterations: kinetic energy %.6g -> %.6g J (relative change %.3g)\n",
              soft_step ? "soft step" : "Fx2D", velocity_iterations, before, after, (after - before) / before);
  return std::abs(after - before) / before;
}

TEST(WorldDynamics, ElasticFrictionlessGasKeepsItsEnergy)
{
  // Fx2D: position correction never touches velocities and every e = 1
  // impact has a fixed Newton target, so the energy lost is that of
  // simultaneous impacts (a disk hitting two others) left short of their
  // targets by too few Gauss-Seidel passes: about 0.7% over 5 s with the
  // default 2, nothing measurable with 10.
  EXPECT_LT(gas_energy_change(false, WorldSettings().velocity_iterations), 0.02);
  EXPECT_LT(gas_energy_change(false, 10), 1e-6);
  // The soft step bounces at the end of each substep, every point the
  // substep pushed ending at e times its speed at the substep's start: with
  // e = 1 that keeps the energy to round-off, however the disks meet.
  EXPECT_LT(gas_energy_change(true, WorldSettings().velocity_iterations), 1e-10);
}

TEST(WorldDynamics, BulletDoesNotTunnelThroughThinWall)
{
  // The Fx2D pipeline detects every substep, so without the sweep the
  // bullet skips the wall; the soft step's frame-long speculative contacts
  // stop it either way (WorldSoftStep.BulletDoesNotTunnel).
  Scene scene = scenes::bullet_wall(500.0);
  scene.settings.soft_step = false;
  const auto run = [&](Toggle toi, StepReport& report) {
    Scene s = scene;
    s.settings.time_of_impact = toi;
    World world = make_world(s);
    report = world.step(60);
    return world;
  };
  const double wall_left = scene.bodies[0].body.aabb().lo.x;
  const double wall_right = scene.bodies[0].body.aabb().hi.x;
  const double radius = scene.bodies[1].body.radius();

  StepReport with_report;
  const World with_toi = run(Toggle::Auto, with_report);
  const Body& stopped = with_toi.body(with_toi.body_ids().back());
  EXPECT_TRUE(with_report.active.time_of_impact);
  EXPECT_GT(with_report.toi_clamps, 0u);
  EXPECT_LE(stopped.position().x + radius, wall_left + with_toi.settings().slop);

  // The same scene without the sweep: the bullet skips over the wall, which
  // shows the check above can fail.
  StepReport without_report;
  const World without = run(Toggle::Off, without_report);
  EXPECT_FALSE(without_report.active.time_of_impact);
  EXPECT_GT(without.body(without.body_ids().back()).position().x - radius, wall_right);
}

// A disk strikes rough level ground (e = 0, mu = 0.5, no gravity). Every
// impulse acts at its bottom point, so its angular momentum about that
// point, I omega - m R v_x, keeps its value. In closed form (J_n = m |v_y|):
// friction up to mu J_n either brings it to rolling, v_x = 2/3 of its speed
// along the ground (a solid disk), or takes mu J_n off that speed and gives
// it a spin of 2 mu J_n / (m R). The soft step finds the contact up to a
// frame's travel ahead, its point midway across the gap; friction used to
// act there, the arm as long as half that gap: at 30 m/s along and 60 m/s
// down the disk kept 29.9 m/s (20 in closed form), spun 10 times as fast as
// its friction impulse turns it by its radius, and slid on.
// (The Fx2D order, its hashes pinned, keeps the midway point: at 3 m/s
// along and 6 down its disk ends at 1.59 m/s, rolling faster than it moves.)
TEST(WorldDynamics, DiskStrikingRoughGroundKeepsAngularMomentumAboutItsContact)
{
  constexpr double kRadius = 0.05;    // m
  constexpr double kMu = 0.5;
  constexpr double kFlight = 0.1;     // s before it meets the ground
  constexpr double kTolerance = 1e-9;  // relative
  const Material rough{0.0, kMu, kMu};
  for (const Vec2 v : {Vec2{3.0, -6.0}, Vec2{30.0, -60.0}, Vec2{300.0, -600.0}, Vec2{30.0, -3.0}, Vec2{-20.0, -5.0}})
  {
    SCOPED_TRACE("disk at (" + std::to_string(v.x) + ", " + std::to_string(v.y) + ") m/s");
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};
    World world(settings);
    world.add_body(scenes::make_static_box(1e4, 1.0, {0.0, -0.5}), rough);  // top face at y = 0
    const BodyId id = world.add_body(Body(1.0, kRadius, {-kFlight * v.x, kRadius - kFlight * v.y}, v), rough);
    const Body& disk = world.body(id);
    const double m = disk.mass();
    const auto about_contact = [&] { return disk.inertia() * disk.omega() - m * kRadius * disk.velocity().x; };
    const double before = about_contact();
    double worst = 0.0;
    for (int f = 0; f < 20; ++f)
    {
      world.step();
      worst = std::max(worst, std::abs(about_contact() - before));
    }
    const double friction = kMu * m * std::abs(v.y);
    const bool rolls = friction >= m * std::abs(v.x) / 3.0;
    const double along = rolls ? 2.0 / 3.0 * v.x : v.x - std::copysign(friction / m, v.x);
    const double rim = rolls ? -along : -std::copysign(2.0 * friction / m, v.x);  // omega R
    std::printf("disk at (%g, %g) m/s: angular momentum about the contact, change / before %.3g (bound %.0e)\n", v.x,
                v.y, worst / std::abs(before), kTolerance);
    EXPECT_LE(worst, kTolerance * std::abs(before)) << "friction acted away from the disk's rim";
    EXPECT_NEAR(disk.velocity().x, along, kTolerance * std::abs(v.x));
    EXPECT_NEAR(disk.omega() * kRadius, rim, kTolerance * std::abs(v.x));
    EXPECT_NEAR(disk.velocity().y, 0.0, kTolerance * std::abs(v.y));
  }
}

TEST(WorldDynamics, FreeBodiesCentreOfMassMovesWithTheirMomentumWithTimeOfImpactOn)
{
  // Free bodies without gravity: contacts exchange momentum in pairs, so the
  // centre of mass moves at P / M. A spinning triangle chases three disks
  // that start on one centre; with time of impact On the soft step swept
  // their pair though its speculative contact already held it, and the
  // translation-only sweep, blind to the spin, stopped both short every
  // substep: they crawled for 100 frames at a fraction of their velocity.
  constexpr int kFrames = 180;
  for (const bool soft_step : {false, true})
  {
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};
    settings.soft_step = soft_step;
    settings.sleeping = Toggle::Off;
    settings.time_of_impact = Toggle::On;
    World world(settings);
    const auto triangle = [](double h) { return std::vector<Vec2>{{-h, -h}, {h, -h}, {0.0, h}}; };
    world.add_body(Body(4.5, triangle(0.25), {0.75, -0.5}, {-0.75, -0.25}, kPi / 2));
    world.add_body(Body(0.5, triangle(0.5), {-0.5, -0.25}, {-1.75, -1.75}));
    for (int k = 0; k < 3; ++k)
    {
      world.add_body(Body(0.5, 0.125, {-1.0, -1.0}, {-1.75, -1.75}));
    }
    // The mass-weighted mean of a body quantity: centre of mass, momentum / mass.
    const auto mass_mean = [&world](auto quantity) {
      Vec2 sum{0.0, 0.0};
      double mass = 0.0;
      for (BodyId id : world.body_ids())
      {
        sum = sum + quantity(world.body(id)) * world.body(id).mass();
        mass += world.body(id).mass();
      }
      return sum / mass;
    };
    const auto position = [](const Body& b) { return b.position(); };
    const auto velocity = [](const Body& b) { return b.velocity(); };
    const Vec2 expected = mass_mean(position) + mass_mean(velocity) * (kFrames * settings.dt);
    double deepest = 0.0;
    for (int frame = 0; frame < kFrames; ++frame)
    {
      const StepReport report = world.step();
      deepest = frame >= 60 ? std::max(deepest, report.max_penetration) : deepest;
    }
    const Vec2 off = mass_mean(position) - expected;
    EXPECT_LT(length(off), 1e-9) << (soft_step ? "soft step" : "Fx2D") << ": the centre of mass lags by " << length(off)
                                 << " m";
    EXPECT_LT(deepest, 0.01) << (soft_step ? "soft step" : "Fx2D") << ": overlap after the first second";
  }
}

TEST(WorldDynamics, ReportedKineticEnergyIsTheDynamicBodiesSumForAnyWorkers)
{
  // Enough moving disks that the workers share the sum; a spinning kinematic
  // disk has energy the report leaves out. The report sums blocks of 512
  // bodies in order, each in body order: the same bits for any worker count.
  constexpr std::size_t kBlock = 512;
  Scene scene = scenes::elastic_gas(3000);
  Body spinner(1.0, 0.5, Vec2{0.0, 0.0}, Vec2{1.0, 0.0});
  spinner.set_type(BodyType::Kinematic);
  spinner.set_omega(3.0);
  scene.bodies.push_back(SceneBody{spinner, Material{}, "spinner"});
  constexpr int kFrames = 5;
  std::vector<double> one_worker;
  for (int workers : {1, 2, 4})
  {
    scene.settings.workers = workers;
    World world = make_world(scene);
    for (int f = 0; f < kFrames; ++f)
    {
      const StepReport report = world.step();
      double sum = 0.0;
      double block = 0.0;
      const std::vector<BodyId> ids = world.body_ids();
      for (std::size_t k = 0; k < ids.size(); ++k)
      {
        const Body& b = world.body(ids[k]);
        block += b.type() == BodyType::Dynamic ? b.kinetic_energy() : 0.0;
        if ((k + 1) % kBlock == 0 || k + 1 == ids.size())
        {
          sum += block;
          block = 0.0;
        }
      }
      EXPECT_EQ(report.kinetic_energy, sum) << workers << " workers, frame " << f;
      if (workers == 1)
      {
        one_worker.push_back(report.kinetic_energy);
      }
      else
      {
        EXPECT_EQ(report.kinetic_energy, one_worker[static_cast<std::size_t>(f)]) << workers << " workers, frame " << f;
      }
    }
  }
  EXPECT_GT(one_worker.back(), 0.0);
}

}  // namespace
}  // namespace collision2d
