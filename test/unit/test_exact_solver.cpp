// Exact (pivoting) contact solve: closed-form cases, resting and stacked
// boxes with redundant contacts, extreme mass ratios, Coulomb friction and
// random clusters, each checked by recomputing the solver's contract
// from the bodies and impulses the solver returns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/exact_solver.h"
#include "collision2d/scenes/random_scenes.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
using test::make_contact;
using test::normal_speed;
using test::tangent_speed;

constexpr double kTol = 1e-12;            // solver tolerance passed in
constexpr double kContractTol = 1e-12;    // relative to the velocity scale
constexpr double kStepSpeed = 9.81 / 60;  // m/s gained under gravity in one 60 Hz frame

Body disk(double mass, double radius, Vec2 position, Vec2 velocity) { return Body(mass, radius, position, velocity); }

Body box(double mass, double half_w, double half_h, Vec2 position, Vec2 velocity)
{
  return Body(mass, {{-half_w, -half_h}, {half_w, -half_h}, {half_w, half_h}, {-half_w, half_h}}, position,
              velocity);
}

Body static_box(double half_w, double half_h, Vec2 position)
{
  Body b = box(1.0, half_w, half_h, position, {0.0, 0.0});
  b.set_type(BodyType::Static);
  return b;
}

/// Inverse effective mass of a contact along `dir`, from the bodies alone.
double inverse_effective_mass(const std::vector<Body>& bodies, const Contact& c, Vec2 dir)
{
  const Body& a = bodies[c.a];
  const Body& b = bodies[c.b];
  const double ra = cross(c.point - a.position(), dir);
  const double rb = cross(c.point - b.position(), dir);
  return a.inv_mass() + b.inv_mass() + a.inv_inertia() * ra * ra + b.inv_inertia() * rb * rb;
}

/// The speeds the problem involves: contact speeds before and after and the
/// speed change each impulse makes on its own contact.
double velocity_scale(const std::vector<Body>& before, const std::vector<Body>& after,
                      const std::vector<Contact>& contacts, const std::vector<ContactImpulse>& impulses)
{
  double scale = 0.0;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const Contact& c = contacts[i];
    const double k = inverse_effective_mass(before, c, c.normal);
    scale = std::max({scale, std::abs(normal_speed(before, c)), std::abs(tangent_speed(before, c)),
                      std::abs(normal_speed(after, c)), std::abs(tangent_speed(after, c)),
                      k * std::abs(impulses[i].normal), k * std::abs(impulses[i].tangent)});
  }
  return scale;
}

/// Every dynamic body's new velocity is its old one plus the impulses listed
/// for its contacts, applied at the contact points, equal and opposite.
void expect_impulses_explain_velocities(const std::vector<Body>& before, const std::vector<Body>& after,
                                        const std::vector<Contact>& contacts,
                                        const std::vector<ContactImpulse>& impulses, double tol)
{
  std::vector<Vec2> dv(before.size());
  std::vector<double> dw(before.size(), 0.0);
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const Contact& c = contacts[i];
    const Vec2 p = impulses[i].normal * c.normal + impulses[i].tangent * perp(c.normal);
    dv[c.a] -= before[c.a].inv_mass() * p;
    dw[c.a] -= before[c.a].inv_inertia() * cross(c.point - before[c.a].position(), p);
    dv[c.b] += before[c.b].inv_mass() * p;
    dw[c.b] += before[c.b].inv_inertia() * cross(c.point - before[c.b].position(), p);
  }
  for (std::size_t i = 0; i < before.size(); ++i)
  {
    const Vec2 expected = before[i].velocity() + dv[i];
    EXPECT_NEAR(after[i].velocity().x, expected.x, tol) << "body " << i;
    EXPECT_NEAR(after[i].velocity().y, expected.y, tol) << "body " << i;
    EXPECT_NEAR(after[i].omega() * after[i].radius(), (before[i].omega() + dw[i]) * before[i].radius(), tol)
        << "body " << i;
  }
}

