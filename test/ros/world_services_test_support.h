// Shared by the world services' rostest client (test_world_services.cpp and
// test_world_services_rejects.cpp, one test binary): service calls, the
// shipped scenes' bodies looked up, and the fixture that keeps a known world
// to compare against after a refused request.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/messages.h"

#include "ros_test_helpers.h"

namespace collision2d
{
namespace world_services_test
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

inline WorldState get_world()
{
  const GetWorld srv = call<GetWorld>("get_world");
  EXPECT_TRUE(srv.response.success);
  return srv.response.state;
}

inline WorldState load(const std::string& scene)
{
  LoadScene::Request request;
  request.scene = scene;
  request.return_state = true;
  const LoadScene srv = call<LoadScene>("load_scene", request);
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_EQ(srv.response.state.size(), srv.response.success ? 1u : 0u);
  return srv.response.state.empty() ? WorldState() : srv.response.state.front();
}

/// A step that asks for the full state in the answer (return_state).
inline StepWorld::Response step(std::uint32_t frames, double dt = 0.0)
{
  StepWorld::Request request;
  request.frames = frames;
  request.dt = dt;
  request.return_state = true;
  const StepWorld srv = call<StepWorld>("step_world", request);
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  return srv.response;
}

inline const BodyMsg* find_body(const WorldState& state, std::uint32_t id)
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

inline VerticalExtent vertical_extent(const BodyMsg& body)
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
inline const BodyMsg* dynamic_by_mass(const WorldState& state, bool heaviest)
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

}  // namespace world_services_test
}  // namespace collision2d
