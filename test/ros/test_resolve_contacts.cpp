// rostest client of ResolveContacts: randomized scenes go through the service
// as any other node would send them, and the physics is recomputed from the
// request and the response (momentum, angular momentum, Newton targets,
// Coulomb cone, energy where guaranteed); the results must equal the core's.
#include <algorithm>
#include <cmath>
#include <future>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "collision2d/ros/messages.h"

#include "collision2d/contact_solver.h"
#include "collision2d/ros/conversions.h"
#include "collision2d/scenes/random_scenes.h"
#include "ros_test_helpers.h"

namespace collision2d
{
namespace
{
using ros_interface::body_to_msg;
using ros_test::contains;
using ros_test::disk_msg;
using ros_test::solver_settings;

constexpr double kServiceWait = 30.0;     // s, node start-up under a loaded machine
constexpr int kRandomScenes = 40;
constexpr std::uint64_t kSeed = 20240611;
constexpr double kVelocityTolerance = 1e-7;  // m/s
constexpr double kRelativeTolerance = 1e-9;
/// An id offset so a response that confused index and id is caught.
constexpr std::uint32_t kIdBase = 100;

ResolveContacts call(const ResolveContacts::Request& request)
{
  ResolveContacts srv;
  srv.request = request;
  EXPECT_TRUE(ros::service::call("resolve_contacts", srv)) << "transport failed";
  return srv;
}

Vec2 to_vec(const geometry_msgs::Point& p) { return {p.x, p.y}; }
Vec2 to_vec(const geometry_msgs::Vector3& v) { return {v.x, v.y}; }

/// Velocity of the material point of `body` at p, with the body centred at `centre`.
Vec2 point_velocity(const BodyMsg& body, Vec2 centre, Vec2 p)
{
  return Vec2{body.twist.linear.x, body.twist.linear.y} + cross(body.twist.angular.z, p - centre);
}

/// Core bodies with the request's poses and the given message's velocities:
/// the state the velocity solve ended in, before position correction.
std::vector<Body> solved_state(const std::vector<BodyMsg>& request, const std::vector<BodyMsg>& velocities)
{
  std::vector<Body> bodies = ros_interface::bodies_from_msgs(request, request.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    bodies[i].set_velocity({velocities[i].twist.linear.x, velocities[i].twist.linear.y});
    bodies[i].set_omega(velocities[i].twist.angular.z);
  }
  return bodies;
}

double scale_of(const std::vector<BodyMsg>& bodies)
{
  double scale = 1.0;
  for (const BodyMsg& b : bodies)
  {
    scale += b.mass * (std::abs(b.twist.linear.x) + std::abs(b.twist.linear.y) + std::abs(b.twist.angular.z)) *
             (1.0 + std::abs(b.pose.x) + std::abs(b.pose.y));
  }
  return scale;
}

/// Momentum and angular momentum of the whole request are conserved, both as
/// recomputed here and as the report states them.
void expect_conservation(const ResolveContacts& srv)
{
  const std::vector<Body> before = solved_state(srv.request.bodies, srv.request.bodies);
  const std::vector<Body> after = solved_state(srv.request.bodies, srv.response.bodies);
  Vec2 p0, p1;
  double l0 = 0.0, l1 = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i)
  {
    p0 += before[i].momentum();
    p1 += after[i].momentum();
    l0 += before[i].angular_momentum();
    l1 += after[i].angular_momentum();
  }
  const double tol = kRelativeTolerance * scale_of(srv.request.bodies);
  EXPECT_NEAR(p1.x, p0.x, tol);
  EXPECT_NEAR(p1.y, p0.y, tol);
  EXPECT_NEAR(l1, l0, tol);
  const SolverReport& report = srv.response.report;
  EXPECT_NEAR(report.momentum_before.x, p0.x, tol);
  EXPECT_NEAR(report.momentum_after.x, p0.x, tol);
  EXPECT_NEAR(report.momentum_after.y, p0.y, tol);
  EXPECT_NEAR(report.angular_momentum_after, report.angular_momentum_before, tol);
  EXPECT_NEAR(report.angular_momentum_before, l0, tol);
}

/// Newton targets from the request's approach speeds, complementarity,
/// Coulomb's cone and sticking inside it, at every contact point. Returns
/// whether energy is guaranteed not to rise (no contact that was not
/// approaching carries impulse).
bool expect_contact_laws(const ResolveContacts& srv)
{
  std::map<std::uint32_t, std::size_t> index;
  for (std::size_t i = 0; i < srv.request.bodies.size(); ++i)
  {
    index[srv.request.bodies[i].id] = i;
  }
  const double e = srv.request.settings.restitution;
  const double mu = srv.request.settings.friction;
  bool energy_guaranteed = true;
  for (const ContactMsg& c : srv.response.contacts)
  {
    const std::size_t a = index.at(c.body_a);
    const std::size_t b = index.at(c.body_b);
    const BodyMsg& a0 = srv.request.bodies[a];
    const BodyMsg& b0 = srv.request.bodies[b];
    const Vec2 ca{a0.pose.x, a0.pose.y};
    const Vec2 cb{b0.pose.x, b0.pose.y};
    const Vec2 p = to_vec(c.point);
    const Vec2 n = to_vec(c.normal);
    const Vec2 t = perp(n);
    const Vec2 rel0 = point_velocity(b0, cb, p) - point_velocity(a0, ca, p);
    const Vec2 rel1 = point_velocity(srv.response.bodies[b], cb, p) - point_velocity(srv.response.bodies[a], ca, p);
    const double approach = dot(rel0, n);
    const double target = approach < 0.0 ? -e * approach : 0.0;
    const double vn = dot(rel1, n);
    const double scale = 1.0 + std::abs(approach);
    EXPECT_NEAR(length(n), 1.0, 1e-12);
    EXPECT_GE(c.normal_impulse, 0.0) << "pulling contact " << c.body_a << "-" << c.body_b;
    EXPECT_GE(vn, target - kVelocityTolerance * scale) << "contact " << c.body_a << "-" << c.body_b;
    if (c.normal_impulse > 1e-9)
    {
      EXPECT_NEAR(vn, target, kVelocityTolerance * scale) << "pushing contact off its Newton target";
    }
    const double cone = mu * c.normal_impulse;
    EXPECT_LE(std::abs(c.tangent_impulse), cone + 1e-9) << "outside the Coulomb cone";
    if (std::abs(c.tangent_impulse) < cone - 1e-7)
    {
      EXPECT_NEAR(dot(rel1, t), 0.0, kVelocityTolerance * scale) << "inside the cone but slipping";
    }
    if (approach >= 0.0 && c.normal_impulse > 1e-12)
    {
      energy_guaranteed = false;
    }
  }
  return energy_guaranteed;
}

/// The reported impulses, applied at the reported points, account for every
/// body's change of velocity and spin: m dv = sum of J, I dw = sum of r x J.
void expect_impulses_explain_velocities(const ResolveContacts& srv)
{
  const std::vector<Body> before = solved_state(srv.request.bodies, srv.request.bodies);
  std::map<std::uint32_t, std::size_t> index;
  for (std::size_t i = 0; i < before.size(); ++i)
  {
    index[srv.request.bodies[i].id] = i;
  }
  std::vector<Vec2> linear(before.size());
  std::vector<double> angular(before.size(), 0.0);
  for (const ContactMsg& c : srv.response.contacts)
  {
    const Vec2 n = to_vec(c.normal);
    const Vec2 impulse = c.normal_impulse * n + c.tangent_impulse * perp(n);
    const Vec2 p = to_vec(c.point);
    const std::size_t a = index.at(c.body_a);
    const std::size_t b = index.at(c.body_b);
    linear[b] += impulse;
    linear[a] -= impulse;
    angular[b] += cross(p - before[b].position(), impulse);
    angular[a] -= cross(p - before[a].position(), impulse);
  }
  for (std::size_t i = 0; i < before.size(); ++i)
  {
    const BodyMsg& after = srv.response.bodies[i];
    const double tol = kRelativeTolerance * (1.0 + length(linear[i]) + std::abs(angular[i]));
    EXPECT_NEAR(before[i].mass() * (after.twist.linear.x - before[i].velocity().x), linear[i].x, tol) << "body " << i;
    EXPECT_NEAR(before[i].mass() * (after.twist.linear.y - before[i].velocity().y), linear[i].y, tol) << "body " << i;
    EXPECT_NEAR(before[i].inertia() * (after.twist.angular.z - before[i].omega()), angular[i], tol) << "body " << i;
  }
}

/// The service answers exactly what the core library computes.
void expect_equals_core(const ResolveContacts& srv)
{
  const SolverSettings& s = srv.request.settings;
  std::vector<Body> core = ros_interface::bodies_from_msgs(srv.request.bodies, srv.request.bodies.size());
  ContactSolver solver(s.restitution, s.friction, s.iterations, s.tolerance, s.bias_factor, s.slop);
  solver.set_mode(s.mode == SolverSettings::EXACT ? SolverMode::Exact : SolverMode::Iterative);
  const SolveReport report = s.use_time_of_impact ? solver.step(core) : solver.resolve(core);
  ASSERT_EQ(srv.response.bodies.size(), core.size());
  for (std::size_t i = 0; i < core.size(); ++i)
  {
    const BodyMsg& got = srv.response.bodies[i];
    EXPECT_EQ(got.id, srv.request.bodies[i].id);
    EXPECT_EQ(got.pose.x, core[i].position().x) << "body " << i;
    EXPECT_EQ(got.pose.y, core[i].position().y) << "body " << i;
    EXPECT_EQ(got.twist.linear.x, core[i].velocity().x) << "body " << i;
    EXPECT_EQ(got.twist.linear.y, core[i].velocity().y) << "body " << i;
    EXPECT_EQ(got.twist.angular.z, core[i].omega()) << "body " << i;
  }
  EXPECT_EQ(srv.response.report.iterations, report.iterations);
  EXPECT_EQ(srv.response.report.converged, report.converged);
  EXPECT_EQ(srv.response.report.total_normal_impulse, report.total_normal_impulse);
  if (s.use_time_of_impact)
  {
    EXPECT_EQ(srv.response.time_of_impact, report.time_of_impact);
  }
}

ResolveContacts::Request random_request(scenes::RandomSceneGenerator& generator, std::uint8_t mode)
{
  const scenes::RandomScene scene = generator.next();
  ResolveContacts::Request request;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    request.bodies.push_back(body_to_msg(scene.bodies[i], kIdBase + 3 * static_cast<std::uint32_t>(i)));
  }
  request.settings = solver_settings(scene.restitution, scene.friction);
  request.settings.mode = mode;
  return request;
}

