// Conversions and validation of the ROS face, without a master: each bad
// input class is rejected with a message naming the body and the field, and
// valid messages convert to the bodies and settings they describe.
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

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kManyBodies = 1000;

BodyMsg disk(std::uint32_t id, double x, double y, double radius = 0.5, double mass = 1.0)
{
  BodyMsg msg;
  msg.id = id;
  msg.shape = BodyMsg::DISK;
  msg.type = BodyMsg::DYNAMIC;
  msg.mass = mass;
  msg.radius = radius;
  msg.pose.x = x;
  msg.pose.y = y;
  return msg;
}

BodyMsg polygon(std::uint32_t id, const std::vector<Vec2>& outline, double x = 0.0, double y = 0.0)
{
  BodyMsg msg = disk(id, x, y);
  msg.shape = BodyMsg::POLYGON;
  msg.radius = 0.0;
  for (const Vec2& v : outline)
  {
    geometry_msgs::Point p;
    p.x = v.x;
    p.y = v.y;
    msg.vertices.push_back(p);
  }
  return msg;
}

const std::vector<Vec2> kUnitSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

/// The message of the InvalidRequest that `convert` throws ("" if none).
template <typename Convert>
std::string rejection_of(Convert convert)
{
  try
  {
    convert();
  }
  catch (const InvalidRequest& e)
  {
    return e.what();
  }
  return "";
}

std::string rejection(const std::vector<BodyMsg>& bodies)
{
  return rejection_of([&] { bodies_from_msgs(bodies, kManyBodies); });
}

/// A second body at index 1 with id 7 carries the defect, so the message
/// must name index and id rather than just "a body".
std::string rejection_of_second(const BodyMsg& bad)
{
  BodyMsg second = bad;
  second.id = 7;
  return rejection({disk(3, -10.0, 0.0), second});
}

void expect_names(const std::string& message, const std::string& field)
{
  EXPECT_NE(message.find("bodies[1] (id 7)"), std::string::npos) << message;
  EXPECT_NE(message.find(field), std::string::npos) << "expected '" << field << "' in: " << message;
}

TEST(BodyFromMsg, DiskCarriesPoseTwistAndType)
{
  BodyMsg msg = disk(4, 1.0, 2.0, 0.25, 3.0);
  msg.pose.theta = 0.3;
  msg.twist.linear.x = -1.0;
  msg.twist.linear.y = 0.5;
  msg.twist.angular.z = 2.0;
  msg.type = BodyMsg::KINEMATIC;
  const Body body = scene_body_from_msg(msg, "b").body;
  EXPECT_EQ(body.shape(), Shape::Disk);
  EXPECT_EQ(body.type(), BodyType::Kinematic);
  EXPECT_EQ(body.mass(), 3.0);
  EXPECT_EQ(body.radius(), 0.25);
  EXPECT_EQ(body.position(), (Vec2{1.0, 2.0}));
  EXPECT_EQ(body.theta(), 0.3);
  EXPECT_EQ(body.velocity(), (Vec2{-1.0, 0.5}));
  EXPECT_EQ(body.omega(), 2.0);
  // Static and kinematic bodies take no impulses.
  EXPECT_EQ(body.inv_mass(), 0.0);
}

TEST(BodyFromMsg, PolygonIsRecentredOnItsCentroid)
{
  const Body body = scene_body_from_msg(polygon(1, kUnitSquare, 5.0, 6.0), "b").body;
  ASSERT_EQ(body.vertex_count(), 4u);
  // The unit square's centroid is (0.5, 0.5): the outline comes back about it.
  EXPECT_NEAR(body.local_vertices()[0].x, -0.5, 1e-12);
  EXPECT_NEAR(body.local_vertices()[0].y, -0.5, 1e-12);
  EXPECT_EQ(body.position(), (Vec2{5.0, 6.0}));
  // Radius of a polygon is its bounding radius: half the diagonal.
  EXPECT_NEAR(body.radius(), std::sqrt(0.5), 1e-12);
}

TEST(BodyToMsg, RoundTripKeepsEveryField)
{
  BodyMsg msg = polygon(9, {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}}, 2.0, -1.0);
  msg.type = BodyMsg::STATIC;
  msg.pose.theta = 0.7;
  msg.twist.angular.z = 0.0;
  msg.material.restitution = 0.4;
  msg.material.static_friction = 0.6;
  msg.material.kinetic_friction = 0.5;
  const SceneBody converted = scene_body_from_msg(msg, "b");
  const BodyMsg back = body_to_msg(converted.body, msg.id, converted.material);
  EXPECT_EQ(back.id, msg.id);
  EXPECT_EQ(back.shape, msg.shape);
  EXPECT_EQ(back.type, msg.type);
  EXPECT_EQ(back.mass, msg.mass);
  EXPECT_EQ(back.pose, msg.pose);
  EXPECT_EQ(back.twist, msg.twist);
  EXPECT_EQ(back.material, msg.material);
  ASSERT_EQ(back.vertices.size(), msg.vertices.size());
  for (std::size_t i = 0; i < msg.vertices.size(); ++i)
  {
    // Centred already, so the outline survives unchanged.
    EXPECT_NEAR(back.vertices[i].x, msg.vertices[i].x, 1e-12);
    EXPECT_NEAR(back.vertices[i].y, msg.vertices[i].y, 1e-12);
  }
}

