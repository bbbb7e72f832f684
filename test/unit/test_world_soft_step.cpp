// The soft step (WorldSettings::soft_step) checked against closed-form
// physics: momentum and Newton's rule in a free impact, the rebound of a
// dropped disk, Coulomb on an incline, stacks that stand, no tunnelling, and
// snapshots that resume it bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
WorldSettings soft(WorldSettings s = WorldSettings())
{
  s.soft_step = true;
  return s;
}

World soft_world(Scene scene)
{
  scene.settings.soft_step = true;
  scene.settings.sleeping = Toggle::Off;
  return make_world(scene);
}

TEST(WorldSoftStep, FreeImpactKeepsMomentumAndMeetsNewtonsRule)
{
  // Two disks closing at 7 m/s, e = 0.6, no gravity: after the frame of the
  // impact the closing speed is reversed and scaled by e, momentum unchanged.
  WorldSettings settings = soft();
  settings.gravity = Vec2{0.0, 0.0};
  World world(settings);
  const Material material{0.6, 0.0, 0.0};
  const BodyId a = world.add_body(Body(2.0, 0.5, {0.0, 0.0}, {4.0, 0.0}), material);
  const BodyId b = world.add_body(Body(1.0, 0.5, {1.2, 0.0}, {-3.0, 0.0}), material);
  const double momentum_before = 2.0 * 4.0 + 1.0 * -3.0;
  double closing = 7.0;
  for (int frame = 0; frame < 30 && closing > 0.0; ++frame)
  {
    world.step();
    closing = world.body(a).velocity().x - world.body(b).velocity().x;
  }
  const double momentum_after = 2.0 * world.body(a).velocity().x + 1.0 * world.body(b).velocity().x;
  EXPECT_NEAR(momentum_after, momentum_before, 1e-12);
  EXPECT_NEAR(-closing, 0.6 * 7.0, 1e-9) << "separation speed after the impact";
}

TEST(WorldSoftStep, DroppedDiskReboundsWithItsRestitution)
{
  // Speeds just before and just after the bounce frame: their ratio is e up
  // to the gravity of that one frame (g dt against the impact speed).
  constexpr double kE = 0.8;
  constexpr double kRadius = 0.25;     // m
  constexpr double kDropHeight = 2.0;  // m
  World world(soft());
  const Material bouncy{kE, 0.0, 0.0};
  world.add_body(scenes::make_static_box(10.0, 1.0, {0.0, -0.5}), bouncy);
  const BodyId disk = world.add_body(Body(1.0, kRadius, {0.0, kRadius + kDropHeight}, {0.0, 0.0}), bouncy);
  double before = 0.0;
  double after = 0.0;
  for (int frame = 0; frame < 240; ++frame)
  {
    const double v = world.body(disk).velocity().y;
    world.step();
    if (world.body(disk).velocity().y > 0.0)
    {
      before = v;
      after = world.body(disk).velocity().y;
      break;
    }
  }
  ASSERT_LT(before, 0.0) << "the disk did not bounce";
  const double g_dt = 9.81 * world.settings().dt;
  const double measured = after / -before;
  std::printf("impact %.5f m/s, rebound %.5f m/s: e measured %.6f (e = %.1f, g dt / v = %.2g)\n", -before, after,
              measured, kE, g_dt / -before);
  EXPECT_NEAR(measured, kE, 1.5 * g_dt / -before);
}

TEST(WorldSoftStep, InclineSticksBelowAndSlidesAboveTheFrictionAngle)
{
  World still = soft_world(scenes::incline(0.4, 0.5, 0.3));
  const BodyId box = still.body_ids().back();
  still.step(60);
  const Vec2 settled = still.body(box).position();
  still.step(600);
  EXPECT_LT(std::sqrt(length_sq(still.body(box).position() - settled)), 1e-4) << "creep below tan = mu_s";

  const double angle = 0.6;
  World sliding = soft_world(scenes::incline(angle, 0.5, 0.3));
  const BodyId slider = sliding.body_ids().back();
  const Vec2 downhill{-std::cos(angle), -std::sin(angle)};
  sliding.step(30);
  const double v0 = dot(sliding.body(slider).velocity(), downhill);
  sliding.step(60);
  const double acceleration = (dot(sliding.body(slider).velocity(), downhill) - v0) / 1.0;
  const double expected = 9.81 * (std::sin(angle) - 0.3 * std::cos(angle));
  std::printf("incline acceleration %.9f m/s^2, g (sin - mu_k cos) = %.9f\n", acceleration, expected);
  EXPECT_NEAR(acceleration, expected, 1e-6);
}

