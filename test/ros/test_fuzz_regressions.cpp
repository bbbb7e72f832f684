// Inputs fuzz/fuzz_ros_conversion.cpp found, replayed through the service's
// ResolveContacts handler without a master. Each keeps the contract the
// fuzzer checks: the request is answered (never an exception), a success
// carries only finite numbers, a failure carries a message and nothing else.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/resolve_contacts.h"
#include "collision2d/vec2.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr std::size_t kMaxBodies = 64;
constexpr double kPromisedMaxSpeed = 1e4;  ///< m/s, the fastest input the core promises finite output for

struct Numbers
{
  std::uint32_t id;
  std::uint8_t shape;
  std::uint8_t type;
  double mass;
  double radius;
  double x, y, theta;
  double vx, vy, omega;
  double restitution, static_friction, kinetic_friction;
};

BodyMsg body(const Numbers& n, const std::vector<Vec2>& vertices = {})
{
  BodyMsg msg;
  msg.id = n.id;
  msg.shape = n.shape;
  msg.type = n.type;
  msg.mass = n.mass;
  msg.radius = n.radius;
  msg.pose.x = n.x;
  msg.pose.y = n.y;
  msg.pose.theta = n.theta;
  msg.twist.linear.x = n.vx;
  msg.twist.linear.y = n.vy;
  msg.twist.angular.z = n.omega;
  msg.material.restitution = n.restitution;
  msg.material.static_friction = n.static_friction;
  msg.material.kinetic_friction = n.kinetic_friction;
  for (const Vec2& v : vertices)
  {
    geometry_msgs::Point p;
    p.x = v.x;
    p.y = v.y;
    msg.vertices.push_back(p);
  }
  return msg;
}

/// The fuzzer's crash-cfe32e0c: EXACT mode, friction 1.75, a 1e-6 kg disk hit
/// by a 1.4e4 m/s kinematic sliver. The exact solve overflowed to a
/// non-finite velocity, which the core refused and the handler's catch-all
/// answered ("resolve_contacts failed: body 2: velocity is not finite").
ResolveContacts::Request exact_mode_overflow()
{
  ResolveContacts::Request request;
  request.bodies = {
      body({12, 1, 1, 7.4306829949706001, 0, -11.606282991736595, -8.906247615814209, -6.2449682357925029,
            5709.7772188611007, -2346.5611934846529, -1816.9868131051301, 0.49320337569316935, 0.28936753835802836,
            0.99661174653660078},
           {{0.54687576944325322, 2.7551248047808182e-05},
            {-0.53885609257493461, -0.00012803278653665887},
            {0.54726217078264316, -1.7960656312998034e-19}}),
      body({10, 0, 0, 0.020435057613706047, 5.2363858357684752, 19.999999990686774, -20, -6.2831853071795862,
            -9999.9993294474625, -10000, -0.0, 0, 0, 0}),
      body({0, 0, 0, 1.0000000046719665e-06, 19.547154954444402, 4.5680471364636643, -16.387268432913679,
            -0.23856482106722154, 4624.0676603770444, -2665.6993586537524, 5999.2255143197262, 0.7415510422001943,
            0.68538562156935923, 0.8925468551542759}),
      body({9, 1, 2, 1.1491472271192003, 0, 9.0938115139150142, -11.198803855826025, -1.47438788133858,
            -9999.9356269835043, 9891.177556132252, -624.39166246672085, 0.69383855818298312, 0.47690213523938557,
            0.46992525112957101},
           {{2.2225963089475833, 0.0039852457104524279},
            {2.0820602592095168, 0.004294300816669953},
            {-1.6466656005858566, 0.0050306962264322118},
            {-2.3547519515080704, 0.0036501375131907654}}),
  };
  request.settings.restitution = 0.86026101859717241;
  request.settings.friction = 1.7522759658471811;
  request.settings.iterations = 59;
  request.settings.tolerance = 5.7066130135575334e-06;
  request.settings.bias_factor = 0.24692195831809174;
  request.settings.slop = 0.040832958112770053;
  request.settings.mode = SolverSettings::EXACT;
  return request;
}

bool finite(const BodyMsg& b)
{
  return std::isfinite(b.pose.x) && std::isfinite(b.pose.y) && std::isfinite(b.pose.theta) &&
         std::isfinite(b.twist.linear.x) && std::isfinite(b.twist.linear.y) && std::isfinite(b.twist.angular.z);
}

/// The handler's contract for any request.
void expect_answered(const ResolveContacts::Request& request, ResolveContacts::Response& response)
{
  ASSERT_NO_THROW(resolve_contacts(request, SolverSettings(), kMaxBodies, response));
  if (!response.success)
  {
    EXPECT_FALSE(response.message.empty());
    EXPECT_TRUE(response.bodies.empty() && response.contacts.empty()) << "a failure with results";
    return;
  }
  ASSERT_EQ(response.bodies.size(), request.bodies.size());
  for (const BodyMsg& b : response.bodies)
  {
    EXPECT_TRUE(finite(b)) << "body id " << b.id << " is not finite";
  }
  EXPECT_TRUE(std::isfinite(response.report.kinetic_energy_after));
}

TEST(FuzzRegression, ExactModeAboveThePromisedSpeedIsAnswered)
{
  ResolveContacts::Response response;
  expect_answered(exact_mode_overflow(), response);
}

/// The same scene slowed to just inside the promised speed range must be
/// solved, with finite output, in both modes.
TEST(FuzzRegression, SameSceneInsideThePromisedSpeedIsSolvedInBothModes)
{
  constexpr double kMargin = 0.999;
  for (const std::uint8_t mode : {SolverSettings::ITERATIVE, SolverSettings::EXACT})
  {
    ResolveContacts::Request request = exact_mode_overflow();
    request.settings.mode = mode;
    for (BodyMsg& b : request.bodies)
    {
      const double speed = std::hypot(b.twist.linear.x, b.twist.linear.y);
      const double factor = std::min(1.0, kMargin * kPromisedMaxSpeed / speed);
      b.twist.linear.x *= factor;
      b.twist.linear.y *= factor;
    }
    ResolveContacts::Response response;
    expect_answered(request, response);
    EXPECT_TRUE(response.success) << "mode " << int(mode) << ": " << response.message;
  }
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
