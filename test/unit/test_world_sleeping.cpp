// Sleeping islands leave the step (world_sleeping_contacts.cpp): their
// contacts are kept aside, still reported, and come back when a mover reaches
// the island, which then wakes whole in that frame. A refused step and a
// snapshot round trip must carry the kept contacts exactly.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"
#include "world_impl.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
using test::same_bits;
using test::same_contacts;

constexpr int kSettleFrames = 600;  // 10 s: a small pyramid falls asleep well before
constexpr double kDropHeight = 1.5;  // m above the top box's centre
constexpr double kDropSpeed = 4.0;   // m/s down
constexpr double kDiskRadius = 0.25; // m
constexpr double kDiskMass = 2.0;    // kg
constexpr double kLargest = std::numeric_limits<double>::max();
constexpr double kFarSpeed = 1e298;   // m/s: a frame moves a body 1.7e296 m, far above the rounding step there
constexpr double kFrame = 1.0 / 60.0; // s, the scenes' frame

bool same_bodies(const World& x, const World& y)
{
  for (BodyId id : x.body_ids())
  {
    const Body& p = x.body(id);
    const Body& q = y.body(id);
    if (!same_bits(p.position().x, q.position().x) || !same_bits(p.position().y, q.position().y) ||
        !same_bits(p.theta(), q.theta()) || !same_bits(p.velocity().x, q.velocity().x) ||
        !same_bits(p.velocity().y, q.velocity().y) || !same_bits(p.omega(), q.omega()) ||
        x.is_sleeping(id) != y.is_sleeping(id))
    {
      return false;
    }
  }
  return true;
}

std::vector<BodyId> dynamic_ids(const World& world)
{
  std::vector<BodyId> ids;
  for (BodyId id : world.body_ids())
  {
    if (world.body(id).type() == BodyType::Dynamic)
    {
      ids.push_back(id);
    }
  }
  return ids;
}

/// A base-4 pyramid put to sleep, in the given pipeline.
World sleeping_pyramid(bool soft)
{
  Scene scene = scenes::pyramid(4);
  scene.settings.sleeping = Toggle::On;
  scene.settings.soft_step = soft;
  World world = make_world(scene);
  world.step(kSettleFrames);
  return world;
}

/// A disk thrown down at the top box from above.
BodyId drop_disk(World& world)
{
  const std::vector<BodyId> boxes = dynamic_ids(world);
  BodyId top = boxes.front();
  for (BodyId id : boxes)
  {
    top = world.body(id).position().y > world.body(top).position().y ? id : top;
  }
  const Vec2 above = world.body(top).position() + Vec2{0.0, kDropHeight};
  return world.add_body(Body(kDiskMass, kDiskRadius, above, {0.0, -kDropSpeed}), Material{});
}

TEST(WorldSleeping, KeptContactsAreReportedUnchanged)
{
  for (const bool soft : {true, false})
  {
    World world = sleeping_pyramid(soft);
    for (BodyId id : dynamic_ids(world))
    {
      ASSERT_TRUE(world.is_sleeping(id)) << "soft " << soft;
    }
    const std::vector<WorldContact> kept = world.contacts();
    ASSERT_FALSE(kept.empty());
    // Every box rests on something: the pile's weight is still carried by
    // the kept contacts (positive normal impulses on the ground row).
    double ground_impulse = 0.0;
    for (const WorldContact& c : kept)
    {
      ground_impulse += world.body(c.a).type() == BodyType::Static ? c.impulse.normal : 0.0;
    }
    EXPECT_GT(ground_impulse, 0.0) << "soft " << soft;
    const StepReport report = world.step(30);
    EXPECT_TRUE(same_contacts(world.contacts(), kept)) << "soft " << soft;
    EXPECT_EQ(report.contact_count, kept.size()) << "soft " << soft;
  }
}

