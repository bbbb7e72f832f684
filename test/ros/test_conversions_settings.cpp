// Settings messages of the ROS face both ways, without a master: every field
// carried, out-of-range values refused naming the field, and the world
// service's handlers leaving the world as it was when a change fails.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/time.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/reconfigure.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/world_service.h"

#include "conversions_test_support.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using namespace conversions_test;  // NOLINT: the shared message builders

SolverSettings valid_settings()
{
  SolverSettings msg;
  msg.restitution = 0.5;
  msg.friction = 0.3;
  msg.iterations = 50;
  msg.tolerance = 1e-9;
  msg.bias_factor = 0.2;
  msg.slop = 1e-3;
  return msg;
}

std::string settings_rejection(const SolverSettings& msg)
{
  return rejection_of([&] { solver_from_msg(msg); });
}

TEST(SolverFromMsg, CarriesEveryFieldAndTheMode)
{
  SolverSettings msg = valid_settings();
  msg.mode = SolverSettings::EXACT;
  const ContactSolver solver = solver_from_msg(msg);
  EXPECT_EQ(solver.restitution(), 0.5);
  EXPECT_EQ(solver.friction(), 0.3);
  EXPECT_EQ(solver.max_iterations(), 50);
  EXPECT_EQ(solver.tolerance(), 1e-9);
  EXPECT_EQ(solver.bias_factor(), 0.2);
  EXPECT_EQ(solver.slop(), 1e-3);
  EXPECT_EQ(solver.mode(), SolverMode::Exact);
}

TEST(SolverFromMsg, OutOfRangeSettingsNameTheField)
{
  SolverSettings msg = valid_settings();
  msg.restitution = 1.2;
  EXPECT_EQ(settings_rejection(msg), "settings: restitution = 1.2 must be in [0, 1]");
  msg = valid_settings();
  msg.friction = -1.0;
  EXPECT_EQ(settings_rejection(msg), "settings: friction = -1 must be >= 0");
  msg = valid_settings();
  msg.iterations = 0;
  EXPECT_EQ(settings_rejection(msg), "settings: iterations = 0 must be in [1, 100000]");
  msg = valid_settings();
  msg.tolerance = 0.0;
  EXPECT_EQ(settings_rejection(msg), "settings: tolerance = 0 must be > 0");
  msg = valid_settings();
  msg.bias_factor = kNaN;
  EXPECT_EQ(settings_rejection(msg), "settings: bias_factor = nan is not finite");
  msg = valid_settings();
  msg.slop = -1e-3;
  EXPECT_EQ(settings_rejection(msg), "settings: slop = -0.001 must be >= 0");
  msg = valid_settings();
  msg.mode = 4;
  EXPECT_EQ(settings_rejection(msg), "settings: mode = 4 is not ITERATIVE (0) or EXACT (1)");
}

TEST(WorldSettingsMsg, RoundTripAndRejection)
{
  WorldSettings settings;
  settings.gravity = Vec2{1.0, -3.0};
  settings.dt = 0.01;
  settings.substeps = 8;
  settings.friction = Toggle::Off;
  settings.sleeping = Toggle::On;
  settings.toi_displacement_fraction = 0.25;
  settings.warm_start_before_integration = true;
  settings.sleep_time = 2.0;
  settings.sleep_auto_min_bodies = 10;
  const WorldSettings back = world_settings_from_msg(world_settings_to_msg(settings));
  EXPECT_EQ(back.toi_displacement_fraction, 0.25);
  EXPECT_TRUE(back.warm_start_before_integration);
  EXPECT_EQ(back.sleep_time, 2.0);
  EXPECT_EQ(back.sleep_auto_min_bodies, 10u);
  EXPECT_EQ(back.gravity, settings.gravity);
  EXPECT_EQ(back.dt, settings.dt);
  EXPECT_EQ(back.substeps, settings.substeps);
  EXPECT_EQ(back.friction, Toggle::Off);
  EXPECT_EQ(back.sleeping, Toggle::On);
  EXPECT_EQ(back.rotation, Toggle::Auto);

  WorldConfig bad = world_settings_to_msg(settings);
  bad.warm_starting = 3;
  EXPECT_THROW(world_settings_from_msg(bad), InvalidRequest);
  bad = world_settings_to_msg(settings);
  bad.dt = -1.0;
  try
  {
    world_settings_from_msg(bad);
    FAIL() << "negative dt accepted";
  }
  catch (const InvalidRequest& e)
  {
    EXPECT_NE(std::string(e.what()).find("dt"), std::string::npos) << e.what();
  }
}

std::string world_rejection(const WorldConfig& msg)
{
  return rejection_of([&] { world_settings_from_msg(msg); });
}

