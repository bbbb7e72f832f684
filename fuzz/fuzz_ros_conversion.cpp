// libFuzzer target: raw bytes -> a ResolveContacts request -> the service's
// own handler (ros_interface::resolve_contacts: validation, message-to-core
// conversion, detect, solve, correct, and back). Built by scripts/fuzz_ros.sh.
//
// The request is filled field by field from the bytes: bodies near each other
// (so they touch) with any shape, type and id values, valid convex outlines or
// raw vertex lists, and solver settings in and out of range. One input in
// kRawInputOneIn may also set any double field to an unconstrained value
// (NaN, inf, 1e308). The request then goes through ROS serialisation and back,
// as it would over the wire.
//
// Checked: no sanitizer report; a rejection is a message naming a body or
// the settings with nothing else filled in; the handler's catch-all
// ("resolve_contacts failed: ...", the core refusing what validation let through)
// answers only requests outside the ranges the core promises finite output
// for (fuzz_support.h); an accepted request echoes every body id in order,
// and inside those ranges every output is finite and an all-dynamic scene
// keeps its linear momentum. (Found: EXACT mode at 1.4e4 m/s, above the
// 1e4 m/s range, overflows; test/ros/test_fuzz_regressions.cpp.)
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <ros/console.h>
#include <ros/serialization.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/resolve_contacts.h"
#include "fuzz_support.h"

using namespace collision2d;

namespace
{
constexpr double kTwoPi = 6.283185307179586;
constexpr int kMaxBodies = 10;
constexpr int kMaxVertices = 10;
constexpr std::size_t kMaxRequestBodies = 64;  ///< the node's ~max_bodies, small so limits are hit
constexpr std::uint32_t kMaxId = 12;           ///< few distinct ids: repeats happen
constexpr int kMaxIterations = 256;
constexpr double kMomentumRelativeTol = 1e-8;
constexpr int kRawInputOneIn = 8;
constexpr int kRawFieldOneIn = 6;

/// Draws fields; in one input of kRawInputOneIn some fields are raw doubles.
class Draw
{
public:
  explicit Draw(FuzzedDataProvider& in) : in_(in), raw_allowed_(in.ConsumeIntegralInRange(0, kRawInputOneIn - 1) == 0)
  {
  }