TEST(WorldSleeping, AnIslandSleepsOnTheFrameThatCompletesItsRest)
{
  // Rest is counted from the outputs: a frame whose end speeds are under the
  // thresholds rests. The island must fall asleep on the frame that brings
  // its rest to sleep_time, although sums of dt round below it (thirty
  // frames of 1/60 s add up to 0.49999999999999994 s).
  for (const bool soft : {true, false})
  {
    for (const double sleep_time : {0.1, 0.2, 0.5, 1.5})
    {
      Scene scene = scenes::column(1);
      scene.settings.sleeping = Toggle::On;
      scene.settings.sleep_time = sleep_time;
      scene.settings.soft_step = soft;
      World world = make_world(scene);
      const BodyId box = dynamic_ids(world).front();
      const WorldSettings& s = world.settings();
      int rested = 0;  // frames of rest before the one it falls asleep in
      int frame = 0;
      for (; frame < kSettleFrames && !world.is_sleeping(box); ++frame)
      {
        world.step(1);
        const Body& b = world.body(box);
        const bool still = length_sq(b.velocity()) <= s.sleep_linear_speed * s.sleep_linear_speed &&
                           b.omega() * b.omega() <= s.sleep_angular_speed * s.sleep_angular_speed;
        rested = world.is_sleeping(box) ? rested : (still ? rested + 1 : 0);
      }
      ASSERT_TRUE(world.is_sleeping(box)) << "soft " << soft << ", sleep_time " << sleep_time;
      EXPECT_EQ(rested + 1, std::lround(sleep_time / s.dt)) << "soft " << soft << ", sleep_time " << sleep_time;
    }
  }
}

TEST(WorldSleeping, AReachedIslandWakesWholeInThatFrame)
{
  for (const bool soft : {true, false})
  {
    World world = sleeping_pyramid(soft);
    const std::vector<BodyId> boxes = dynamic_ids(world);
    drop_disk(world);
    int frames = 0;
    while (world.is_sleeping(boxes.front()) && frames < 60)
    {
      world.step();
      ++frames;
      // No box wakes alone: the island is asleep or awake as a whole.
      std::size_t awake = 0;
      for (BodyId id : boxes)
      {
        awake += world.is_sleeping(id) ? 0 : 1;
      }
      EXPECT_TRUE(awake == 0 || awake == boxes.size()) << "soft " << soft << ", frame " << frames;
    }
    ASSERT_LT(frames, 60) << "soft " << soft << ": the disk never woke the pile";
    // The woken pile was solved with its contacts: over the next second it
    // stays within the penetration it settled at, plus the disk's blow.
    double deepest = 0.0;
    for (int f = 0; f < 60; ++f)
    {
      deepest = std::max(deepest, world.step().max_penetration);
    }
    EXPECT_LT(deepest, 0.05) << "soft " << soft;  // 5 cm: a fifth of a box edge
  }
}

TEST(WorldSleeping, RefusedStepPutsTheKeptContactsBack)
{
  // The refused step starts while the pile sleeps and only the disk moves
  // (the step keeps only the movers' motion aside), wakes the pile, and
  // overflows in the same frame: everything must come back.
  for (const bool soft : {true, false})
  {
    for (const int frames : {1, 2})
    {
      World world = sleeping_pyramid(soft);
      drop_disk(world);
      // Find the last two frames before the disk wakes the pile.
      std::vector<World> history{world, world};
      int frames_left = 60;
      while (world.is_sleeping(dynamic_ids(world).front()) && --frames_left > 0)
      {
        history = {history[1], world};
        world.step();
      }
      ASSERT_GT(frames_left, 0) << "soft " << soft << ": the disk never woke the pile";
      world = history[0];
      // A body near the largest coordinate moves so fast that it overflows
      // in the second frame from here; its box pairs with nothing.
      const double speed = kFarSpeed;
      const BodyId thrown =
          world.add_body(Body(1.0, kDiskRadius, {kLargest - 1.5 * speed * kFrame, 0.0}, {speed, 0.0}), Material{});
      world.step();  // no edit since: the next step keeps only the movers' motion
      ASSERT_TRUE(world.is_sleeping(dynamic_ids(world).front())) << "soft " << soft;
      const World before = world;
      EXPECT_THROW(world.step(frames), std::overflow_error) << "soft " << soft << ", frames " << frames;
      EXPECT_TRUE(same_contacts(world.contacts(), before.contacts())) << "soft " << soft << ", frames " << frames;
      EXPECT_TRUE(same_bodies(world, before)) << "soft " << soft << ", frames " << frames;
      // ... and the world steps on as the copy does.
      World copy = before;
      for (World* w : {&world, &copy})
      {
        w->remove_body(thrown);
        w->step(30);
      }
      EXPECT_TRUE(same_contacts(world.contacts(), copy.contacts())) << "soft " << soft << ", frames " << frames;
      EXPECT_TRUE(same_bodies(world, copy)) << "soft " << soft << ", frames " << frames;
    }
  }
}