/// The solver's contract at exit, per contact, in speeds (m/s): Newton target
/// reached, push only, complementarity, Coulomb cone, stick inside it, slide
/// against the impulse on it. Returns the velocity scale used.
double expect_contract(const std::vector<Body>& before, const std::vector<Body>& after,
                       const std::vector<Contact>& contacts, const std::vector<ContactImpulse>& impulses, double e,
                       double mu, double relative_tol)
{
  EXPECT_EQ(impulses.size(), contacts.size());
  const double scale = velocity_scale(before, after, contacts, impulses);
  const double tol = relative_tol * scale;
  expect_impulses_explain_velocities(before, after, contacts, impulses, tol);
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const Contact& c = contacts[i];
    const double k = inverse_effective_mass(before, c, c.normal);
    const double target = test::newton_target(before, c, e);
    const double gap = normal_speed(after, c) - target;
    const double lambda_n = impulses[i].normal;
    const double lambda_t = impulses[i].tangent;
    EXPECT_GE(lambda_n, 0.0) << "contact " << i << " pulls";
    EXPECT_GE(gap, -tol) << "contact " << i << " misses its target";
    EXPECT_LE(std::min(gap, k * lambda_n), tol) << "contact " << i << " pushes while separating";
    if (mu == 0.0)
    {
      EXPECT_EQ(lambda_t, 0.0) << "contact " << i;
      continue;
    }
    const double vt = tangent_speed(after, c);
    const double slack = k * (mu * lambda_n - std::abs(lambda_t));
    EXPECT_GE(slack, -tol) << "contact " << i << " outside the Coulomb cone";
    EXPECT_LE(std::min(std::abs(vt), slack), tol) << "contact " << i << " slides inside the cone";
    if (lambda_t * vt > 0.0)
    {
      EXPECT_LE(std::min(std::abs(vt), k * std::abs(lambda_t)), tol) << "contact " << i << " friction pushes";
    }
  }
  return scale;
}

struct Outcome
{
  std::vector<Body> bodies;
  std::vector<ContactImpulse> impulses;
  SolveReport report;
};

Outcome solve(const std::vector<Body>& bodies, const std::vector<Contact>& contacts, double e, double mu)
{
  Outcome out{bodies, {}, {}};
  out.report = solve_exact(out.bodies, contacts, e, mu, kTol, &out.impulses);
  return out;
}

/// Disks a < b touching along the line of centres.
Contact disk_contact(const std::vector<Body>& bodies, std::size_t a, std::size_t b)
{
  const Vec2 d = bodies[b].position() - bodies[a].position();
  const Vec2 n = d / length(d);
  return make_contact(a, b, n, bodies[a].position() + bodies[a].radius() * n, 0.0);
}

TEST(ExactSolver, SpecThreeDisksReachTheFixedPoint)
{
  const std::vector<Body> bodies = {disk(1.0, 1.0, {0, 0}, {1.0, 0}), disk(1.0, 1.0, {2, 0}, {0.0, 0}),
                                    disk(1.0, 1.0, {4, 0}, {0.1, 0})};
  const std::vector<Contact> contacts = {disk_contact(bodies, 0, 1), disk_contact(bodies, 1, 2)};
  const Outcome out = solve(bodies, contacts, 1.0, 0.0);
  // Hand solution: 2 l1 - l2 = 2, 2 l2 - l1 = -0.1 -> l1 = 1.3, l2 = 0.6.
  EXPECT_NEAR(out.bodies[0].velocity().x, -0.3, 1e-15);
  EXPECT_NEAR(out.bodies[1].velocity().x, 0.7, 1e-15);
  EXPECT_NEAR(out.bodies[2].velocity().x, 0.7, 1e-15);
  EXPECT_NEAR(out.report.kinetic_energy_before, 0.505, 1e-15);
  EXPECT_NEAR(out.report.kinetic_energy_after, 0.535, 1e-15);
  EXPECT_NEAR(out.report.kinetic_energy_after, test::total_kinetic_energy(out.bodies), 1e-15);
  EXPECT_NEAR(out.report.total_normal_impulse, 1.9, 1e-14);
  EXPECT_TRUE(out.report.converged);
  EXPECT_FALSE(out.report.exact_fallback);
  EXPECT_EQ(out.report.cluster_count, 1u);
  EXPECT_EQ(out.report.contact_count, 2u);
  EXPECT_GE(out.report.iterations, 1);
  EXPECT_LE(out.report.max_residual, 1e-15);
  expect_contract(bodies, out.bodies, contacts, out.impulses, 1.0, 0.0, kContractTol);
}