TEST(WorldSoftStep, InclineHoldsUpToTheFrictionAngleAtAnySubsteps)
{
  // While its contacts first compress the box rocks on its corners, and its
  // friction meets the static bound for a frame. That must not latch the
  // kinetic cone (mu_k < tan(angle) could never stop it): at rest, the last
  // substep's impulses carry exactly the box's weight, inside the static
  // cone. The friction angle is atan(0.5) = 0.4636 rad; one substep holds to
  // 0.45, two and more to 0.46, and 0.47 slides at g (sin - mu_k cos).
  const double mu_s = 0.5;
  const double mu_k = 0.3;
  const struct
  {
    double angle;
    int substeps;
    bool holds;
  } runs[] = {{0.4, 1, true}, {0.4, 2, true}, {0.4, 4, true}, {0.45, 1, true}, {0.46, 2, true},
              {0.46, 4, true}, {0.47, 1, false}, {0.47, 2, false}, {0.47, 4, false}};
  for (const auto& run : runs)
  {
    Scene scene = scenes::incline(run.angle, mu_s, mu_k);
    scene.settings.substeps = run.substeps;
    World world = soft_world(scene);
    const BodyId box = world.body_ids().back();
    const Vec2 start = world.body(box).position();
    const Vec2 downhill{-std::cos(run.angle), -std::sin(run.angle)};
    world.step(30);
    const double v0 = dot(world.body(box).velocity(), downhill);
    world.step(60);
    const double acceleration = dot(world.body(box).velocity(), downhill) - v0;  // over 1 s
    if (!run.holds)
    {
      const double expected = 9.81 * (std::sin(run.angle) - mu_k * std::cos(run.angle));
      std::printf("angle %.2f, %d substeps: slides at %.9f m/s^2, g (sin - mu_k cos) = %.9f\n", run.angle,
                  run.substeps, acceleration, expected);
      EXPECT_NEAR(acceleration, expected, 1e-6) << run.angle;
      continue;
    }
    world.step(210);
    const Vec2 at_5s = world.body(box).position();
    world.step(300);
    const Body& b = world.body(box);
    const double h = scene.settings.dt / run.substeps;
    const double weight = b.mass() * length(scene.settings.gravity) * h;  // N s per substep
    double normal = 0.0;
    double tangent = 0.0;
    for (const WorldContact& c : world.contacts())
    {
      normal += c.impulse.normal;
      tangent += c.impulse.tangent;
    }
    const double moved = length(b.position() - start);
    const double creep = length(b.position() - at_5s);
    std::printf("angle %.2f, %d substeps: moved %.3g m in 10 s (%.3g m after 5 s), impulses n %.9f t %.9f "
                "(weight cos %.9f, sin %.9f)\n",
                run.angle, run.substeps, moved, creep, normal, tangent, weight * std::cos(run.angle),
                weight * std::sin(run.angle));
    EXPECT_LT(moved, 1e-3) << run.angle << " rad, " << run.substeps << " substeps: the box slid";
    EXPECT_LT(creep, 1e-9) << run.angle << " rad, " << run.substeps << " substeps: the box creeps";
    EXPECT_NEAR(normal, weight * std::cos(run.angle), 1e-6 * weight) << run.angle << ", " << run.substeps;
    EXPECT_NEAR(std::abs(tangent), weight * std::sin(run.angle), 1e-6 * weight) << run.angle << ", " << run.substeps;
    EXPECT_LE(std::abs(tangent), mu_s * normal) << "inside the static cone";
  }
}

TEST(WorldSoftStep, TwentyBoxColumnStands)
{
  World world = soft_world(scenes::column(20));
  world.step(60);
  const std::vector<Vec2> settled = test::positions(world);
  double deepest = 0.0;
  for (int frame = 0; frame < 540; ++frame)
    deepest = std::max(deepest, world.step().max_penetration);
  const double moved = test::largest_move(world, settled, test::positions(world));
  std::printf("column: drift 1 s -> 10 s %.3g m, deepest %.3g m\n", moved, deepest);
  EXPECT_LT(moved, 1e-3);
  EXPECT_LT(deepest, 0.02) << "the contacts' springs carry the column's weight";
}

/// A 20-box column stepped 1 s to settle, then 4 s more with `tune` applied
/// to its settings.
struct ColumnRest
{
  double drift = 0.0;    ///< largest move of a box from 1 s to 5 s (m)
  double deepest = 0.0;  ///< deepest contact in the frame after (m)
};

template <class Tune>
ColumnRest rest_column(Tune tune)
{
  Scene scene = scenes::column(20);
  tune(scene.settings);
  World world = soft_world(scene);
  world.step(60);
  const std::vector<Vec2> settled = test::positions(world);
  world.step(240);
  ColumnRest rest;
  rest.drift = test::largest_move(world, settled, test::positions(world));
  rest.deepest = world.step().max_penetration;
  return rest;
}