void check_random_scenes(std::uint8_t mode, int count)
{
  scenes::RandomSceneGenerator generator(kSeed + mode);
  int energy_checked = 0;
  for (int k = 0; k < count; ++k)
  {
    SCOPED_TRACE("scene " + std::to_string(k));
    const ResolveContacts srv = call(random_request(generator, mode));
    ASSERT_TRUE(srv.response.success) << srv.response.message;
    EXPECT_FALSE(srv.response.contacts.empty()) << "random scenes are built overlapping";
    EXPECT_TRUE(srv.response.report.converged);
    expect_conservation(srv);
    expect_impulses_explain_velocities(srv);
    if (expect_contact_laws(srv))
    {
      ++energy_checked;
      EXPECT_LE(srv.response.report.kinetic_energy_after,
                srv.response.report.kinetic_energy_before * (1.0 + kRelativeTolerance) + 1e-12);
    }
    expect_equals_core(srv);
  }
  // Most scenes qualify; if none did, the energy law went untested.
  EXPECT_GT(energy_checked, 0);
}

TEST(ResolveContacts, RandomScenesIterative) { check_random_scenes(SolverSettings::ITERATIVE, kRandomScenes); }

TEST(ResolveContacts, RandomScenesExact) { check_random_scenes(SolverSettings::EXACT, kRandomScenes / 4); }