TEST(WorldSettingsMsg, SolverFieldsRoundTrip)
{
  // Each field away from its default, so a field the conversion drops comes
  // back as the default and fails.
  WorldSettings settings;
  settings.solver_mode = SolverMode::Exact;
  settings.position_iterations = WorldSettings().position_iterations + 3;
  settings.position_block = !WorldSettings().position_block;
  settings.exact_position_correction = !WorldSettings().exact_position_correction;
  settings.warm_start_before_integration = !WorldSettings().warm_start_before_integration;
  const WorldConfig msg = world_settings_to_msg(settings);
  EXPECT_EQ(msg.solver_mode, WorldConfig::SOLVER_EXACT);
  EXPECT_EQ(msg.position_iterations, settings.position_iterations);
  EXPECT_EQ(msg.position_block, settings.position_block);
  EXPECT_EQ(msg.exact_position_correction, settings.exact_position_correction);
  EXPECT_EQ(msg.warm_start_before_integration, settings.warm_start_before_integration);
  const WorldSettings back = world_settings_from_msg(msg);
  EXPECT_EQ(back.solver_mode, SolverMode::Exact);
  EXPECT_EQ(back.position_iterations, settings.position_iterations);
  EXPECT_EQ(back.position_block, settings.position_block);
  EXPECT_EQ(back.exact_position_correction, settings.exact_position_correction);
  EXPECT_EQ(back.warm_start_before_integration, settings.warm_start_before_integration);
  // And back to iterative: the message's default value is not a fixed point.
  settings.solver_mode = SolverMode::Iterative;
  EXPECT_EQ(world_settings_to_msg(settings).solver_mode, WorldConfig::SOLVER_ITERATIVE);
  EXPECT_EQ(world_settings_from_msg(world_settings_to_msg(settings)).solver_mode, SolverMode::Iterative);
}

TEST(WorldSettingsMsg, BadSolverFieldsNameTheField)
{
  WorldConfig msg = world_settings_to_msg(WorldSettings());
  msg.solver_mode = 7;
  EXPECT_EQ(world_rejection(msg), "settings: solver_mode = 7 is not SOLVER_ITERATIVE (0) or SOLVER_EXACT (1)");
  msg = world_settings_to_msg(WorldSettings());
  msg.position_iterations = 0;
  EXPECT_NE(world_rejection(msg).find("position_iterations"), std::string::npos) << world_rejection(msg);
  // A default-constructed message is no set of defaults: its zero dt,
  // substeps and iterations are refused, as before these fields existed.
  EXPECT_NE(world_rejection(WorldConfig()), "");
}

// Reconfigure and every-field round trips: test_settings_tables.cpp.

class WorldServiceTest : public ::testing::Test
{
protected:
  static void SetUpTestCase() { ::ros::Time::init(); }

  WorldService service_{WorldServiceOptions{}};
};

/// Header stamps differ between calls; everything else must not.
void expect_same_world(WorldState a, WorldState b)
{
  a.header = b.header;
  EXPECT_TRUE(a == b) << "the world changed";
}

TEST_F(WorldServiceTest, FailedChangesLeaveTheWorldAsItWas)
{
  SetWorld::Request set;
  set.keep_settings = true;
  set.bodies = {disk(0, 0, 1), disk(1, 3, 1)};
  SetWorld::Response set_response;
  service_.set_world(set, set_response);
  ASSERT_TRUE(set_response.success) << set_response.message;
  StepWorld::Request step;
  step.frames = 3;
  StepWorld::Response step_response;
  service_.step(step, step_response);
  ASSERT_TRUE(step_response.success) << step_response.message;
  const WorldState before = service_.state();

  set.bodies.push_back(disk(2, 0, 0, -1.0));
  service_.set_world(set, set_response);
  EXPECT_FALSE(set_response.success);
  EXPECT_NE(set_response.message.find("bodies[2] (id 2): radius = -1"), std::string::npos) << set_response.message;
  step.dt = -0.5;
  service_.step(step, step_response);
  EXPECT_FALSE(step_response.success);
  EXPECT_NE(step_response.message.find("dt = -0.5 must be > 0"), std::string::npos) << step_response.message;
  expect_same_world(before, service_.state());
}

TEST_F(WorldServiceTest, DtOfOneRequestDoesNotStick)
{
  const double world_dt = service_.settings().dt;
  StepWorld::Request step;
  step.frames = 4;
  step.dt = 0.25 * world_dt;
  StepWorld::Response response;
  service_.step(step, response);
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_EQ(response.frame_count, 4u);
  EXPECT_NEAR(response.sim_time, 4 * step.dt, 1e-12);
  EXPECT_EQ(service_.settings().dt, world_dt);
}

TEST_F(WorldServiceTest, StepAnswersASummaryUnlessAskedForTheState)
{
  service_.load("bouncing_disks");
  StepWorld::Request step;
  step.frames = 2;
  StepWorld::Response summary;
  service_.step(step, summary);
  ASSERT_TRUE(summary.success) << summary.message;
  EXPECT_EQ(summary.frame_count, 2u);
  EXPECT_EQ(summary.body_count, service_.state().bodies.size());
  EXPECT_GT(summary.body_count, 0u);
  EXPECT_TRUE(summary.state.empty());
  EXPECT_EQ(summary.report.frames, 2);

  step.return_state = true;
  StepWorld::Response full;
  service_.step(step, full);
  ASSERT_TRUE(full.success) << full.message;
  ASSERT_EQ(full.state.size(), 1u);
  EXPECT_EQ(full.state[0].frame_count, 4u);
  EXPECT_EQ(full.state[0].bodies.size(), full.body_count);
  EXPECT_EQ(full.state[0].frame_count, service_.state().frame_count);
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
