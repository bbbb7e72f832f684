// rostest client of the world services: StepWorld on shipped scenes (a resting
// stack stays, a dropped disk bounces, frames and time advance, the topic
// publishes), the other world services, and every bad-input class, each
// answered with success = false, a message naming the body and field, and the
// world (GetWorld) left exactly as it was.
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

namespace collision2d
{
namespace
{
using ros_test::box_msg;
using ros_test::contains;
using ros_test::disk_msg;
using ros_test::same_world;

constexpr double kServiceWait = 30.0;  // s
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
/// The test launch file's ~max_bodies and ~max_frames_per_call.
constexpr std::size_t kMaxBodies = 64;
constexpr std::uint32_t kMaxFrames = 2000;

template <typename Service>
Service call(const std::string& name, const typename Service::Request& request = typename Service::Request())
{
  Service srv;
  srv.request = request;
  EXPECT_TRUE(ros::service::call(name, srv)) << name << ": transport failed";
  return srv;
}

WorldState get_world()
{
  const GetWorld srv = call<GetWorld>("get_world");
  EXPECT_TRUE(srv.response.success);
  return srv.response.state;
}

WorldState load(const std::string& scene)
{
  LoadScene::Request request;
  request.scene = scene;
  const LoadScene srv = call<LoadScene>("load_scene", request);
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  return srv.response.state;
}

/// A step that asks for the full state in the answer (return_state).
StepWorld::Response step(std::uint32_t frames, double dt = 0.0)
{
  StepWorld::Request request;
  request.frames = frames;
  request.dt = dt;
  request.return_state = true;
  const StepWorld srv = call<StepWorld>("step_world", request);
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  return srv.response;
}

const BodyMsg* find_body(const WorldState& state, std::uint32_t id)
{
  for (const BodyMsg& body : state.bodies)
  {
    if (body.id == id)
    {
      return &body;
    }
  }
  return nullptr;
}

/// Lowest and highest y of a polygon's outline, placed by its pose.
struct VerticalExtent
{
  double low;
  double high;
};

VerticalExtent vertical_extent(const BodyMsg& body)
{
  VerticalExtent extent{kInf, -kInf};
  const double c = std::cos(body.pose.theta);
  const double s = std::sin(body.pose.theta);
  for (const geometry_msgs::Point& v : body.vertices)
  {
    const double y = body.pose.y + s * v.x + c * v.y;
    extent.low = std::min(extent.low, y);
    extent.high = std::max(extent.high, y);
  }
  return extent;
}

/// The dynamic body of largest (heaviest = true) or smallest mass.
const BodyMsg* dynamic_by_mass(const WorldState& state, bool heaviest)
{
  const BodyMsg* found = nullptr;
  for (const BodyMsg& body : state.bodies)
  {
    if (body.type == BodyMsg::DYNAMIC &&
        (found == nullptr || (heaviest ? body.mass > found->mass : body.mass < found->mass)))
    {
      found = &body;
    }
  }
  return found;
}

class WorldServices : public ::testing::Test
{
protected:
  /// A known world to compare against after each failed request.
  void SetUp() override
  {
    load("resting_box");
    step(3);
    before_ = get_world();
    ASSERT_FALSE(before_.bodies.empty());
  }

  /// The failure message names what it must, and the world did not move.
  template <typename Response>
  void expect_rejected(const Response& response, const std::string& part)
  {
    EXPECT_FALSE(response.success);
    EXPECT_TRUE(contains(response.message, part));
    EXPECT_TRUE(same_world(before_, get_world()));
  }

  /// SetWorld with a valid first body and `bad` second (index 1, id 7).
  SetWorld::Response set_with_bad_second(BodyMsg bad)
  {
    bad.id = 7;
    SetWorld::Request request;
    request.keep_settings = true;
    request.bodies = {disk_msg(3, {-10.0, 5.0}), bad};
    return call<SetWorld>("set_world", request).response;
  }

  WorldState before_;
};

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
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  ASSERT_LT(set.response.state.settings.gravity.y, 0.0);

