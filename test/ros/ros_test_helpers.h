// Message builders and checks shared by the rostest clients.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/ros/messages.h"

#include "collision2d/vec2.h"

namespace collision2d
{
namespace ros_test
{
inline BodyMsg disk_msg(std::uint32_t id, Vec2 position, Vec2 velocity = Vec2{}, double radius = 0.5,
                          double mass = 1.0)
{
  BodyMsg msg;
  msg.id = id;
  msg.shape = BodyMsg::DISK;
  msg.type = BodyMsg::DYNAMIC;
  msg.mass = mass;
  msg.radius = radius;
  msg.pose.x = position.x;
  msg.pose.y = position.y;
  msg.twist.linear.x = velocity.x;
  msg.twist.linear.y = velocity.y;
  return msg;
}

inline BodyMsg box_msg(std::uint32_t id, double width, double height, Vec2 position, double mass = 1.0)
{
  BodyMsg msg = disk_msg(id, position, Vec2{}, 0.0, mass);
  msg.shape = BodyMsg::POLYGON;
  const double hx = 0.5 * width;
  const double hy = 0.5 * height;
  for (const Vec2& corner : {Vec2{-hx, -hy}, Vec2{hx, -hy}, Vec2{hx, hy}, Vec2{-hx, hy}})
  {
    geometry_msgs::Point p;
    p.x = corner.x;
    p.y = corner.y;
    msg.vertices.push_back(p);
  }
  return msg;
}

inline SolverSettings solver_settings(double restitution, double friction)
{
  // Converged far below the checks' tolerances, so the invariants hold to them.
  constexpr int kIterations = 20000;
  constexpr double kTolerance = 1e-11;
  SolverSettings msg;
  msg.restitution = restitution;
  msg.friction = friction;
  msg.iterations = kIterations;
  msg.tolerance = kTolerance;
  msg.bias_factor = 0.2;
  msg.slop = 1e-3;
  return msg;
}

inline ::testing::AssertionResult contains(const std::string& text, const std::string& part)
{
  if (text.find(part) != std::string::npos)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "'" << part << "' not in '" << text << "'";
}

/// Everything but the header stamp, which differs between calls.
inline ::testing::AssertionResult same_world(WorldState a, const WorldState& b)
{
  a.header = b.header;
  if (a == b)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "world changed: frame " << a.frame_count << " -> " << b.frame_count
                                       << ", bodies " << a.bodies.size() << " -> " << b.bodies.size();
}

}  // namespace ros_test
}  // namespace collision2d
