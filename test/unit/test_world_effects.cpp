// Model selection: Auto turns on only what a scene needs, switching off an
// effect a scene does not need changes nothing, warm starting saves
// iterations on a resting stack, and sleeping is exactly switchable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"

namespace collision2d
{
namespace
{
/// Largest difference in any pose or velocity component between two worlds
/// holding the same bodies.
double state_difference(const World& a, const World& b)
{
  double worst = 0.0;
  for (BodyId id : a.body_ids())
  {
    const Body& p = a.body(id);
    const Body& q = b.body(id);
    worst = std::max({worst, std::abs(p.position().x - q.position().x), std::abs(p.position().y - q.position().y),
                      std::abs(p.velocity().x - q.velocity().x), std::abs(p.velocity().y - q.velocity().y),
                      std::abs(p.theta() - q.theta()), std::abs(p.omega() - q.omega())});
  }
  return worst;
}

using ToggleField = Toggle WorldSettings::*;

/// Runs `scene` twice, with `field` forced on and off.
double on_off_difference(const Scene& scene, ToggleField field, int frames)
{
  Scene on = scene;
  Scene off = scene;
  on.settings.*field = Toggle::On;
  off.settings.*field = Toggle::Off;
  World a = make_world(on);
  World b = make_world(off);
  a.step(frames);
  b.step(frames);
  return state_difference(a, b);
}

TEST(WorldEffects, AutoModelsOnlyWhatTheSceneNeeds)
{
  World gas = make_world(scenes::elastic_gas(100, 3));
  const ActiveEffects g = gas.step(5).active;
  EXPECT_FALSE(g.rotation);  // frictionless disks
  EXPECT_FALSE(g.friction);
  EXPECT_TRUE(g.restitution);
  EXPECT_FALSE(g.time_of_impact);
  EXPECT_FALSE(g.warm_starting);  // no gravity: no resting contacts
  EXPECT_FALSE(g.sleeping);       // below sleep_auto_min_bodies

  World stack = make_world(scenes::column(5));
  const ActiveEffects s = stack.step(5).active;
  EXPECT_TRUE(s.rotation);  // polygons
  EXPECT_TRUE(s.friction);
  EXPECT_FALSE(s.restitution);  // e = 0
  EXPECT_TRUE(s.position_correction);
  EXPECT_TRUE(s.warm_starting);

  World bullet = make_world(scenes::bullet_wall(500.0));
  EXPECT_TRUE(bullet.step(5).active.time_of_impact);
}

// The bodies' types, shapes and materials are counted again after each edit
// (the counts are kept between edits); a disk's spin whenever it decides.
TEST(WorldEffects, AutoFollowsEditsToTheBodies)
{
  const Material rough{0.0, 0.6, 0.6};
  World world;
  world.add_body(scenes::make_static_box(10.0, 1.0, Vec2{0.0, -0.5}), rough);
  const BodyId disk = world.add_body(Body(1.0, 0.5, Vec2{0.0, 0.5}, Vec2{0.0, 0.0}), rough);
  ActiveEffects a = world.step(3).active;
  EXPECT_TRUE(a.friction);  // a rough disk on rough ground
  EXPECT_TRUE(a.rotation);
  world.set_body_type(disk, BodyType::Static);
  a = world.step(3).active;
  EXPECT_FALSE(a.friction);  // nothing dynamic is rough now
  EXPECT_FALSE(a.rotation);
  const BodyId smooth = world.add_body(Body(1.0, 0.5, Vec2{3.0, 0.5}, Vec2{0.0, 0.0}), Material{});
  EXPECT_FALSE(world.step(3).active.rotation);  // a smooth disk with no spin
  world.set_body_state(smooth, Vec2{3.0, 0.5}, 0.0, Vec2{0.0, 0.0}, 2.0);
  EXPECT_TRUE(world.step(3).active.rotation);  // ... spun
  world.add_body(scenes::make_box(1.0, 1.0, 1.0, Vec2{-3.0, 0.5}), Material{});
  world.set_body_state(smooth, Vec2{3.0, 0.5}, 0.0, Vec2{0.0, 0.0}, 0.0);
  EXPECT_TRUE(world.step(3).active.rotation);  // a dynamic box turns under contacts
}

// A frictionless disk that spins slowly keeps rotation on until it falls
// asleep, which stops it: the spin is counted again each frame, no edit needed.
TEST(WorldEffects, RotationEndsWhenTheOnlySpinningDiskSleeps)
{
  WorldSettings settings;
  settings.sleeping = Toggle::On;
  World world(settings);
  world.add_body(scenes::make_static_box(10.0, 1.0, Vec2{0.0, -0.5}));
  world.add_body(Body(1.0, 0.5, Vec2{0.0, 0.5}, Vec2{0.0, 0.0}, 0.5 * settings.sleep_angular_speed));
  EXPECT_TRUE(world.step().active.rotation);
  int frames = 1;
  while (world.step().sleeping_bodies == 0 && frames < 600)
  {
    ++frames;
  }
  ASSERT_LT(frames, 600) << "the disk never fell asleep";
  EXPECT_FALSE(world.step().active.rotation);
}

TEST(WorldEffects, SwitchingOffUnneededEffectsChangesNothing)
{
  const Scene frictionless = scenes::bouncing_disks(5, 0.8);
  EXPECT_EQ(on_off_difference(frictionless, &WorldSettings::friction, 180), 0.0);
  const Scene inelastic = scenes::pyramid(5);
  EXPECT_EQ(on_off_difference(inelastic, &WorldSettings::restitution, 180), 0.0);
  // Contact impulses on frictionless disks pass through their centres, up to
  // the round-off of the lever arm.
  const Scene gas = scenes::elastic_gas(200, 5);
  EXPECT_LT(on_off_difference(gas, &WorldSettings::rotation, 180), 1e-12);
  EXPECT_LT(on_off_difference(frictionless, &WorldSettings::rotation, 180), 1e-12);
  // Nothing in a resting column moves fast enough to need a sweep: Auto and
  // Off are the same computation.
  Scene column = scenes::column(8);
  World automatic = make_world(column);
  column.settings.time_of_impact = Toggle::Off;
  World off = make_world(column);
  EXPECT_FALSE(automatic.step(120).active.time_of_impact);
  off.step(120);
  EXPECT_EQ(state_difference(automatic, off), 0.0);
}

TEST(WorldEffects, ForcingAnEffectOnShowsInTheReport)
{
  Scene gas = scenes::elastic_gas(50, 2);
  gas.settings.rotation = Toggle::On;
  gas.settings.friction = Toggle::On;
  gas.settings.sleeping = Toggle::On;
  World world = make_world(gas);
  const ActiveEffects a = world.step().active;
  EXPECT_TRUE(a.rotation);
  EXPECT_TRUE(a.friction);
  EXPECT_TRUE(a.sleeping);
}

/// Iterations a resting stack needs, from `settled`, for one frame to end with
/// a velocity residual of at most `tol` (m/s); `cap` + 1 when never.
int iterations_needed(const World& settled, Toggle warm, double tol, int cap)
{
  for (int k = 1; k <= cap; ++k)
  {
    World trial = settled;
    WorldSettings s = trial.settings();
    s.warm_starting = warm;
    s.velocity_iterations = k;
    trial.set_settings(s);
    if (trial.step().velocity_residual <= tol)
    {
      return k;
    }
  }
  return cap + 1;
}

TEST(WorldEffects, WarmStartingNeedsFewerIterationsOnARestingStack)
{
  // Measure: the largest normal-velocity residual over the frame's substeps
  // (StepReport::velocity_residual) after the same number of Gauss-Seidel
  // passes; the stack is settled first so both start from the same state.
  // The Fx2D pipeline: its passes are Gauss-Seidel to a residual.
  Scene column = scenes::column(10);
  column.settings.soft_step = false;
  World world = make_world(column);
  world.step(120);
  constexpr double kTolerance = 1e-4;  // m/s, a tenth of a millimetre per second
  constexpr int kCap = 40;
  const int warm = iterations_needed(world, Toggle::On, kTolerance, kCap);
  const int cold = iterations_needed(world, Toggle::Off, kTolerance, kCap);
  std::printf("column(10) to %.0e m/s: %d iterations warm, %d cold (cap %d)\n", kTolerance, warm, cold, kCap);
  EXPECT_LT(warm, cold);
  EXPECT_LE(warm, kCap);
}

TEST(WorldEffects, SleepingIsExactlySwitchable)
{
  Scene pile = scenes::pyramid(5);
  pile.settings.sleeping = Toggle::On;
  World sleepy = make_world(pile);
  sleepy.step(240);
  std::size_t asleep = 0;
  std::size_t dynamic = 0;
  for (BodyId id : sleepy.body_ids())
  {
    dynamic += sleepy.body(id).type() == BodyType::Dynamic ? 1 : 0;
    asleep += sleepy.is_sleeping(id) ? 1 : 0;
  }
  EXPECT_EQ(asleep, dynamic);
  // Asleep, nothing moves at all.
  const World frozen = sleepy;
  sleepy.step(60);
  EXPECT_EQ(state_difference(sleepy, frozen), 0.0);

  // A disk dropped on the pile wakes it.
  const BodyId top = sleepy.body_ids().back();
  const Vec2 above = sleepy.body(top).position() + Vec2{0.0, 2.0};
  sleepy.add_body(Body(5.0, 0.3, above, {0.0, -5.0}), scenes::rough_material());
  sleepy.step(30);
  EXPECT_FALSE(sleepy.is_sleeping(top));

  // Off: nobody sleeps (Auto is off too for a scene this small).
  pile.settings.sleeping = Toggle::Off;
  World awake = make_world(pile);
  EXPECT_EQ(awake.step(240).sleeping_bodies, 0u);
  pile.settings.sleeping = Toggle::Auto;
  World automatic = make_world(pile);
  const StepReport r = automatic.step(240);
  EXPECT_FALSE(r.active.sleeping);
  EXPECT_EQ(state_difference(automatic, awake), 0.0);
}

}  // namespace
}  // namespace collision2d