TEST(ResolveContacts, ThreeDisksInARowReachTheSpecFixedPoint)
{
  // The contract's case: equal disks along x, velocities (1, 0, 0.1), e = 1: the
  // fixed point is (-0.3, 0.7, 0.7) and kinetic energy rises 0.505 -> 0.535,
  // because the resting middle contact is pushed into action.
  constexpr double kOverlap = 1e-4;  // m: exact touching is not a contact
  ResolveContacts::Request request;
  request.bodies = {disk_msg(1, {0.0, 0.0}, {1.0, 0.0}), disk_msg(2, {1.0 - kOverlap, 0.0}),
                    disk_msg(3, {2.0 - 2 * kOverlap, 0.0}, {0.1, 0.0})};
  request.settings = solver_settings(1.0, 0.0);
  const ResolveContacts srv = call(request);
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_NEAR(srv.response.bodies[0].twist.linear.x, -0.3, 1e-9);
  EXPECT_NEAR(srv.response.bodies[1].twist.linear.x, 0.7, 1e-9);
  EXPECT_NEAR(srv.response.bodies[2].twist.linear.x, 0.7, 1e-9);
  EXPECT_NEAR(srv.response.report.kinetic_energy_before, 0.505, 1e-12);
  EXPECT_NEAR(srv.response.report.kinetic_energy_after, 0.535, 1e-9);
  expect_conservation(srv);
}

