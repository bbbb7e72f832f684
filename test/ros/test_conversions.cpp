// Conversions and validation of the ROS face, without a master: each bad
// input class is rejected with a message naming the body and the field, and
// valid messages convert to the bodies they describe. Settings and the world
// service are test_conversions_settings.cpp, linked into the same binary.
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

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
