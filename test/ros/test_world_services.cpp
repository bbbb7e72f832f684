// rostest client of the world services: StepWorld on shipped scenes (a resting
// stack stays, a dropped disk bounces, frames and time advance, the topic
// publishes) and the other world services. The refusals of bad input are
// test_world_services_rejects.cpp, linked into the same binary.
#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/messages.h"
#include "collision2d/scenes/standard_scenes.h"

#include "ros_test_helpers.h"
#include "world_services_test_support.h"

namespace collision2d
{
namespace
{
using namespace world_services_test;  // NOLINT: the shared helpers and fixture

TEST_F(WorldServices, StepAdvancesFramesAndTime)
{
  const double dt = before_.settings.dt;
  StepWorld::Response response = step(10);
  EXPECT_EQ(response.state.at(0).frame_count, before_.frame_count + 10);
  EXPECT_EQ(response.frame_count, before_.frame_count + 10);
  EXPECT_EQ(response.sim_time, response.state.at(0).sim_time);
  EXPECT_NEAR(response.state.at(0).sim_time, before_.sim_time + 10 * dt, 1e-12);
  EXPECT_EQ(response.report.frames, 10);
  EXPECT_EQ(response.report.substeps, 10 * before_.settings.substeps);
  // A dt for one call: time advances by it, the world keeps its own.
  response = step(4, 0.5 * dt);
  EXPECT_NEAR(response.state.at(0).sim_time, before_.sim_time + 12 * dt, 1e-12);
  EXPECT_EQ(response.state.at(0).settings.dt, dt);
  EXPECT_TRUE(same_world(response.state.at(0), get_world()));
}

TEST_F(WorldServices, RestingStackStays)
{
  const WorldState start = load("column");  // 20 boxes of 1 m on the ground
  const StepWorld::Response response = step(120);  // 2 s
  ASSERT_EQ(response.state.at(0).bodies.size(), start.bodies.size());
  // Neither sliding nor toppling. The boxes do sink into their 20 contacts by
  // the gravity sag each substep's correction leaves (test_world_stacking
  // states about 0.15 m at the top with the default 4 substeps).
  constexpr double kLateral = 0.02;  // m
  constexpr double kTilt = 0.02;     // rad
  constexpr double kSink = 0.2;      // m
  for (std::size_t i = 0; i < start.bodies.size(); ++i)
  {
    const BodyMsg& a = start.bodies[i];
    const BodyMsg& b = response.state.at(0).bodies[i];
    EXPECT_NEAR(b.pose.x, a.pose.x, kLateral) << "body " << a.id;
    EXPECT_NEAR(b.pose.theta, a.pose.theta, kTilt) << "body " << a.id;
    EXPECT_LE(a.pose.y - b.pose.y, kSink) << "body " << a.id;
    EXPECT_GE(a.pose.y - b.pose.y, -kLateral) << "body " << a.id << " rose";
  }
  // At rest: 1 mJ over 20 kg is a speed of 1 cm/s.
  EXPECT_LT(response.report.kinetic_energy_after, 1e-3);
}

TEST_F(WorldServices, DroppedDiskBounces)
{
  constexpr double kHeight = 2.0;       // m, of the disk's lowest point above the ground
  constexpr double kRestitution = 0.8;
  SetWorld::Request request;
  request.keep_settings = true;
  BodyMsg ground = box_msg(0, 40.0, 1.0, {0.0, -0.5});
  ground.type = BodyMsg::STATIC;
  ground.material.restitution = 1.0;
  BodyMsg ball = disk_msg(1, {0.0, kHeight + 0.25}, {}, 0.25);
  ball.material.restitution = kRestitution;
  request.bodies = {ground, ball};
  request.return_state = true;
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  const WorldState& start = set.response.state.at(0);
  ASSERT_LT(start.settings.gravity.y, 0.0);

  // Fall (~0.64 s), bounce, and rise to the next apex.
  double lowest = kHeight, apex_after_bounce = 0.0;
  bool bounced = false;
  for (int frame = 0; frame < 150; ++frame)
  {
    const BodyMsg* disk = find_body(step(1).state.at(0), start.bodies[1].id);
    ASSERT_NE(disk, nullptr);
    const double height = disk->pose.y - 0.25;
    lowest = std::min(lowest, height);
    bounced = bounced || disk->twist.linear.y > 0.0;
    if (bounced)
    {
      apex_after_bounce = std::max(apex_after_bounce, height);
    }
  }
  ASSERT_TRUE(bounced) << "the disk never moved up";
  // Frames sample the fall every dt: the lowest sample is within one frame's
  // travel at impact speed of the ground.
  const double impact_speed = std::sqrt(2.0 * -start.settings.gravity.y * kHeight);
  EXPECT_LT(lowest, impact_speed * start.settings.dt) << "bounced before reaching the ground";
  EXPECT_GE(lowest, -0.01) << "sank into the ground";
  // Newton's e (min of the two materials, 0.8) returns e^2 of the drop height.
  EXPECT_NEAR(apex_after_bounce, kRestitution * kRestitution * kHeight, 0.15 * kHeight);
}

TEST_F(WorldServices, TopicPublishesEveryStep)
{
  std::mutex mutex;
  std::vector<std::uint64_t> frames;
  ros::NodeHandle handle;
  ros::Subscriber subscriber = handle.subscribe<WorldState>("world_state", 10, [&](const WorldState::ConstPtr& state) {
    std::lock_guard<std::mutex> lock(mutex);
    frames.push_back(state->frame_count);
  });
  // Latched: the last state arrives on subscribing.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kServiceWait);
  const auto received = [&](std::uint64_t frame) {
    std::lock_guard<std::mutex> lock(mutex);
    return std::find(frames.begin(), frames.end(), frame) != frames.end();
  };
  while (!received(before_.frame_count) && ros::WallTime::now() < deadline)
  {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  EXPECT_TRUE(received(before_.frame_count)) << "latched state not received";
  step(1);
  step(1);
  while (!received(before_.frame_count + 2) && ros::WallTime::now() < deadline)
  {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  EXPECT_TRUE(received(before_.frame_count + 1));
  EXPECT_TRUE(received(before_.frame_count + 2));
}

TEST_F(WorldServices, AddRemoveAndReset)
{
  AddBody::Request add;
  add.body = disk_msg(999, {5.0, 3.0});
  const AddBody added = call<AddBody>("add_body", add);
  ASSERT_TRUE(added.response.success) << added.response.message;
  WorldState state = get_world();
  ASSERT_NE(find_body(state, added.response.id), nullptr);
  EXPECT_EQ(state.bodies.size(), before_.bodies.size() + 1);

  RemoveBody::Request remove;
  remove.id = added.response.id;
  EXPECT_TRUE(call<RemoveBody>("remove_body", remove).response.success);
  EXPECT_EQ(find_body(get_world(), added.response.id), nullptr);

  const std_srvs::Trigger reset = call<std_srvs::Trigger>("reset_world");
  EXPECT_TRUE(reset.response.success) << reset.response.message;
  state = get_world();
  EXPECT_EQ(state.frame_count, 0u);
  EXPECT_EQ(state.scene, "resting_box");
}

TEST_F(WorldServices, SetWorldRoundTripsGetWorld)
{
  SetWorld::Request request;
  request.bodies = before_.bodies;
  request.settings = before_.settings;
  request.return_state = true;
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  // Same bodies and settings, restarted at frame 0.
  ASSERT_EQ(set.response.state.size(), 1u);
  const WorldState& state = set.response.state[0];
  ASSERT_EQ(state.bodies.size(), before_.bodies.size());
  for (std::size_t i = 0; i < before_.bodies.size(); ++i)
  {
    EXPECT_EQ(state.bodies[i].pose, before_.bodies[i].pose);
    EXPECT_EQ(state.bodies[i].twist, before_.bodies[i].twist);
    EXPECT_EQ(state.bodies[i].material, before_.bodies[i].material);
  }
  EXPECT_EQ(state.settings, before_.settings);
  EXPECT_EQ(state.frame_count, 0u);
  // The summary says the same as the state.
  EXPECT_EQ(set.response.frame_count, state.frame_count);
  EXPECT_EQ(set.response.sim_time, state.sim_time);
  EXPECT_EQ(set.response.body_count, state.bodies.size());
}

// The answers of the services that replace the world fit a terminal: the
// state comes only when asked for, and the summary counts the new world.
TEST_F(WorldServices, ReplacingTheWorldAnswersASummaryUnlessTheStateIsAskedFor)
{
  step(3);
  SetWorld::Request set_request;
  set_request.bodies = before_.bodies;
  set_request.keep_settings = true;
  const SetWorld set = call<SetWorld>("set_world", set_request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  EXPECT_TRUE(set.response.state.empty());
  EXPECT_EQ(set.response.frame_count, 0u);
  EXPECT_EQ(set.response.sim_time, 0.0);
  EXPECT_EQ(set.response.body_count, before_.bodies.size());

  LoadScene::Request load_request;
  load_request.scene = "newtons_cradle";
  const LoadScene loaded = call<LoadScene>("load_scene", load_request);
  ASSERT_TRUE(loaded.response.success) << loaded.response.message;
  EXPECT_TRUE(loaded.response.state.empty());
  EXPECT_FALSE(loaded.response.available.empty());
  EXPECT_EQ(loaded.response.body_count, get_world().bodies.size());
  EXPECT_GT(loaded.response.body_count, before_.bodies.size());
}

TEST_F(WorldServices, SetWorldKeepsTheSolverSettings)
{
  // Each away from its default, so one the node drops reads back as the default.
  SetWorld::Request request;
  request.bodies = before_.bodies;
  request.settings = before_.settings;
  request.settings.solver_mode = WorldConfig::SOLVER_EXACT;
  request.settings.position_iterations = before_.settings.position_iterations + 2;
  request.settings.position_block = !before_.settings.position_block;
  request.settings.exact_position_correction = !before_.settings.exact_position_correction;
  request.return_state = true;
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  for (const WorldConfig& shown : {set.response.state.at(0).settings, get_world().settings, step(1).state.at(0).settings})
  {
    EXPECT_EQ(shown.solver_mode, WorldConfig::SOLVER_EXACT);
    EXPECT_EQ(shown.position_iterations, request.settings.position_iterations);
    EXPECT_EQ(shown.position_block, request.settings.position_block);
    EXPECT_EQ(shown.exact_position_correction, request.settings.exact_position_correction);
  }
}

TEST_F(WorldServices, ExactSolverCarriesAMillionToOneStack)
{
  // A 1e6 kg box on a 1 kg box on the ground: the iterative passes let the
  // heavy box fall into the light one within half a second (test_world_exact);
  // the exact solver holds it at slop. Compliance 0 so that no spring depth
  // (weight * compliance, 5 cm here) adds to slop.
  constexpr double kMassRatio = 1e6;
  constexpr double kSlops = 3.0;     // allowed depth, in slops
  constexpr int kChecks = 12;
  constexpr std::uint32_t kFramesPerCheck = 10;  // 2 s in all at the default dt
  const Scene scene = scenes::heavy_on_light(kMassRatio);
  SetWorld::Request request;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    request.bodies.push_back(
        ros_interface::body_to_msg(scene.bodies[i].body, static_cast<std::uint32_t>(i), scene.bodies[i].material));
  }
  request.settings = before_.settings;
  request.settings.solver_mode = WorldConfig::SOLVER_EXACT;
  request.settings.exact_position_correction = true;
  request.settings.compliance = 0.0;
  request.return_state = true;
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;

  for (int check = 0; check < kChecks; ++check)
  {
    const StepWorld::Response response = step(kFramesPerCheck);
    ASSERT_EQ(response.state.at(0).settings.solver_mode, WorldConfig::SOLVER_EXACT);
    const BodyMsg* heavy = dynamic_by_mass(response.state.at(0), true);
    const BodyMsg* light = dynamic_by_mass(response.state.at(0), false);
    ASSERT_TRUE(heavy != nullptr && light != nullptr && heavy != light);
    ASSERT_NEAR(heavy->mass / light->mass, kMassRatio, 1e-6 * kMassRatio);
    const double allowed = kSlops * response.state.at(0).settings.slop;
    const double depth = vertical_extent(*light).high - vertical_extent(*heavy).low;
    EXPECT_LT(depth, allowed) << "the heavy box sank into the light one at frame " << response.state.at(0).frame_count;
    // Still resting on it, not thrown off by an overcorrection.
    EXPECT_GT(depth, -allowed) << "the heavy box left the light one at frame " << response.state.at(0).frame_count;
    const BodyMsg* ground = find_body(response.state.at(0), set.response.state.at(0).bodies.front().id);
    ASSERT_TRUE(ground != nullptr && ground->type == BodyMsg::STATIC);
    EXPECT_LT(vertical_extent(*ground).high - vertical_extent(*light).low, allowed)
        << "the light box sank into the ground";
    // The report shows the islands were pivoted, none left to the passes.
    EXPECT_GT(response.report.exact_islands, 0u);
    EXPECT_EQ(response.report.exact_fallbacks, 0u);
  }
}

}  // namespace
}  // namespace collision2d

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_world_services");
  ros::NodeHandle handle;
  for (const char* service : {"get_world", "step_world", "load_scene", "set_world", "reset_world"})
  {
    if (!ros::service::waitForService(service, ros::Duration(collision2d::world_services_test::kServiceWait)))
    {
      ADD_FAILURE() << service << " never came up";
    }
  }
  return RUN_ALL_TESTS();
}