/// How deep the column's lowest box-box contact rests on a spring of
/// `hertz`: the 19 boxes' weight over m_rel omega^2, m_rel the two boxes'
/// reduced mass.
double column_spring_depth(double hertz)
{
  const World reference = soft_world(scenes::column(20));
  const double mass = reference.body(reference.body_ids().back()).mass();
  const double g = length(reference.settings().gravity);
  const double omega = 2.0 * M_PI * hertz;
  return 19.0 * mass * g / (0.5 * mass * omega * omega);
}

TEST(WorldSoftStep, MorePassesHoldAColumnAtTheStiffestContacts)
{
  // At 60 Hz (the cap at 4 substeps) one solve and one relax pass a substep
  // leave the column's weight bouncing between its contacts; four carry it
  // down each substep. Either way the lowest box-box contact rests as deep
  // as its spring needs.
  constexpr double kHertz = 60.0;
  const auto at_passes = [&](int passes) {
    return rest_column([&](WorldSettings& s) {
      s.contact_hertz = kHertz;
      s.soft_iterations = passes;
    });
  };
  const ColumnRest one = at_passes(1);
  const ColumnRest four = at_passes(4);
  const double spring_depth = column_spring_depth(kHertz);
  std::printf("column at %g Hz, drift 1 s -> 5 s: 1 pass %.3g m, 4 passes %.3g m; deepest %.4g / %.4g m, "
              "spring %.4g m\n", kHertz, one.drift, four.drift, one.deepest, four.deepest, spring_depth);
  EXPECT_LT(four.drift, 1e-5);
  EXPECT_GT(one.drift, 10.0 * four.drift) << "the passes were not run";
  EXPECT_NEAR(four.deepest, spring_depth, 0.01 * spring_depth);
}

TEST(WorldSoftStep, MoreSubstepsRaiseTheStiffnessCap)
{
  // The tall-stack setting asks for 90 Hz: 4 substeps of a 60 Hz frame cap a
  // contact at a quarter of their rate (60 Hz), 6 substeps allow all of it.
  // The lowest box-box contact's depth shows which stiffness acted.
  constexpr double kAskedHertz = 90.0;
  const auto at_substeps = [&](int substeps) {
    return rest_column([&](WorldSettings& s) {
      s.substeps = substeps;
      s.contact_hertz = kAskedHertz;
      s.contact_damping_ratio = 15.0;
      s.soft_iterations = 2;
    });
  };
  const ColumnRest four = at_substeps(4);
  const ColumnRest six = at_substeps(6);
  const double cap4 = 0.25 * 4.0 / scenes::column(20).settings.dt;  // Hz
  std::printf("column asking %g Hz: 4 substeps deepest %.4g m (spring at %g Hz %.4g m), 6 substeps %.4g m "
              "(spring %.4g m); drift 1 s -> 5 s %.3g / %.3g m\n",
              kAskedHertz, four.deepest, cap4, column_spring_depth(cap4), six.deepest,
              column_spring_depth(kAskedHertz), four.drift, six.drift);
  EXPECT_NEAR(four.deepest, column_spring_depth(cap4), 0.01 * column_spring_depth(cap4));
  EXPECT_NEAR(six.deepest, column_spring_depth(kAskedHertz), 0.01 * column_spring_depth(kAskedHertz));
  EXPECT_LT(six.drift, 1e-5);
}

TEST(WorldSoftStep, PyramidBoxesStayLevelOnTheirAnchors)
{
  // Velocity-only friction lets each contact slip by round-off every pass,
  // and a pyramid's boxes tilt as the slips add up (1.5e-3 rad in 10 s);
  // pulled back to where they stuck, they stay level.
  World world = soft_world(scenes::pyramid(20));
  world.step(600);
  double tilt = 0.0;
  for (BodyId id : world.body_ids())
  {
    tilt = std::max(tilt, std::abs(std::remainder(world.body(id).theta(), 0.5 * M_PI)));
  }
  constexpr double kLevel = 5e-4;  // rad
  std::printf("base-20 pyramid after 10 s: largest tilt %.3g rad\n", tilt);
  EXPECT_LT(tilt, kLevel);
}