TEST(ExactSolver, OneDimensionalImpactsMatchClosedFormOverMassRatios)
{
  for (int exponent = -6; exponent <= 6; ++exponent)
    for (double e : {0.0, 0.3, 1.0})
    {
      const double m1 = 1.0;
      const double m2 = std::pow(10.0, exponent);
      const double v1 = 1.0;
      const double v2 = -0.5;
      const std::vector<Body> bodies = {disk(m1, 0.5, {0, 0}, {v1, 0}), disk(m2, 0.5, {1, 0}, {v2, 0})};
      const std::vector<Contact> contacts = {disk_contact(bodies, 0, 1)};
      const Outcome out = solve(bodies, contacts, e, 0.0);
      const double p = m1 * v1 + m2 * v2;
      const double u1 = (p + m2 * e * (v2 - v1)) / (m1 + m2);
      const double u2 = (p + m1 * e * (v1 - v2)) / (m1 + m2);
      const double scale = std::abs(v1 - v2);
      EXPECT_NEAR(out.bodies[0].velocity().x, u1, 1e-9 * scale) << "m2 = " << m2 << " e = " << e;
      EXPECT_NEAR(out.bodies[1].velocity().x, u2, 1e-9 * scale) << "m2 = " << m2 << " e = " << e;
      EXPECT_TRUE(out.report.converged);
      expect_contract(bodies, out.bodies, contacts, out.impulses, e, 0.0, kContractTol);
    }
}

TEST(ExactSolver, ElasticOffCentreImpactSpinsTheBoxAndConservesEverything)
{
  // Disk hits the box's left face 0.3 m below its centroid: the box starts to
  // spin, momenta are conserved and, with e = 1, so is energy.
  const std::vector<Body> bodies = {disk(2.0, 0.5, {-1.5, -0.3}, {3.0, 0.0}), box(5.0, 1.0, 0.5, {0, 0}, {0, 0})};
  const std::vector<Contact> contacts = {make_contact(0, 1, {1.0, 0.0}, {-1.0, -0.3}, 0.0)};
  const Outcome out = solve(bodies, contacts, 1.0, 0.0);
  EXPECT_GT(out.bodies[1].omega(), 0.0);  // push along +x below the centroid turns counter-clockwise
  const Vec2 p0 = test::total_momentum(bodies);
  const Vec2 p1 = test::total_momentum(out.bodies);
  EXPECT_NEAR(p1.x, p0.x, 1e-14);
  EXPECT_NEAR(p1.y, p0.y, 1e-14);
  EXPECT_NEAR(test::total_angular_momentum(out.bodies), test::total_angular_momentum(bodies), 1e-13);
  EXPECT_NEAR(out.report.kinetic_energy_after, out.report.kinetic_energy_before, 1e-13);
  expect_contract(bodies, out.bodies, contacts, out.impulses, 1.0, 0.0, kContractTol);
}