TEST(BodyFromMsg, NonFiniteNumbersNameTheField)
{
  BodyMsg bad = disk(0, 0, 0);
  bad.mass = kNaN;
  expect_names(rejection_of_second(bad), "mass = nan is not finite");
  bad = disk(0, 0, 0);
  bad.pose.y = kInf;
  expect_names(rejection_of_second(bad), "pose.y = inf is not finite");
  bad = disk(0, 0, 0);
  bad.twist.angular.z = -kInf;
  expect_names(rejection_of_second(bad), "twist.angular.z = -inf");
  bad = polygon(0, kUnitSquare);
  bad.vertices[2].x = kNaN;
  expect_names(rejection_of_second(bad), "vertices[2].x = nan");
  bad = disk(0, 0, 0);
  bad.material.static_friction = kNaN;
  expect_names(rejection_of_second(bad), "material.static_friction = nan");
}

TEST(BodyFromMsg, NonPositiveMassOrRadius)
{
  expect_names(rejection_of_second(disk(0, 0, 0, 0.5, 0.0)), "mass = 0 must be > 0");
  expect_names(rejection_of_second(disk(0, 0, 0, 0.5, -2.0)), "mass = -2 must be > 0");
  expect_names(rejection_of_second(disk(0, 0, 0, -0.5)), "radius = -0.5 must be > 0");
  expect_names(rejection_of_second(disk(0, 0, 0, 0.0)), "radius = 0 must be > 0");
}

TEST(BodyFromMsg, BadOutlines)
{
  expect_names(rejection_of_second(polygon(0, {{0, 0}, {1, 0}})), "2 given, a POLYGON needs at least 3");
  expect_names(rejection_of_second(polygon(0, {{0, 0}, {0, 1}, {1, 1}, {1, 0}})), "clockwise");
  expect_names(rejection_of_second(polygon(0, {{0, 0}, {2, 0}, {1, 0.2}, {2, 2}, {0, 2}})),
               "vertices[2]: the outline turns clockwise here, so it is not convex");
  expect_names(rejection_of_second(polygon(0, {{0, 0}, {1, 0}, {2, 0}})), "zero area");
  expect_names(rejection_of_second(polygon(0, {{0, 0}, {1, 0}, {1, 0}, {0, 1}})), "vertices[2] repeats vertices[1]");
  // A pentagram turns left at every vertex but winds around twice.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k)
  {
    const double angle = 4.0 * M_PI * k / 5.0;
    star.push_back({std::cos(angle), std::sin(angle)});
  }
  expect_names(rejection_of_second(polygon(0, star)), "more than once");
}

TEST(BodyFromMsg, UnknownShapeOrTypeAndStrayVertices)
{
  BodyMsg bad = disk(0, 0, 0);
  bad.shape = 5;
  expect_names(rejection_of_second(bad), "shape = 5 is not DISK (0) or POLYGON (1)");
  bad = disk(0, 0, 0);
  bad.type = 9;
  expect_names(rejection_of_second(bad), "type = 9");
  bad = polygon(0, kUnitSquare);
  bad.shape = BodyMsg::DISK;
  bad.radius = 1.0;
  expect_names(rejection_of_second(bad), "a DISK takes none (4 given)");
}

TEST(BodyFromMsg, MaterialOutOfRange)
{
  BodyMsg bad = disk(0, 0, 0);
  bad.material.restitution = 1.5;
  expect_names(rejection_of_second(bad), "material.restitution = 1.5 must be in [0, 1]");
  bad = disk(0, 0, 0);
  bad.material.kinetic_friction = -0.1;
  expect_names(rejection_of_second(bad), "material.kinetic_friction = -0.1 must be >= 0");
}

TEST(BodiesFromMsgs, CoincidentCentresNameBothBodies)
{
  const std::string message = rejection({disk(3, 0, 0), disk(4, 5, 5), disk(8, 0, 0)});
  EXPECT_NE(message.find("bodies[0] (id 3) and bodies[2] (id 8)"), std::string::npos) << message;
  EXPECT_NE(message.find("centres coincide"), std::string::npos) << message;
  // Touching is fine: only a shared centre leaves the normal undefined.
  EXPECT_EQ(rejection({disk(3, 0, 0), disk(4, 1, 0)}), "");
}

TEST(BodiesFromMsgs, LimitAndDuplicateIds)
{
  std::vector<BodyMsg> bodies;
  for (std::uint32_t i = 0; i < 4; ++i)
  {
    bodies.push_back(disk(i, 2.0 * i, 0));
  }
  try
  {
    bodies_from_msgs(bodies, 3);
    FAIL() << "4 bodies passed a limit of 3";
  }
  catch (const InvalidRequest& e)
  {
    EXPECT_NE(std::string(e.what()).find("4 given, more than the limit of 3"), std::string::npos) << e.what();
  }
  bodies[3].id = 1;
  EXPECT_NE(rejection(bodies).find("bodies[3] (id 1): id repeats that of bodies[1]"), std::string::npos);
  // The world services label bodies by index only and accept repeated ids.
  EXPECT_EQ(scene_bodies_from_msgs(bodies, kManyBodies).size(), 4u);
}

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