TEST(WorldSoftStep, SymmetricPyramidSettlesAsItsMirrorImage)
{
  // Gravity, the contacts and friction are mirror symmetric, so each box of a
  // symmetric pyramid should move as the mirror image of its partner while
  // the stack settles. What can break the symmetry is the order of the
  // solve: coloured in body index order, the pyramid leaned left and right
  // by centimetres in its first second.
  World world = soft_world(scenes::pyramid(20));
  const std::vector<Vec2> start = test::positions(world);
  std::vector<std::size_t> mirror(start.size(), SIZE_MAX);
  for (std::size_t i = 0; i < start.size(); ++i)
  {
    for (std::size_t j = 0; j < start.size(); ++j)
    {
      if (std::abs(start[i].x + start[j].x) < 1e-9 && std::abs(start[i].y - start[j].y) < 1e-9)
      {
        mirror[i] = j;
      }
    }
  }
  double worst = 0.0;
  for (int frame = 0; frame < 60; ++frame)
  {
    world.step();
    const std::vector<Vec2> now = test::positions(world);
    for (std::size_t i = 0; i < now.size(); ++i)
    {
      if (mirror[i] != SIZE_MAX)
      {
        const Vec2 m = now[mirror[i]];
        worst = std::max({worst, std::abs(now[i].x + m.x), std::abs(now[i].y - m.y)});
      }
    }
  }
  constexpr double kAsymmetry = 2e-3;  // m
  std::printf("base-20 pyramid, first second: largest departure from mirror symmetry %.3g m\n", worst);
  EXPECT_EQ(std::count(mirror.begin(), mirror.end(), SIZE_MAX), 0) << "every body has a mirror image";
  EXPECT_LT(worst, kAsymmetry);
}

TEST(WorldSoftStep, ThrownBodyFollowsItsParabola)
{
  // Nothing near it: each substep moves it by its mean velocity, so after t
  // it is at x0 + v0 t + g t^2 / 2 to round-off, whatever the substeps.
  WorldSettings settings = soft();
  World world(settings);
  const Vec2 x0{0.0, 100.0};
  const Vec2 v0{3.0, 12.0};
  const BodyId ball = world.add_body(Body(1.0, 0.1, x0, v0));
  constexpr int kFrames = 90;
  world.step(kFrames);
  const double t = kFrames * settings.dt;
  const Vec2 expected = x0 + t * v0 + (0.5 * t * t) * settings.gravity;
  const double error = length(world.body(ball).position() - expected);
  std::printf("thrown body after %.2f s: %.3g m from its parabola\n", t, error);
  EXPECT_LT(error, 1e-12 * length(expected));
  EXPECT_LT(length(world.body(ball).velocity() - (v0 + t * settings.gravity)), 1e-12 * length(v0));
}

TEST(WorldSoftStep, BulletDoesNotTunnel)
{
  World world = soft_world(scenes::bullet_wall(1e4));
  const BodyId bullet = world.body_ids().back();
  const double wall_x = world.body(world.body_ids().front()).position().x;
  for (int frame = 0; frame < 120; ++frame)
  {
    world.step();
    ASSERT_LT(world.body(bullet).position().x, wall_x) << "frame " << frame;
  }
}

TEST(WorldSoftStep, ExactModeHoldsAMillionKilogramBoxOnALightOneForAMinute)
{
  // The soft passes cannot carry a 1e6 : 1 stack (the heavy box's weight
  // overwhelms the light one's springs); the exact mode solves the island's
  // velocities as one LCP every pass, with a rigid push-out.
  constexpr double kRatio = 1e6;
  Scene scene = scenes::heavy_on_light(kRatio);
  scene.settings.solver_mode = SolverMode::Exact;
  World world = soft_world(scene);
  const std::vector<BodyId> ids = world.body_ids();
  const BodyId light = ids[1];
  const BodyId heavy = ids[2];
  ASSERT_EQ(world.body(heavy).mass(), kRatio * world.body(light).mass());
  world.step(60);
  const std::vector<Vec2> settled = test::positions(world);
  double deepest = 0.0;
  std::size_t solved = 0;
  std::size_t fallbacks = 0;
  for (int frame = 0; frame < 59 * 60; ++frame)
  {
    const StepReport report = world.step();
    deepest = std::max(deepest, report.max_penetration);
    solved += report.exact_islands;
    fallbacks += report.exact_fallbacks;
  }
  const double moved = test::largest_move(world, settled, test::positions(world));
  // Weight over the contacts: the light box carries the heavy one, the ground both.
  const double g = -scene.settings.gravity.y;
  double ground_push = 0.0;
  for (const WorldContact& c : world.contacts())
  {
    ground_push += c.a == ids[0] ? c.impulse.normal : 0.0;
  }
  const double h = scene.settings.dt / scene.settings.substeps;
  const double weight = (1.0 + kRatio) * world.body(light).mass() * g;
  std::printf("1e6 : 1 stack, exact soft step: drift 1 s -> 60 s %.3g m, deepest %.3g m, ground carries %.9g of the weight\n",
              moved, deepest, ground_push / (weight * h));
  EXPECT_LT(moved, 1e-3);
  EXPECT_LT(deepest, 1e-3);
  EXPECT_GT(solved, 0u);
  EXPECT_EQ(fallbacks, 0u);
  EXPECT_NEAR(ground_push / (weight * h), 1.0, 1e-6) << "the last pass's impulse holds the weight over one substep";
}

}  // namespace
}  // namespace collision2d