TEST(ExactSolver, BounceOffAStaticWall)
{
  std::vector<Body> bodies = {static_box(0.5, 5.0, {0, 0}), disk(3.0, 0.5, {1.0, 0.2}, {-2.0, 0.7})};
  const std::vector<Contact> contacts = {make_contact(0, 1, {1.0, 0.0}, {0.5, 0.2}, 0.0)};
  const Outcome out = solve(bodies, contacts, 0.6, 0.0);
  EXPECT_NEAR(out.bodies[1].velocity().x, 1.2, 1e-15);
  EXPECT_NEAR(out.bodies[1].velocity().y, 0.7, 1e-15);
  EXPECT_EQ(out.bodies[0].velocity(), Vec2{});  // static: untouched
  expect_contract(bodies, out.bodies, contacts, out.impulses, 0.6, 0.0, kContractTol);
}

/// Ground (static, body 0) and a box of half size h resting on it with its two
/// bottom corners as contacts.
struct Resting
{
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

Resting box_on_ground(double mass, Vec2 velocity)
{
  Resting r;
  r.bodies = {static_box(10.0, 0.5, {0, -0.5}), box(mass, 0.5, 0.5, {0, 0.5}, velocity)};
  r.contacts = {make_contact(0, 1, {0, 1}, {-0.5, 0}, 0.0), make_contact(0, 1, {0, 1}, {0.5, 0}, 0.0)};
  return r;
}

TEST(ExactSolver, BoxLandingFlatStopsWithBothCorners)
{
  const Resting r = box_on_ground(2.0, {0.0, -kStepSpeed});
  const Outcome out = solve(r.bodies, r.contacts, 0.0, 0.0);
  EXPECT_NEAR(out.bodies[1].velocity().y, 0.0, 1e-15);
  EXPECT_NEAR(out.bodies[1].omega(), 0.0, 1e-15);
  EXPECT_NEAR(out.impulses[0].normal + out.impulses[1].normal, 2.0 * kStepSpeed, 1e-15);
  EXPECT_NEAR(out.impulses[0].normal, out.impulses[1].normal, 1e-15);  // no turning: equal moments
  EXPECT_TRUE(out.report.converged);
  expect_contract(r.bodies, out.bodies, r.contacts, out.impulses, 0.0, 0.0, kContractTol);
}

TEST(ExactSolver, PlankOnThreeSupportsHasASingularDelassusMatrix)
{
  // Three normal rows, two free directions (vy, w): rank 2. Any impulse split
  // with the right sum and moment solves it.
  std::vector<Body> bodies = {static_box(10.0, 0.5, {0, -0.5}), box(4.0, 2.0, 0.1, {0, 0.1}, {0, -1.0})};
  bodies[1].set_omega(0.2);
  std::vector<Contact> contacts;
  for (double x : {-2.0, 0.0, 2.0})
    contacts.push_back(make_contact(0, 1, {0, 1}, {x, 0}, 0.0));
  const Outcome out = solve(bodies, contacts, 0.0, 0.0);
  EXPECT_TRUE(out.report.converged);
  EXPECT_NEAR(out.bodies[1].velocity().y, 0.0, 1e-14);
  EXPECT_NEAR(out.bodies[1].omega(), 0.0, 1e-14);
  double sum = 0.0;
  double moment = 0.0;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    sum += out.impulses[i].normal;
    moment += contacts[i].point.x * out.impulses[i].normal;
  }
  EXPECT_NEAR(sum, 4.0 * 1.0, 1e-13);
  EXPECT_NEAR(moment, -bodies[1].inertia() * 0.2, 1e-13);
  expect_contract(bodies, out.bodies, contacts, out.impulses, 0.0, 0.0, kContractTol);
}