  // Fall (~0.64 s), bounce, and rise to the next apex.
  double lowest = kHeight, apex_after_bounce = 0.0;
  bool bounced = false;
  for (int frame = 0; frame < 150; ++frame)
  {
    const BodyMsg* disk = find_body(step(1).state.at(0), set.response.state.bodies[1].id);
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
  const double impact_speed = std::sqrt(2.0 * -set.response.state.settings.gravity.y * kHeight);
  EXPECT_LT(lowest, impact_speed * set.response.state.settings.dt) << "bounced before reaching the ground";
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
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  // Same bodies and settings, restarted at frame 0.
  ASSERT_EQ(set.response.state.bodies.size(), before_.bodies.size());
  for (std::size_t i = 0; i < before_.bodies.size(); ++i)
  {
    EXPECT_EQ(set.response.state.bodies[i].pose, before_.bodies[i].pose);
    EXPECT_EQ(set.response.state.bodies[i].twist, before_.bodies[i].twist);
    EXPECT_EQ(set.response.state.bodies[i].material, before_.bodies[i].material);
  }
  EXPECT_EQ(set.response.state.settings, before_.settings);
  EXPECT_EQ(set.response.state.frame_count, 0u);
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
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  for (const WorldConfig& shown : {set.response.state.settings, get_world().settings, step(1).state.at(0).settings})
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
    const BodyMsg* ground = find_body(response.state.at(0), set.response.state.bodies.front().id);
    ASSERT_TRUE(ground != nullptr && ground->type == BodyMsg::STATIC);
    EXPECT_LT(vertical_extent(*ground).high - vertical_extent(*light).low, allowed)
        << "the light box sank into the ground";
    // The report shows the islands were pivoted, none left to the passes.
    EXPECT_GT(response.report.exact_islands, 0u);
    EXPECT_EQ(response.report.exact_fallbacks, 0u);
  }
}

TEST_F(WorldServices, OverflowingStepIsRefusedAndTheWorldKept)
{
  // Gravity 1e308 m/s^2 with one-second frames: the second frame's velocity
  // passes the largest double. Finite, so validation lets it through; the
  // step must refuse instead of publishing inf, and keep the world.
  SetWorld::Request request;
  request.bodies = before_.bodies;
  request.settings = before_.settings;
  request.settings.gravity.y = -1e308;
  request.settings.dt = 1.0;
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  before_ = get_world();

  StepWorld::Request step_request;
  step_request.frames = 3;
  const StepWorld stepped = call<StepWorld>("step_world", step_request);
  expect_rejected(stepped.response, "overflowed to a non-finite state");
  EXPECT_TRUE(contains(stepped.response.message, "step_world failed")) << stepped.response.message;
}

TEST_F(WorldServices, NonFiniteNumbers)
{
  BodyMsg bad = disk_msg(0, {0.0, 0.0});
  bad.pose.x = kNaN;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): pose.x = nan is not finite");
  bad = disk_msg(0, {0.0, 0.0});
  bad.twist.linear.y = kInf;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): twist.linear.y = inf is not finite");
  AddBody::Request add;
  add.body = disk_msg(0, {1.0, 1.0});
  add.body.radius = kNaN;
  expect_rejected(call<AddBody>("add_body", add).response, "body: radius = nan is not finite");
}

TEST_F(WorldServices, NonPositiveMassOrRadius)
{
  expect_rejected(set_with_bad_second(disk_msg(0, {0.0, 0.0}, {}, 0.5, 0.0)), "bodies[1] (id 7): mass = 0 must be > 0");
  expect_rejected(set_with_bad_second(disk_msg(0, {0.0, 0.0}, {}, -0.1)),
                  "bodies[1] (id 7): radius = -0.1 must be > 0");
}

TEST_F(WorldServices, BadOutlines)
{
  BodyMsg bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  bad.vertices.resize(2);
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices: 2 given, a POLYGON needs at least 3");
  bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  std::reverse(bad.vertices.begin(), bad.vertices.end());
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices are clockwise");
  bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  bad.vertices[2].x = 0.0;  // (0.5, 0.5) -> (0, -0.2): a dent at vertex 2
  bad.vertices[2].y = -0.2;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices[2]: the outline turns clockwise here");
  bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  bad.vertices.resize(3);
  for (std::size_t i = 0; i < 3; ++i)
  {
    bad.vertices[i].x = 0.5 * i;  // three distinct points on a line
    bad.vertices[i].y = 0.0;
  }
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices enclose zero area");
}

