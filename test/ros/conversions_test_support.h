// Shared by the conversion tests of the ROS face (test_conversions.cpp and
// test_conversions_settings.cpp, one test binary): bodies as messages, and
// the message of the InvalidRequest a conversion throws.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/world_service.h"

#include "ros_test_helpers.h"

namespace collision2d
{
namespace ros_interface
{
namespace conversions_test
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kManyBodies = 1000;

/// A dynamic disk at rest (ros_test::disk_msg with the position as x, y).
inline BodyMsg disk(std::uint32_t id, double x, double y, double radius = 0.5, double mass = 1.0)
{
  return ros_test::disk_msg(id, Vec2{x, y}, Vec2{}, radius, mass);
}

inline BodyMsg polygon(std::uint32_t id, const std::vector<Vec2>& outline, double x = 0.0, double y = 0.0)
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

inline const std::vector<Vec2> kUnitSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

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

inline std::string rejection(const std::vector<BodyMsg>& bodies)
{
  return rejection_of([&] { bodies_from_msgs(bodies, kManyBodies); });
}

/// A second body at index 1 with id 7 carries the defect, so the message
/// must name index and id rather than just "a body".
inline std::string rejection_of_second(const BodyMsg& bad)
{
  BodyMsg second = bad;
  second.id = 7;
  return rejection({disk(3, -10.0, 0.0), second});
}

inline void expect_names(const std::string& message, const std::string& field)
{
  EXPECT_NE(message.find("bodies[1] (id 7)"), std::string::npos) << message;
  EXPECT_NE(message.find(field), std::string::npos) << "expected '" << field << "' in: " << message;
}

}  // namespace conversions_test
}  // namespace ros_interface
}  // namespace collision2d