TEST(ExactSolver, SlidingBoxLosesMuTimesItsNormalImpulse)
{
  // Friction makes the two tangent rows identical (singular Delassus). The box
  // cannot stop in one step, so it slides on the cone; the friction torque
  // shifts the normal impulses forward but (mu <= 1) both corners stay loaded.
  const double mu = 0.5;
  const Resting r = box_on_ground(1.5, {1.0, -kStepSpeed});
  const Outcome out = solve(r.bodies, r.contacts, 0.0, mu);
  EXPECT_TRUE(out.report.converged);
  EXPECT_NEAR(out.bodies[1].velocity().x, 1.0 - mu * kStepSpeed, 1e-14);
  EXPECT_NEAR(out.bodies[1].velocity().y, 0.0, 1e-14);
  EXPECT_NEAR(out.bodies[1].omega(), 0.0, 1e-14);
  EXPECT_GT(out.impulses[1].normal, out.impulses[0].normal);  // leading corner carries more
  for (const ContactImpulse& impulse : out.impulses)
    EXPECT_NEAR(impulse.tangent, mu * impulse.normal, 1e-15);  // perp(up) = -x: against the motion
  expect_contract(r.bodies, out.bodies, r.contacts, out.impulses, 0.0, mu, kContractTol);
}

TEST(ExactSolver, SlowBoxSticksInsideTheCone)
{
  const double mu = 0.5;
  const Resting r = box_on_ground(1.5, {0.01, -kStepSpeed});
  const Outcome out = solve(r.bodies, r.contacts, 0.0, mu);
  EXPECT_TRUE(out.report.converged);
  EXPECT_NEAR(out.bodies[1].velocity().x, 0.0, 1e-15);
  EXPECT_NEAR(out.bodies[1].velocity().y, 0.0, 1e-15);
  EXPECT_NEAR(out.bodies[1].omega(), 0.0, 1e-15);
  const double friction = out.impulses[0].tangent + out.impulses[1].tangent;
  EXPECT_NEAR(friction, 1.5 * 0.01, 1e-15);  // along perp(up) = -x
  EXPECT_LT(std::abs(friction), mu * (out.impulses[0].normal + out.impulses[1].normal));
  expect_contract(r.bodies, out.bodies, r.contacts, out.impulses, 0.0, mu, kContractTol);
}

/// Boxes of the given masses stacked on a static ground, each moving down at
/// the speed one frame of gravity gives (the boxes rest on each other, the
/// bottom one approaches the ground).
Resting stack(const std::vector<double>& masses)
{
  Resting r;
  r.bodies.push_back(static_box(10.0, 0.5, {0, -0.5}));
  for (std::size_t i = 0; i < masses.size(); ++i)
  {
    const double y = static_cast<double>(i);
    r.bodies.push_back(box(masses[i], 0.5, 0.5, {0, y + 0.5}, {0, -kStepSpeed}));
    r.contacts.push_back(make_contact(i, i + 1, {0, 1}, {-0.5, y}, 0.0));
    r.contacts.push_back(make_contact(i, i + 1, {0, 1}, {0.5, y}, 0.0));
  }
  return r;
}

void expect_stack_holds(const std::vector<double>& masses, double e, double mu)
{
  SCOPED_TRACE(::testing::Message() << masses.size() << " boxes, top mass " << masses.back() << ", e " << e
                                    << ", mu " << mu);
  const Resting r = stack(masses);
  const Outcome out = solve(r.bodies, r.contacts, e, mu);
  ASSERT_FALSE(out.report.exact_fallback);
  EXPECT_TRUE(out.report.converged);
  // Newton targets to 1e-9 of the approach speed, never pulling.
  for (std::size_t i = 0; i < r.contacts.size(); ++i)
  {
    EXPECT_GE(out.impulses[i].normal, 0.0);
    EXPECT_GE(normal_speed(out.bodies, r.contacts[i]), test::newton_target(r.bodies, r.contacts[i], e) -
                                                           1e-9 * kStepSpeed)
        << "contact " << i;
  }
  // Each interface carries the momentum of everything above it (e = 0: the
  // whole stack stops).
  if (e == 0.0)
  {
    double above = 0.0;
    for (std::size_t level = masses.size(); level-- > 0;)
    {
      above += masses[level] * kStepSpeed;
      const double carried = out.impulses[2 * level].normal + out.impulses[2 * level + 1].normal;
      EXPECT_NEAR(carried, above, 1e-9 * above) << "level " << level;
      EXPECT_NEAR(out.bodies[level + 1].velocity().y, 0.0, 1e-9 * kStepSpeed) << "level " << level;
    }
  }
  expect_contract(r.bodies, out.bodies, r.contacts, out.impulses, e, mu, 1e-9);
}