TEST_F(WorldServices, UnknownShapeType)
{
  BodyMsg bad = disk_msg(0, {0.0, 0.0});
  bad.shape = 2;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): shape = 2 is not DISK (0) or POLYGON (1)");
}

TEST_F(WorldServices, CoincidentCentres)
{
  expect_rejected(set_with_bad_second(disk_msg(0, {-10.0, 5.0})), "bodies[0] (id 3) and bodies[1] (id 7)");
  AddBody::Request add;
  add.body = disk_msg(0, {before_.bodies.back().pose.x, before_.bodies.back().pose.y}, {}, 0.1);
  expect_rejected(call<AddBody>("add_body", add).response,
                  "centre coincides with that of body id " + std::to_string(before_.bodies.back().id));
}

TEST_F(WorldServices, OutOfRangeSettings)
{
  SetWorld::Request request;
  request.bodies = {disk_msg(0, {0.0, 0.0})};
  request.settings = before_.settings;
  request.settings.substeps = 0;
  expect_rejected(call<SetWorld>("set_world", request).response, "substeps");
  request.settings = before_.settings;
  request.settings.friction = 9;
  expect_rejected(call<SetWorld>("set_world", request).response, "settings: friction = 9 is not AUTO (0), ON (1) or OFF (2)");
  request.settings = before_.settings;
  request.settings.solver_mode = 7;
  expect_rejected(call<SetWorld>("set_world", request).response,
                  "settings: solver_mode = 7 is not SOLVER_ITERATIVE (0) or SOLVER_EXACT (1)");
  request.settings = before_.settings;
  request.settings.position_iterations = 0;
  expect_rejected(call<SetWorld>("set_world", request).response, "position_iterations");

  StepWorld::Request step_request;
  step_request.frames = 0;
  expect_rejected(call<StepWorld>("step_world", step_request).response, "frames = 0 must be in [1, 2000]");
  step_request.frames = kMaxFrames + 1;
  expect_rejected(call<StepWorld>("step_world", step_request).response, "frames = 2001");
  step_request.frames = 1;
  step_request.dt = kNaN;
  expect_rejected(call<StepWorld>("step_world", step_request).response, "dt = nan is not finite");

  ResolveContacts::Request resolve;
  resolve.bodies = {disk_msg(0, {0.0, 0.0})};
  resolve.settings = ros_test::solver_settings(-0.5, 0.0);
  expect_rejected(call<ResolveContacts>("resolve_contacts", resolve).response,
                  "settings: restitution = -0.5 must be in [0, 1]");
}

TEST_F(WorldServices, UnknownSceneOrBody)
{
  LoadScene::Request request;
  request.scene = "no_such_scene";
  const LoadScene srv = call<LoadScene>("load_scene", request);
  expect_rejected(srv.response, "unknown scene 'no_such_scene' (known: ");
  EXPECT_TRUE(std::find(srv.response.available.begin(), srv.response.available.end(), "pyramid") !=
              srv.response.available.end());
  request.scene = "/nonexistent/scene.yaml";
  expect_rejected(call<LoadScene>("load_scene", request).response, "scene '/nonexistent/scene.yaml'");

  RemoveBody::Request remove;
  remove.id = 123456;
  expect_rejected(call<RemoveBody>("remove_body", remove).response, "id 123456: no body with this id");
}

TEST_F(WorldServices, MoreBodiesThanTheLimit)
{
  SetWorld::Request request;
  request.keep_settings = true;
  for (std::uint32_t i = 0; i <= kMaxBodies; ++i)
  {
    request.bodies.push_back(disk_msg(i, {2.0 * i, 0.0}));
  }
  expect_rejected(call<SetWorld>("set_world", request).response, "65 given, more than the limit of 64");
  // A shipped scene above the limit is refused the same way (pyramid: 210 boxes).
  LoadScene::Request load_request;
  load_request.scene = "pyramid";
  expect_rejected(call<LoadScene>("load_scene", load_request).response, "more than the limit of 64");
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
    if (!ros::service::waitForService(service, ros::Duration(collision2d::kServiceWait)))
    {
      ADD_FAILURE() << service << " never came up";
    }
  }
  return RUN_ALL_TESTS();
}