/// Two boxes on a ground with a plank across them: one island until the
/// plank goes.
struct BridgeWorld
{
  World world;
  BodyId left;
  BodyId right;
  BodyId plank;
};

BridgeWorld bridge(bool soft)
{
  Scene scene;
  scene.settings.sleeping = Toggle::On;
  scene.settings.soft_step = soft;
  scene.bodies.push_back(SceneBody{scenes::make_static_box(40.0, 1.0, {0.0, -0.5}), Material{}, "ground"});
  scene.bodies.push_back(SceneBody{scenes::make_box(1.0, 1.0, 1.0, {-2.0, 0.5}), Material{}, "left"});
  scene.bodies.push_back(SceneBody{scenes::make_box(1.0, 1.0, 1.0, {2.0, 0.5}), Material{}, "right"});
  scene.bodies.push_back(SceneBody{scenes::make_box(0.5, 6.0, 0.2, {0.0, 1.1}), Material{}, "plank"});
  return BridgeWorld{make_world(scene), 1, 2, 3};  // make_world: ids in scene order
}

TEST(WorldSleeping, RefusedStepInWhichAnIslandFellAsleepLeavesNoIslandBehind)
{
  // The bridge falls asleep in the first frame of a refused two-frame step.
  // Put back, it must be as a copy that never tried the step: once the plank
  // is gone and the two boxes sleep apart, waking one leaves the other asleep.
  for (const bool soft : {true, false})
  {
    BridgeWorld b = bridge(soft);
    std::vector<World> history{b.world, b.world};
    int frames_left = 600;
    while (!b.world.is_sleeping(b.left) && --frames_left > 0)
    {
      history = {history[1], b.world};
      b.world.step();
    }
    ASSERT_GT(frames_left, 0) << "soft " << soft << ": the bridge never fell asleep";
    World world = history[1];  // the frame before it sleeps
    const double speed = kFarSpeed;
    const BodyId thrown =
        world.add_body(Body(1.0, kDiskRadius, {kLargest - 1.5 * speed * kFrame, 0.0}, {speed, 0.0}), Material{});
    const World before = world;
    EXPECT_THROW(world.step(2), std::overflow_error) << "soft " << soft;
    ASSERT_FALSE(world.is_sleeping(b.left)) << "soft " << soft;
    World copy = before;
    for (World* w : {&world, &copy})
    {
      w->remove_body(thrown);
      w->remove_body(b.plank);
      int frames = 0;
      while (!(w->is_sleeping(b.left) && w->is_sleeping(b.right)) && frames++ < 600)
      {
        w->step();
      }
      ASSERT_LT(frames, 600) << "soft " << soft << ": the boxes never fell asleep apart";
      // An edit wakes the body's island, and only that.
      w->set_body_state(b.left, w->body(b.left).position(), w->body(b.left).theta(), {0.0, 0.0}, 0.0);
    }
    EXPECT_FALSE(copy.is_sleeping(b.left)) << "soft " << soft;
    EXPECT_TRUE(copy.is_sleeping(b.right)) << "soft " << soft;
    EXPECT_FALSE(world.is_sleeping(b.left)) << "soft " << soft;
    EXPECT_TRUE(world.is_sleeping(b.right)) << "soft " << soft << ": the refused step left one island label on both";
    EXPECT_TRUE(same_bodies(world, copy)) << "soft " << soft;
  }
}

TEST(WorldSleeping, SnapshotOfASleepingIslandResumesExactly)
{
  for (const bool soft : {true, false})
  {
    World world = sleeping_pyramid(soft);
    drop_disk(world);
    // The snapshot sorts the contacts kept aside out again.
    World resumed = world;
    resumed.set_step_state(world.step_state());
    for (int f = 0; f < 90; ++f)
    {
      world.step();
      resumed.step();
    }
    EXPECT_TRUE(same_contacts(world.contacts(), resumed.contacts())) << "soft " << soft;
    EXPECT_TRUE(same_bodies(world, resumed)) << "soft " << soft;
  }
}

