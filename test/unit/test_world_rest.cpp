// A world at rest replays its last frame (world_rest.cpp). The replay must
// give exactly what stepping every frame in full gives: bodies, contacts,
// impulses, clock and step reports, bit for bit, in both pipelines, and an
// edit through the API must end it.
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/scene.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"
#include "world_impl.h"

namespace collision2d
{
namespace
{
/// Every bit of the state and report, as raw bytes.
std::vector<unsigned char> state_bytes(const World& world, const StepReport& report)
{
  std::vector<unsigned char> bytes;
  const auto add = [&bytes](double value) {
    unsigned char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    bytes.insert(bytes.end(), raw, raw + sizeof value);
  };
  for (BodyId id : world.body_ids())
  {
    const Body& b = world.body(id);
    for (double v : {b.position().x, b.position().y, b.theta(), b.velocity().x, b.velocity().y, b.omega()})
    {
      add(v);
    }
    add(world.is_sleeping(id) ? 1.0 : 0.0);
  }
  for (const WorldContact& c : world.contacts())
  {
    for (double v : {static_cast<double>(c.a), static_cast<double>(c.b), c.contact.normal.x, c.contact.normal.y,
                     c.contact.point.x, c.contact.point.y, c.contact.penetration,
                     static_cast<double>(c.contact.feature), c.impulse.normal, c.impulse.tangent,
                     c.sliding ? 1.0 : 0.0, c.anchor_drift, c.origin.r_a.x, c.origin.r_a.y, c.origin.r_b.x,
                     c.origin.r_b.y, c.origin.separation, c.origin.theta_a, c.origin.theta_b,
                     c.origin.known ? 1.0 : 0.0})
    {
      add(v);
    }
  }
  for (double v : {world.time(), static_cast<double>(world.frame_count()), static_cast<double>(report.frames),
                   static_cast<double>(report.substeps), static_cast<double>(report.contact_count),
                   report.max_penetration, report.kinetic_energy, report.max_detected_penetration,
                   report.velocity_residual, report.warm_substep_residual,
                   static_cast<double>(report.swept_bodies), static_cast<double>(report.sleeping_bodies),
                   static_cast<double>(report.active.sleeping), static_cast<double>(report.active.friction)})
  {
    add(v);
  }
  return bytes;
}

/// A base-10 pyramid left to fall asleep.
World settled_pyramid(bool soft)
{
  Scene scene = scenes::pyramid(10);
  scene.settings.soft_step = soft;
  scene.settings.sleeping = Toggle::On;
  World world = make_world(scene);
  StepReport report;
  for (int f = 0; f < 600 && report.sleeping_bodies < 55; ++f)
  {
    report = world.step();
  }
  EXPECT_EQ(report.sleeping_bodies, 55u) << "the pyramid did not fall asleep";
  return world;
}

/// Steps both worlds alike, the first with replays and the second in full,
/// and expects the same bytes after each call.
void expect_same_steps(World& replayed, World& full, const std::vector<int>& calls, const char* what)
{
  for (std::size_t k = 0; k < calls.size(); ++k)
  {
    detail::set_rest_replay_enabled(true);
    const StepReport a = replayed.step(calls[k]);
    detail::set_rest_replay_enabled(false);
    const StepReport b = full.step(calls[k]);
    detail::set_rest_replay_enabled(true);
    ASSERT_EQ(state_bytes(replayed, a), state_bytes(full, b)) << what << ", call " << k;
  }
}

class WorldRest : public ::testing::TestWithParam<bool>
{
};

TEST_P(WorldRest, ReplayedFramesMatchFullFrames)
{
  World replayed = settled_pyramid(GetParam());
  World full = replayed;
  const std::uint64_t before = detail::replayed_rest_frames();
  expect_same_steps(replayed, full, {1, 1, 5, 1, 30}, "at rest");
  // The first frame at rest is stepped in full; the rest are replayed.
  EXPECT_GE(detail::replayed_rest_frames() - before, 30u);
}

TEST_P(WorldRest, AnEditEndsTheReplay)
{
  World replayed = settled_pyramid(GetParam());
  replayed.step(3);  // at rest: replayed
  World full = replayed;
  const BodyId top = replayed.body_ids().back();
  const Body b = replayed.body(top);  // a copy: the edit below changes the world's
  for (World* w : {&replayed, &full})
  {
    w->set_body_state(top, b.position() + Vec2{0.0, 0.5}, b.theta(), Vec2{0.3, 0.0}, 0.0);
  }
  expect_same_steps(replayed, full, {1, 10, 60, 120, 5}, "after a wake");
  WorldSettings margin = replayed.settings();
  margin.speculative_margin *= 0.5;
  for (World* w : {&replayed, &full})
  {
    w->set_settings(margin);
  }
  expect_same_steps(replayed, full, {1, 5}, "after a settings change");
  const BodyId removed = replayed.body_ids()[3];
  for (World* w : {&replayed, &full})
  {
    w->remove_body(removed);
  }
  expect_same_steps(replayed, full, {1, 30, 120}, "after a removal");
}

INSTANTIATE_TEST_SUITE_P(Pipelines, WorldRest, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? std::string("soft_step") : std::string("fx2d");
                         });

}  // namespace
}  // namespace collision2d