TEST(ExactSolver, HeavyOnLightStackHoldsAtMassRatioMillion)
{
  expect_stack_holds({1.0, 1e6}, 0.0, 0.0);
  expect_stack_holds({1.0, 1e6, 1.0, 1e6}, 0.0, 0.0);
  expect_stack_holds({1.0, 1e3, 1e6}, 0.0, 0.5);
  expect_stack_holds({1.0, 1e6, 1.0, 1e6}, 0.5, 0.5);
}

TEST(ExactSolver, InfeasiblePinchFallsBackWithoutTouchingBodies)
{
  // A disk moving right between two touching static walls with e = 1: the
  // right contact needs vx <= -2, the left one vx >= 0. No impulses exist.
  std::vector<Body> bodies = {static_box(0.5, 2.0, {-1.0, 0}), disk(1.0, 0.5, {0, 0}, {2.0, 0.5}),
                              static_box(0.5, 2.0, {1.0, 0})};
  const std::vector<Contact> contacts = {make_contact(0, 1, {1, 0}, {-0.5, 0}, 0.0),
                                         make_contact(1, 2, {1, 0}, {0.5, 0}, 0.0)};
  std::vector<Body> solved = bodies;
  std::vector<ContactImpulse> impulses(5, ContactImpulse{1.0, 1.0});
  const SolveReport report = solve_exact(solved, contacts, 1.0, 0.0, kTol, &impulses);
  EXPECT_TRUE(report.exact_fallback);
  EXPECT_FALSE(report.converged);
  ASSERT_EQ(impulses.size(), contacts.size());
  for (const ContactImpulse& impulse : impulses)
  {
    EXPECT_EQ(impulse.normal, 0.0);
    EXPECT_EQ(impulse.tangent, 0.0);
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    EXPECT_EQ(solved[i].velocity(), bodies[i].velocity());
    EXPECT_EQ(solved[i].omega(), bodies[i].omega());
  }
  EXPECT_EQ(report.kinetic_energy_after, report.kinetic_energy_before);
}

TEST(ExactSolver, OversizedClusterFallsBackAndSmallerOnesSolve)
{
  // A touching row of disks: one cluster of n - 1 contacts, 4 unknowns each
  // with friction. Above kMaxExactUnknowns the call reports failure at once.
  const std::size_t n = kMaxExactUnknowns / 4 + 2;
  std::vector<Body> bodies;
  for (std::size_t i = 0; i < n; ++i)
    bodies.push_back(disk(1.0, 0.5, {static_cast<double>(i), 0.0}, {i == 0 ? 1.0 : 0.0, 0.1}));
  std::vector<Contact> contacts;
  for (std::size_t i = 0; i + 1 < n; ++i)
    contacts.push_back(disk_contact(bodies, i, i + 1));
  const Outcome rough = solve(bodies, contacts, 1.0, 0.3);
  EXPECT_TRUE(rough.report.exact_fallback);
  EXPECT_FALSE(rough.report.converged);
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_EQ(rough.bodies[i].velocity(), bodies[i].velocity());
  // Without friction the same row is n - 1 unknowns: solved. Newton's cradle:
  // e = 1 passes the speed to the last disk.
  const Outcome smooth = solve(bodies, contacts, 1.0, 0.0);
  ASSERT_FALSE(smooth.report.exact_fallback);
  EXPECT_TRUE(smooth.report.converged);
  expect_contract(bodies, smooth.bodies, contacts, smooth.impulses, 1.0, 0.0, kContractTol);
}