TEST(WorldSleeping, StagesThatSkipRestingBodiesChangeNothing)
{
  // A pile asleep while a disk falls beside it, then onto it: the frames
  // that visit only the movers must give the bits of frames that visit
  // every body and rebuild the resting grid each time.
  for (const bool soft : {true, false})
  {
    World skipping = sleeping_pyramid(soft);
    drop_disk(skipping);
    const Body& top = skipping.body(skipping.body_ids().back());
    skipping.add_body(Body(kDiskMass, kDiskRadius, top.position() + Vec2{8.0, 0.0}, {1.0, 0.0}), Material{});
    World full = skipping;
    for (int f = 0; f < 120; ++f)
    {
      skipping.step();
      detail::set_full_body_passes(true);
      full.step();
      detail::set_full_body_passes(false);
      ASSERT_TRUE(same_bodies(skipping, full)) << "soft " << soft << ", frame " << f;
      ASSERT_TRUE(same_contacts(skipping.contacts(), full.contacts())) << "soft " << soft << ", frame " << f;
    }
  }
}

TEST(WorldSleeping, PilesWokenOneByOneMatchFullPasses)
{
  // Three small piles fall asleep at different times while disks are
  // thrown at them one after another and a kinematic box slides past: every
  // frame of the stepping that skips resting bodies must give the bits of
  // frames that visit all of them, in both pipelines and with two workers.
  constexpr int kFrames = 420;
  constexpr int kThrowEvery = 60;        // frames between thrown disks
  constexpr double kPileSpacing = 12.0;  // m between the piles' centres
  for (const bool soft : {true, false})
  {
    for (const int workers : {1, 2})
    {
      Scene scene;
      scene.settings.sleeping = Toggle::On;
      scene.settings.sleep_time = 0.2;
      scene.settings.soft_step = soft;
      scene.settings.workers = workers;
      scenes::add_ground(scene, scenes::GroundParams{});
      for (int pile = 0; pile < 3; ++pile)
      {
        scenes::PyramidParams pyramid;
        pyramid.base = 3 + pile;
        pyramid.at = Vec2{kPileSpacing * (pile - 1), 0.5};
        scenes::add_pyramid(scene, pyramid);
      }
      Body slider = scenes::make_static_box(0.5, 0.5, {-25.0, 4.0});
      slider.set_type(BodyType::Kinematic);
      slider.set_velocity({0.2, 0.0});
      scene.bodies.push_back(SceneBody{slider, Material{}, "slider"});
      World skipping = make_world(scene);
      World full = make_world(scene);
      int mixed_frames = 0;  // some dynamic body asleep, some awake
      for (int f = 0; f < kFrames; ++f)
      {
        if (f > 0 && f % kThrowEvery == 0)
        {
          const double x = kPileSpacing * (f / kThrowEvery % 3 - 1);
          for (World* w : {&skipping, &full})
          {
            w->add_body(Body(kDiskMass, kDiskRadius, {x, 8.0}, {0.0, -kDropSpeed}), Material{});
          }
        }
        skipping.step();
        detail::set_full_body_passes(true);
        full.step();
        detail::set_full_body_passes(false);
        ASSERT_TRUE(same_bodies(skipping, full)) << "soft " << soft << ", workers " << workers << ", frame " << f;
        ASSERT_TRUE(same_contacts(skipping.contacts(), full.contacts()))
            << "soft " << soft << ", workers " << workers << ", frame " << f;
        const std::vector<BodyId> dynamic = dynamic_ids(skipping);
        const auto asleep = std::count_if(dynamic.begin(), dynamic.end(),
                                          [&](BodyId id) { return skipping.is_sleeping(id); });
        mixed_frames += asleep > 0 && asleep < static_cast<long>(dynamic.size()) ? 1 : 0;
      }
      // The run had piles asleep while other bodies moved.
      EXPECT_GT(mixed_frames, kFrames / 4) << "soft " << soft << ", workers " << workers;
    }
  }
}

}  // namespace
}  // namespace collision2d