TEST(ResolveContacts, SweepFindsTheImpactOfAFastDisk)
{
  // A 5 cm disk at 500 m/s toward a thin static wall 2 m away: without the
  // sweep it would pass through in one unit step.
  ResolveContacts::Request request;
  BodyMsg wall = ros_test::box_msg(7, 0.05, 4.0, {2.0, 0.0});
  wall.type = BodyMsg::STATIC;
  request.bodies = {disk_msg(4, {0.0, 0.0}, {500.0, 0.0}, 0.05), wall};
  request.settings = solver_settings(1.0, 0.0);
  request.settings.use_time_of_impact = true;
  const ResolveContacts srv = call(request);
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  // First touch when the disk has covered 2 - 0.025 - 0.05 m of its 500.
  EXPECT_NEAR(srv.response.time_of_impact, (2.0 - 0.025 - 0.05) / 500.0, 1e-9);
  ASSERT_EQ(srv.response.contacts.size(), 1u);
  EXPECT_NEAR(srv.response.bodies[0].twist.linear.x, -500.0, 1e-6);  // e = 1 off a static wall
  expect_equals_core(srv);
}

TEST(ResolveContacts, NodeSettingsStandInWhenAsked)
{
  ResolveContacts::Request request;
  request.bodies = {disk_msg(1, {0.0, 0.0}, {1.0, 0.0}), disk_msg(2, {0.99, 0.0}, {-1.0, 0.0})};
  request.settings.use_node_settings = true;  // every other field left invalid (0 iterations)
  const ResolveContacts srv = call(request);
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  ASSERT_EQ(srv.response.contacts.size(), 1u);
  // The test launch file sets solver_restitution 0.5: separation 0.5 * 2 m/s.
  EXPECT_NEAR(srv.response.bodies[1].twist.linear.x - srv.response.bodies[0].twist.linear.x, 1.0, 1e-9);
}

TEST(ResolveContacts, BadRequestsNameTheBodyAndField)
{
  ResolveContacts::Request request;
  request.bodies = {disk_msg(5, {0.0, 0.0}), disk_msg(6, {3.0, 0.0}, {}, 0.5, -1.0)};
  request.settings = solver_settings(0.5, 0.2);
  ResolveContacts srv = call(request);
  EXPECT_FALSE(srv.response.success);
  EXPECT_TRUE(contains(srv.response.message, "bodies[1] (id 6): mass = -1 must be > 0"));
  EXPECT_TRUE(srv.response.bodies.empty());

  request.bodies[1].mass = 1.0;
  request.settings.bias_factor = 2.0;
  srv = call(request);
  EXPECT_FALSE(srv.response.success);
  EXPECT_TRUE(contains(srv.response.message, "settings: bias_factor = 2 must be in [0, 1]"));

  // The test launch file limits requests to 64 bodies.
  request.settings = solver_settings(0.5, 0.2);
  request.bodies.clear();
  for (std::uint32_t i = 0; i < 65; ++i)
  {
    request.bodies.push_back(disk_msg(i, {2.0 * i, 0.0}));
  }
  srv = call(request);
  EXPECT_FALSE(srv.response.success);
  EXPECT_TRUE(contains(srv.response.message, "65 given, more than the limit of 64"));
}

TEST(ResolveContacts, ConcurrentCallsGetTheirOwnAnswers)
{
  constexpr int kParallelCalls = 8;
  scenes::RandomSceneGenerator generator(kSeed + 99);
  std::vector<ResolveContacts::Request> requests;
  for (int k = 0; k < kParallelCalls; ++k)
  {
    requests.push_back(random_request(generator, SolverSettings::ITERATIVE));
  }
  std::vector<std::future<ResolveContacts>> answers;
  for (const auto& request : requests)
  {
    answers.push_back(std::async(std::launch::async, [&request] { return call(request); }));
  }
  for (int k = 0; k < kParallelCalls; ++k)
  {
    const ResolveContacts parallel = answers[k].get();
    ASSERT_TRUE(parallel.response.success) << parallel.response.message;
    // Stateless: the same request alone gives the same answer.
    EXPECT_TRUE(parallel.response == call(requests[k]).response) << "call " << k;
  }
}

}  // namespace
}  // namespace collision2d

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_resolve_contacts");
  ros::NodeHandle handle;
  if (!ros::service::waitForService("resolve_contacts", ros::Duration(collision2d::kServiceWait)))
  {
    ADD_FAILURE() << "resolve_contacts never came up";
  }
  return RUN_ALL_TESTS();
}
