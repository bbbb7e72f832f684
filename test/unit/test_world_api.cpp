// World bookkeeping: stable ids, add/remove/set between frames, settings and
// material validation, static and kinematic bodies.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace
{
Body disk(Vec2 p, Vec2 v = Vec2{0.0, 0.0}) { return Body(1.0, 0.5, p, v); }

/// Expects validate() to reject `s` with a message naming `field`.
void expect_rejected(const WorldSettings& s, const std::string& field)
{
  try
  {
    World::validate(s);
    FAIL() << field << " was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(WorldApi, IdsAreStableAndNeverReused)
{
  World world;
  const BodyId a = world.add_body(disk({0.0, 0.0}));
  const BodyId b = world.add_body(disk({2.0, 0.0}));
  const BodyId c = world.add_body(disk({4.0, 0.0}));
  world.remove_body(b);
  const BodyId d = world.add_body(disk({6.0, 0.0}));
  EXPECT_NE(d, b);
  EXPECT_EQ(world.body_ids(), (std::vector<BodyId>{a, c, d}));
  EXPECT_FALSE(world.has_body(b));
  EXPECT_THROW(world.body(b), std::out_of_range);
  EXPECT_THROW(world.remove_body(b), std::out_of_range);
  // The survivors keep their own state under their own ids.
  EXPECT_EQ(world.body(c).position().x, 4.0);
  EXPECT_EQ(world.body(d).position().x, 6.0);
  world.clear();
  EXPECT_EQ(world.body_count(), 0u);
  EXPECT_GT(world.add_body(disk({0.0, 0.0})), d);
}

TEST(WorldApi, SetStateBetweenFramesKeepsIdsAndApplies)
{
  WorldSettings settings;
  settings.gravity = Vec2{0.0, 0.0};
  World world(settings);
  const BodyId a = world.add_body(disk({0.0, 0.0}));
  const BodyId b = world.add_body(disk({5.0, 0.0}));
  world.step(3);
  world.set_body_state(b, Vec2{1.0, 2.0}, 0.3, Vec2{-1.0, 0.5}, 2.0);
  EXPECT_EQ(world.body_ids(), (std::vector<BodyId>{a, b}));
  const Body& moved = world.body(b);
  EXPECT_EQ(moved.position(), (Vec2{1.0, 2.0}));
  EXPECT_EQ(moved.theta(), 0.3);
  EXPECT_EQ(moved.velocity(), (Vec2{-1.0, 0.5}));
  EXPECT_EQ(moved.omega(), 2.0);
  // Free flight without gravity: the set velocity carries it.
  world.step(6);
  EXPECT_NEAR(world.body(b).position().x, 1.0 - 6.0 * settings.dt, 1e-12);
  EXPECT_THROW(world.set_body_state(a, Vec2{NAN, 0.0}, 0.0, Vec2{}, 0.0), std::invalid_argument);
}

TEST(WorldApi, RejectsBadSettingsNamingTheField)
{
  WorldSettings s;
  s.dt = 0.0;
  expect_rejected(s, "dt");
  s = WorldSettings();
  s.dt = INFINITY;
  expect_rejected(s, "dt");
  s = WorldSettings();
  s.dt = NAN;
  expect_rejected(s, "dt");
  s = WorldSettings();
  s.substeps = 0;
  expect_rejected(s, "substeps");
  s = WorldSettings();
  s.velocity_iterations = 0;
  expect_rejected(s, "velocity_iterations");
  s = WorldSettings();
  s.position_iterations = 0;
  expect_rejected(s, "position_iterations");
  s = WorldSettings();
  s.slop = -1e-3;
  expect_rejected(s, "slop");
  s = WorldSettings();
  s.compliance = -1.0;
  expect_rejected(s, "compliance");
  s = WorldSettings();
  s.restitution_threshold = -0.1;
  expect_rejected(s, "restitution_threshold");
  s = WorldSettings();
  s.gravity = Vec2{0.0, NAN};
  expect_rejected(s, "gravity");
  s = WorldSettings();
  s.toi_displacement_fraction = 0.0;
  expect_rejected(s, "toi_displacement_fraction");
  s = WorldSettings();
  s.sleep_time = -1.0;
  expect_rejected(s, "sleep_time");
  EXPECT_NO_THROW(World::validate(WorldSettings()));
}

TEST(WorldApi, RejectedSettingsLeaveTheWorldUnchanged)
{
  WorldSettings good;
  good.substeps = 7;
  World world(good);
  WorldSettings bad = good;
  bad.substeps = 0;
  EXPECT_THROW(world.set_settings(bad), std::invalid_argument);
  EXPECT_EQ(world.settings().substeps, 7);
  EXPECT_THROW(World{bad}, std::invalid_argument);
  EXPECT_THROW(world.step(0), std::invalid_argument);
}

TEST(WorldApi, RejectsBadMaterialsNamingTheField)
{
  World world;
  const auto expect_field = [&](const Material& m, const std::string& field) {
    try
    {
      world.add_body(disk({0.0, 0.0}), m);
      FAIL() << field << " was accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  expect_field(Material{1.2, 0.0, 0.0}, "restitution");
  expect_field(Material{-0.1, 0.0, 0.0}, "restitution");
  expect_field(Material{0.5, -1.0, 0.0}, "static_friction");
  expect_field(Material{0.5, 0.5, NAN}, "kinetic_friction");
  EXPECT_EQ(world.body_count(), 0u);
}

TEST(WorldApi, StaticBodiesNeverMove)
{
  World world;
  const BodyId floor = world.add_body(scenes::make_static_box(10.0, 1.0, {0.0, -0.5}, 0.1));
  for (int i = 0; i < 5; ++i)
  {
    world.add_body(Body(2.0, 0.3, {-2.0 + i, 1.0 + 0.7 * i}, {0.5, -3.0}), Material{0.5, 0.4, 0.3});
  }
  const Body before = world.body(floor);
  world.step(120);
  const Body& after = world.body(floor);
  EXPECT_EQ(after.position(), before.position());
  EXPECT_EQ(after.theta(), before.theta());
  EXPECT_EQ(after.velocity(), (Vec2{0.0, 0.0}));
  EXPECT_EQ(after.omega(), 0.0);
  EXPECT_GT(world.contacts().size(), 0u);  // the disks did land on it
}

TEST(WorldApi, AMovedStaticBodyIsMetWhereItWasMoved)
{
  // The step poses a static body's outline once per edit, not every frame:
  // an edit must move it. A box rests on a floor; the floor is moved 1 m
  // down and the box must fall onto it there, not onto where it was.
  constexpr double kDrop = 1.0;  // m
  for (const bool soft : {true, false})
  {
    World world;
    WorldSettings s = world.settings();
    s.soft_step = soft;
    world.set_settings(s);
    const BodyId floor = world.add_body(scenes::make_static_box(10.0, 1.0, {0.0, -0.5}, 0.0));
    const BodyId box = world.add_body(scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.5}), Material{0.0, 0.5, 0.5});
    world.step(30);
    ASSERT_GT(world.contacts().size(), 0u) << "the box rests on the floor";
    world.set_body_state(floor, Vec2{0.0, -0.5 - kDrop}, 0.0, Vec2{}, 0.0);
    world.step();
    EXPECT_EQ(world.contacts().size(), 0u) << (soft ? "soft" : "fx2d") << ": the floor moved away";
    world.step(90);  // 1.5 s: it falls 1 m in 0.45 s, then settles
    const Body& b = world.body(box);
    EXPECT_NEAR(b.position().y, 0.5 - kDrop, 0.01) << (soft ? "soft" : "fx2d") << ": resting on the moved floor";
    EXPECT_LT(std::abs(b.velocity().y), 0.05) << (soft ? "soft" : "fx2d");
    EXPECT_GT(world.contacts().size(), 0u) << (soft ? "soft" : "fx2d");
  }
}

TEST(WorldApi, KinematicBodiesKeepTheirVelocity)
{
  World world;
  world.add_body(scenes::make_static_box(40.0, 1.0, {0.0, -0.5}), scenes::rough_material());
  const Vec2 push{2.0, 0.0};
  const double spin = 0.5;
  Body pusher = scenes::make_box(1.0, 1.0, 1.0, {-3.0, 0.6});
  pusher.set_type(BodyType::Kinematic);
  pusher.set_velocity(push);
  pusher.set_omega(spin);
  const BodyId k = world.add_body(pusher, scenes::rough_material());
  const BodyId box = world.add_body(scenes::make_box(5.0, 1.0, 1.0, {0.0, 0.5}), scenes::rough_material());
  const int frames = 90;
  world.step(frames);
  const Body& after = world.body(k);
  EXPECT_EQ(after.velocity(), push);
  EXPECT_EQ(after.omega(), spin);
  const double t = frames * world.settings().dt;
  EXPECT_NEAR(after.position().x, -3.0 + push.x * t, 1e-9);
  EXPECT_NEAR(after.theta(), spin * t, 1e-9);
  // It was not pushed back by the box it shoved.
  EXPECT_GT(world.body(box).position().x, 0.1);
}

}  // namespace
}  // namespace collision2d

namespace collision2d
{
namespace
{
TEST(WorldApi, SetBodyTypeHoldsAndReleasesABody)
{
  World world;
  const BodyId ball = world.add_body(Body(2.0, 0.5, {0.0, 5.0}, {1.0, 0.0}));
  world.set_body_type(ball, BodyType::Kinematic);
  world.step(60);
  // Kinematic: no gravity, it keeps the velocity it was given.
  EXPECT_DOUBLE_EQ(world.body(ball).velocity().y, 0.0);
  EXPECT_NEAR(world.body(ball).position().x, 1.0, 1e-12);
  world.set_body_type(ball, BodyType::Dynamic);
  world.step();
  EXPECT_LT(world.body(ball).velocity().y, 0.0) << "released, it falls";
  world.set_body_type(ball, BodyType::Static);
  EXPECT_EQ(world.body(ball).velocity(), (Vec2{0.0, 0.0})) << "a static body keeps no velocity";
  EXPECT_THROW(world.set_body_type(99, BodyType::Static), std::out_of_range);
}

}  // namespace
}  // namespace collision2d