  double range(double lo, double hi)
  {
    if (raw_allowed_ && in_.ConsumeIntegralInRange(0, kRawFieldOneIn - 1) == 0)
    {
      return in_.ConsumeFloatingPoint<double>();
    }
    return in_.ConsumeFloatingPointInRange(lo, hi);
  }
  double log_range(double lo, double hi) { return std::exp(range(std::log(lo), std::log(hi))); }
  FuzzedDataProvider& in() { return in_; }

private:
  FuzzedDataProvider& in_;
  bool raw_allowed_;
};

geometry_msgs::Point point(double x, double y)
{
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  return p;
}

/// Mostly a convex counter-clockwise outline (sorted angles on an ellipse),
/// sometimes points in any order, count or repetition.
std::vector<geometry_msgs::Point> vertices(Draw& draw, double size)
{
  std::vector<geometry_msgs::Point> out;
  const int count = draw.in().ConsumeIntegralInRange(0, kMaxVertices);
  if (draw.in().ConsumeIntegralInRange(0, 3) == 0)
  {
    for (int i = 0; i < count; ++i)
    {
      const double x = size * draw.range(-1.0, 1.0);  // one draw a statement: inputs decode alike under clang and gcc
      out.push_back(point(x, size * draw.range(-1.0, 1.0)));
    }
    return out;
  }
  const double aspect = draw.log_range(1.0, 1000.0);
  std::vector<double> angles;
  for (int i = 0; i < std::max(count, 3); ++i)
  {
    angles.push_back(draw.range(0.0, kTwoPi));
  }
  std::sort(angles.begin(), angles.end());
  for (double a : angles)
  {
    out.push_back(point(size * std::cos(a), size / aspect * std::sin(a)));
  }
  return out;
}

BodyMsg body(Draw& draw, double scale, double speed)
{
  FuzzedDataProvider& in = draw.in();
  BodyMsg msg;
  msg.id = in.ConsumeIntegralInRange<std::uint32_t>(0, kMaxId);
  msg.shape = in.ConsumeIntegralInRange<std::uint8_t>(0, 2);
  msg.type = in.ConsumeIntegralInRange(0, 9) < 8 ? BodyMsg::DYNAMIC : in.ConsumeIntegralInRange<std::uint8_t>(1, 3);
  msg.mass = draw.log_range(fuzz::kMinMass, fuzz::kMaxMass);
  msg.mass *= in.ConsumeIntegralInRange(0, 15) == 0 ? -1.0 : 1.0;
  const double size = scale * draw.log_range(0.05, 2.0);
  if (msg.shape == BodyMsg::DISK)
  {
    msg.radius = size;
  }
  if (msg.shape != BodyMsg::DISK || in.ConsumeIntegralInRange(0, 15) == 0)
  {
    msg.vertices = vertices(draw, size);
  }
  msg.pose.x = scale * draw.range(-2.0, 2.0);
  msg.pose.y = scale * draw.range(-2.0, 2.0);
  msg.pose.theta = draw.range(-kTwoPi, kTwoPi);
  msg.twist.linear.x = speed * draw.range(-1.0, 1.0);
  msg.twist.linear.y = speed * draw.range(-1.0, 1.0);
  msg.twist.angular.z = draw.range(-fuzz::kMaxSpin, fuzz::kMaxSpin);
  msg.twist.angular.z *= draw.range(0.0, 1.0);
  msg.material.restitution = draw.range(0.0, 1.0);
  msg.material.static_friction = draw.range(0.0, 1.0);
  msg.material.kinetic_friction = draw.range(0.0, 1.0);
  return msg;
}

SolverSettings settings(Draw& draw, double scale)
{
  FuzzedDataProvider& in = draw.in();
  SolverSettings msg;
  msg.restitution = draw.range(-0.1, 1.1);
  msg.friction = draw.range(-0.1, 2.0);
  msg.iterations = in.ConsumeIntegralInRange(-1, kMaxIterations);
  msg.tolerance = draw.log_range(1e-14, 1e-3);
  msg.bias_factor = draw.range(-0.1, 1.1);
  msg.slop = scale * draw.range(-0.001, 0.01);
  msg.use_time_of_impact = in.ConsumeBool();
  msg.mode = in.ConsumeIntegralInRange<std::uint8_t>(0, 2);
  return msg;
}

/// The node's settings, used when a request sets use_node_settings.
SolverSettings node_settings()
{
  SolverSettings msg;
  msg.restitution = 0.5;
  msg.friction = 0.3;
  msg.iterations = 64;
  msg.tolerance = 1e-9;
  msg.bias_factor = 0.2;
  msg.slop = 1e-3;
  return msg;
}

std::vector<std::uint8_t> wire_bytes(const ResolveContacts::Request& request)
{
  namespace ser = ros::serialization;
  std::vector<std::uint8_t> buffer(ser::serializationLength(request));
  ser::OStream out(buffer.data(), static_cast<std::uint32_t>(buffer.size()));
  ser::serialize(out, request);
  return buffer;
}

/// Through the wire format and back, as roscpp delivers a request. Compared
/// as bytes: a NaN field never equals itself.
ResolveContacts::Request over_the_wire(const ResolveContacts::Request& request)
{
  std::vector<std::uint8_t> buffer = wire_bytes(request);
  ResolveContacts::Request received;
  ros::serialization::IStream in(buffer.data(), static_cast<std::uint32_t>(buffer.size()));
  ros::serialization::deserialize(in, received);
  fuzz::require(wire_bytes(received) == buffer, "request changed over the wire");
  return received;
}

bool in_range(const BodyMsg& b)
{
  const double speed = std::hypot(b.twist.linear.x, b.twist.linear.y);
  const bool mass_ok = b.type != BodyMsg::DYNAMIC || fuzz::within(b.mass, fuzz::kMinMass, fuzz::kMaxMass);
  bool size_ok = b.shape != BodyMsg::DISK || fuzz::within(b.radius, fuzz::kMinSize, fuzz::kMaxSize);
  for (const auto& v : b.vertices)
  {
    size_ok = size_ok && std::hypot(v.x, v.y) <= 2.0 * fuzz::kMaxSize;
  }
  return mass_ok && size_ok && std::abs(b.pose.x) <= fuzz::kMaxCoordinate &&
         std::abs(b.pose.y) <= fuzz::kMaxCoordinate && std::isfinite(b.pose.theta) &&
         std::abs(b.pose.theta) <= 1e3 && speed <= fuzz::kMaxSpeed && std::abs(b.twist.angular.z) <= fuzz::kMaxSpin;
}

bool finite(const BodyMsg& b)
{
  return std::isfinite(b.pose.x) && std::isfinite(b.pose.y) && std::isfinite(b.pose.theta) &&
         std::isfinite(b.twist.linear.x) && std::isfinite(b.twist.linear.y) && std::isfinite(b.twist.angular.z);
}

bool finite(const ContactMsg& c)
{
  return std::isfinite(c.point.x) && std::isfinite(c.point.y) && std::isfinite(c.normal.x) &&
         std::isfinite(c.normal.y) && std::isfinite(c.penetration) && std::isfinite(c.normal_impulse) &&
         std::isfinite(c.tangent_impulse);
}

bool finite(const SolverReport& r)
{
  return std::isfinite(r.max_residual) && std::isfinite(r.total_normal_impulse) &&
         std::isfinite(r.kinetic_energy_before) && std::isfinite(r.kinetic_energy_after) &&
         std::isfinite(r.momentum_after.x) && std::isfinite(r.momentum_after.y) &&
         std::isfinite(r.angular_momentum_after);
}

bool all_in_range(const ResolveContacts::Request& request)
{
  return std::all_of(request.bodies.begin(), request.bodies.end(), [](const BodyMsg& b) { return in_range(b); });
}

/// Validation names the body or the settings. The handler's catch-all
/// ("resolve_contacts failed: ...") answers what the core itself refused, e.g. a
/// solve that overflowed: acceptable only outside the promised ranges.
void check_rejection(const ResolveContacts::Request& request, const ResolveContacts::Response& response)
{
  const std::string& message = response.message;
  const bool names_field = message.rfind("bodies", 0) == 0 || message.rfind("settings", 0) == 0;
  const bool core_refused = message.rfind("resolve_contacts failed: ", 0) == 0 && !all_in_range(request);
  if (!names_field && !core_refused)
  {
    std::fprintf(stderr, "rejection: '%s'\n", message.c_str());
  }
  fuzz::require(names_field || core_refused, "rejection names neither a body nor the settings");
  fuzz::require(response.bodies.empty() && response.contacts.empty(), "rejection with results filled in");
}

void check_momentum(const ResolveContacts::Request& request, const ResolveContacts::Response& response)
{
  double px = 0.0;
  double py = 0.0;
  double scale = 0.0;
  for (std::size_t i = 0; i < request.bodies.size(); ++i)
  {
    const double m = request.bodies[i].mass;
    px += m * (response.bodies[i].twist.linear.x - request.bodies[i].twist.linear.x);
    py += m * (response.bodies[i].twist.linear.y - request.bodies[i].twist.linear.y);
    scale += m * (std::hypot(request.bodies[i].twist.linear.x, request.bodies[i].twist.linear.y) +
                  std::hypot(response.bodies[i].twist.linear.x, response.bodies[i].twist.linear.y));
  }
  fuzz::require(std::hypot(px, py) <= kMomentumRelativeTol * scale + 1e-300, "linear momentum not conserved");
}

void check_answer(const ResolveContacts::Request& request, const ResolveContacts::Response& response)
{
  fuzz::require(response.bodies.size() == request.bodies.size(), "body count changed");
  for (std::size_t i = 0; i < request.bodies.size(); ++i)
  {
    fuzz::require(response.bodies[i].id == request.bodies[i].id, "body ids not echoed in order");
  }
  if (!all_in_range(request))
  {
    return;  // finite but huge input may overflow: only the sanitizers judge it
  }
  for (const BodyMsg& b : response.bodies)
  {
    fuzz::require(finite(b), "non-finite body from in-range input");
  }
  for (const ContactMsg& c : response.contacts)
  {
    fuzz::require(finite(c), "non-finite contact from in-range input");
  }
  fuzz::require(finite(response.report), "non-finite report from in-range input");
  fuzz::require(std::isfinite(response.time_of_impact), "non-finite time of impact");
  if (std::all_of(request.bodies.begin(), request.bodies.end(),
                  [](const BodyMsg& b) { return b.type == BodyMsg::DYNAMIC; }))
  {
    check_momentum(request, response);
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/)
{
  // Most inputs are refused, each with a WARN: printing them took most of
  // the fuzzer's time. Errors still show.
  if (ros::console::set_logger_level(ROSCONSOLE_ROOT_LOGGER_NAME, ros::console::levels::Error))
  {
    ros::console::notifyLoggerLevelsChanged();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  Draw draw(in);
  const double scale = std::pow(10.0, in.ConsumeIntegralInRange(-4, 4));
  const double speed = std::pow(10.0, in.ConsumeIntegralInRange(-2, 4));
  ResolveContacts::Request request;
  request.settings = settings(draw, scale);
  request.settings.use_node_settings = in.ConsumeIntegralInRange(0, 7) == 0;
  const int count = in.ConsumeIntegralInRange(0, kMaxBodies);
  for (int i = 0; i < count; ++i)
  {
    request.bodies.push_back(body(draw, scale, speed));
  }
  request = over_the_wire(request);

  ResolveContacts::Response response;
  ros_interface::resolve_contacts(request, node_settings(), kMaxRequestBodies, response);
  if (response.success)
  {
    check_answer(request, response);
  }
  else
  {
    check_rejection(request, response);
  }
  return 0;
}