TEST(ExactSolver, StaticBodiesDoNotCoupleClustersAndKinematicOnesKeepTheirVelocity)
{
  // Two disks on one static floor (two clusters), a kinematic paddle hitting
  // a third disk (one cluster), and a contact between floor and paddle (no
  // dynamic body: no impulse).
  std::vector<Body> bodies = {static_box(10.0, 0.5, {0, -0.5}), disk(1.0, 0.5, {-3, 0.5}, {0, -1}),
                              disk(2.0, 0.5, {3, 0.5}, {0, -2}), box(1.0, 0.5, 0.5, {6, 0.5}, {-1, 0}),
                              disk(1.0, 0.5, {5, 0.5}, {0, 0})};
  bodies[3].set_type(BodyType::Kinematic);
  const std::vector<Contact> contacts = {
      make_contact(0, 1, {0, 1}, {-3, 0}, 0.0), make_contact(0, 2, {0, 1}, {3, 0}, 0.0),
      make_contact(0, 3, {0, 1}, {6, 0}, 0.0), make_contact(3, 4, {-1, 0}, {5.5, 0.5}, 0.0)};
  const Outcome out = solve(bodies, contacts, 0.5, 0.0);
  EXPECT_EQ(out.report.cluster_count, 3u);
  EXPECT_EQ(out.impulses[2].normal, 0.0);
  EXPECT_EQ(out.bodies[3].velocity(), bodies[3].velocity());
  EXPECT_NEAR(out.bodies[1].velocity().y, 0.5, 1e-15);
  EXPECT_NEAR(out.bodies[2].velocity().y, 1.0, 1e-15);
  EXPECT_NEAR(out.bodies[4].velocity().x, -1.5, 1e-15);  // paddle at -1, e = 0.5: separate at 0.5 more
  expect_contract(bodies, out.bodies, contacts, out.impulses, 0.5, 0.0, kContractTol);
}

/// Frictionless theory: if no contact that was separating or resting before
/// the solve carries impulse, kinetic energy cannot rise.
bool only_approaching_contacts_push(const std::vector<Body>& before, const std::vector<Contact>& contacts,
                                    const std::vector<ContactImpulse>& impulses)
{
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (impulses[i].normal > 0.0 && normal_speed(before, contacts[i]) >= 0.0)
      return false;
  return true;
}

TEST(ExactSolver, RandomClustersHonourTheContract)
{
  scenes::RandomSceneOptions options;
  options.max_bodies = 12;
  options.max_mass_ratio = 1e4;
  options.static_probability = 0.3;
  scenes::RandomSceneGenerator generator(2024, options);
  int solved = 0;
  int fallbacks = 0;
  int energy_checked = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const scenes::RandomScene scene = generator.next();
    const std::vector<Contact> contacts = ContactSolver::detect_contacts(scene.bodies);
    const double mu = trial % 2 == 0 ? 0.0 : scene.friction;
    const Outcome out = solve(scene.bodies, contacts, scene.restitution, mu);
    if (out.report.exact_fallback)
    {
      ++fallbacks;
      continue;
    }
    ++solved;
    EXPECT_TRUE(out.report.converged) << "trial " << trial << " residual " << out.report.max_residual;
    expect_contract(scene.bodies, out.bodies, contacts, out.impulses, scene.restitution, mu, kContractTol);
    if (mu == 0.0 && only_approaching_contacts_push(scene.bodies, contacts, out.impulses))
    {
      ++energy_checked;
      EXPECT_LE(out.report.kinetic_energy_after, out.report.kinetic_energy_before * (1.0 + 1e-12))
          << "trial " << trial;
    }
    if (::testing::Test::HasFailure())
      FAIL() << "first failing trial " << trial;
  }
  EXPECT_GE(solved, 290);
  EXPECT_GT(energy_checked, 20);
  RecordProperty("fallbacks", fallbacks);
}

}  // namespace
}  // namespace collision2d
