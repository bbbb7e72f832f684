// The velocity solve against textbook closed forms: 1D impacts, off-centre
// hits, frictionless spin, Coulomb sliding and sticking, and the contract's three-disk
// fixed point where a resting contact is pushed into action.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "collision2d/contact_solver.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
using test::make_contact;

constexpr double kTight = 1e-12;   // agreement with a closed form (m/s, rad/s, N s): round-off only
constexpr double kRadius = 0.5;    // m
constexpr double kOverlap = 1e-3;  // m

/// Two disks on the x axis, 0 moving at u1 toward 1 moving at u2; one contact.
struct HeadOn
{
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

HeadOn head_on(double m1, double m2, double u1, double u2)
{
  HeadOn s;
  const double gap = 2.0 * kRadius - kOverlap;
  s.bodies.emplace_back(m1, kRadius, Vec2{0.0, 0.0}, Vec2{u1, 0.0});
  s.bodies.emplace_back(m2, kRadius, Vec2{gap, 0.0}, Vec2{u2, 0.0});
  s.contacts.push_back(make_contact(0, 1, Vec2{1.0, 0.0}, Vec2{0.5 * gap, 0.0}, kOverlap));
  return s;
}

TEST(SolverClosedForm, HeadOnImpactsMatchTextbookForSeveralRestitutionsAndMassRatios)
{
  const double u1 = 1.5;
  const double u2 = -0.5;
  for (double e : {0.0, 0.3, 0.7, 1.0})
  {
    for (double ratio : {1.0, 3.0, 100.0, 0.01})
    {
      const double m1 = 2.0;
      const double m2 = m1 * ratio;
      HeadOn s = head_on(m1, m2, u1, u2);
      const ContactSolver solver(e, 0.4);
      const SolveReport report = solver.solve(s.bodies, s.contacts);

      // Momentum plus Newton's law v2 - v1 = -e (u2 - u1).
      const double v1 = (m1 * u1 + m2 * u2 + m2 * e * (u2 - u1)) / (m1 + m2);
      const double v2 = (m1 * u1 + m2 * u2 + m1 * e * (u1 - u2)) / (m1 + m2);
      SCOPED_TRACE(testing::Message() << "e=" << e << " m2/m1=" << ratio);
      EXPECT_NEAR(s.bodies[0].velocity().x, v1, kTight * 2.0);
      EXPECT_NEAR(s.bodies[1].velocity().x, v2, kTight * 2.0);
      EXPECT_EQ(s.bodies[0].velocity().y, 0.0);
      EXPECT_EQ(s.bodies[1].omega(), 0.0);
      EXPECT_TRUE(report.converged);
      const double reduced_mass = m1 * m2 / (m1 + m2);
      EXPECT_NEAR(report.total_normal_impulse, (1.0 + e) * reduced_mass * (u1 - u2), kTight * m2);
    }
  }
}

TEST(SolverClosedForm, ElasticEqualMassesExchangeVelocities)
{
  HeadOn s = head_on(1.0, 1.0, 2.0, 0.0);
  const double energy_before = test::total_kinetic_energy(s.bodies);
  ContactSolver(1.0, 0.0).solve(s.bodies, s.contacts);
  EXPECT_NEAR(s.bodies[0].velocity().x, 0.0, kTight);
  EXPECT_NEAR(s.bodies[1].velocity().x, 2.0, kTight);
  EXPECT_NEAR(test::total_kinetic_energy(s.bodies), energy_before, kTight);
}

TEST(SolverClosedForm, OffCentreHitSpinsABoxByImpulseMomentum)
{
  // A disk hits the left face of a resting 2 x 1 box at height y = 0.3.
  const double m = 1.0;
  const double box_mass = 4.0;
  const double width = 2.0;
  const double height = 1.0;
  const double u = 3.0;
  const double e = 0.5;
  const Vec2 point{-0.5 * width, 0.3};
  std::vector<Body> bodies;
  bodies.emplace_back(m, kRadius, point - Vec2{kRadius - kOverlap, 0.0}, Vec2{u, 0.0});
  const double hw = 0.5 * width;
  const double hh = 0.5 * height;
  bodies.emplace_back(box_mass, std::vector<Vec2>{{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}}, Vec2{}, Vec2{});
  const std::vector<Contact> contacts{make_contact(0, 1, Vec2{1.0, 0.0}, point, kOverlap)};
  ContactSolver(e, 0.0).solve(bodies, contacts);

  // Impulse-momentum: lambda = (1 + e) u / K with K = 1/m + 1/M + (r x n)^2 / I.
  const double inertia = box_mass * (width * width + height * height) / 12.0;
  const double arm = cross(point, Vec2{1.0, 0.0});  // r_b x n, box centred at the origin
  const double lambda = (1.0 + e) * u / (1.0 / m + 1.0 / box_mass + arm * arm / inertia);
  EXPECT_NEAR(bodies[1].omega(), lambda * arm / inertia, kTight);
  EXPECT_LT(bodies[1].omega(), 0.0);  // hit above the centre from the left: clockwise
  EXPECT_NEAR(bodies[1].velocity().x, lambda / box_mass, kTight);
  EXPECT_NEAR(bodies[0].velocity().x, u - lambda / m, kTight);
  EXPECT_NEAR(test::normal_speed(bodies, contacts[0]), e * u, kTight);
}

TEST(SolverClosedForm, FrictionlessContactKeepsASpinningDiskSpinning)
{
  const double spin = 7.0;
  HeadOn s = head_on(1.0, 2.0, 1.0, 0.0);
  s.bodies[0].set_omega(spin);
  s.bodies[0].set_velocity(Vec2{1.0, 0.4});  // oblique, so a frictional contact would slide
  ContactSolver(0.8, 0.0).solve(s.bodies, s.contacts);
  EXPECT_EQ(s.bodies[0].omega(), spin);
  EXPECT_EQ(s.bodies[1].omega(), 0.0);
  EXPECT_EQ(s.bodies[0].velocity().y, 0.4);  // no tangential impulse at all
}

/// A disk (body 1) striking a static ground (body 0) whose top is y = 0.
struct GroundHit
{
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
  double mass = 2.0;
};

GroundHit ground_hit(Vec2 velocity, double omega)
{
  GroundHit s;
  const double hw = 10.0;
  const double hh = 0.5;
  s.bodies.emplace_back(1.0, std::vector<Vec2>{{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}}, Vec2{0.0, -hh}, Vec2{});
  s.bodies[0].set_type(BodyType::Static);
  s.bodies.emplace_back(s.mass, kRadius, Vec2{0.0, kRadius - kOverlap}, velocity, omega);
  // At the disk's lowest point, so the lever arm is exactly R.
  s.contacts.push_back(make_contact(0, 1, Vec2{0.0, 1.0}, Vec2{0.0, -kOverlap}, kOverlap));
  return s;
}

TEST(SolverClosedForm, GlancingImpactSlidesAtTheConeBound)
{
  const double vx = 2.0;
  const double vy = -1.0;
  const double e = 0.5;
  const double mu = 0.1;
  GroundHit s = ground_hit(Vec2{vx, vy}, 0.0);
  std::vector<ContactImpulse> impulses;
  const SolveReport report = ContactSolver(e, mu).solve(s.bodies, s.contacts, &impulses);
  ASSERT_TRUE(report.converged);

  // Normal and tangential rows are decoupled (the lever arm is along n), so
  // lambda_n = (1 + e) m |vy|; sticking would need m vx / 3 (K_t = 3 / m for
  // a uniform disk), more than mu lambda_n, so the disk slides.
  const double lambda_n = (1.0 + e) * s.mass * -vy;
  ASSERT_GT(s.mass * vx / 3.0, mu * lambda_n);
  EXPECT_NEAR(impulses[0].normal, lambda_n, kTight);
  EXPECT_NEAR(std::abs(impulses[0].tangent), mu * impulses[0].normal, kTight);
  const Body& disk = s.bodies[1];
  EXPECT_NEAR(disk.velocity().y, -e * vy, kTight);
  EXPECT_NEAR(disk.velocity().x, vx - mu * lambda_n / s.mass, kTight);
  const double inertia = 0.5 * s.mass * kRadius * kRadius;
  // Friction along -x at the bottom point spins the disk clockwise (rolling forward).
  EXPECT_NEAR(disk.omega(), -mu * lambda_n * kRadius / inertia, kTight);
  // The bottom point still slides forward, against the friction impulse.
  const double slip = test::tangent_speed(s.bodies, s.contacts[0]);
  EXPECT_NEAR(disk.velocity().x + disk.omega() * kRadius, -slip, kTight);
  EXPECT_GT(disk.velocity().x + disk.omega() * kRadius, 0.0);
  EXPECT_LT(slip * impulses[0].tangent, 0.0);
}

TEST(SolverClosedForm, GentleImpactSticksInsideTheCone)
{
  const double vx = 0.3;
  const double vy = -1.0;
  const double mu = 0.5;
  GroundHit s = ground_hit(Vec2{vx, vy}, 0.0);
  std::vector<ContactImpulse> impulses;
  ASSERT_TRUE(ContactSolver(0.0, mu).solve(s.bodies, s.contacts, &impulses).converged);

  const double lambda_n = s.mass * -vy;
  const double lambda_stick = s.mass * vx / 3.0;  // m vx / 3 removes the slip
  ASSERT_LT(lambda_stick, mu * lambda_n);
  EXPECT_NEAR(impulses[0].normal, lambda_n, kTight);
  EXPECT_NEAR(std::abs(impulses[0].tangent), lambda_stick, kTight);
  EXPECT_LT(std::abs(impulses[0].tangent), mu * impulses[0].normal);
  const Body& disk = s.bodies[1];
  EXPECT_NEAR(disk.velocity().x, vx - lambda_stick / s.mass, kTight);  // = 2 vx / 3: rolling
  EXPECT_NEAR(disk.velocity().x + disk.omega() * kRadius, 0.0, kTight);
  EXPECT_NEAR(test::tangent_speed(s.bodies, s.contacts[0]), 0.0, kTight);
  EXPECT_NEAR(disk.velocity().y, 0.0, kTight);
}

TEST(SolverClosedForm, ThreeDisksInARowReachTheFixedPointAndGainEnergy)
{
  // Equal unit disks touching in a row, velocities (1, 0, 0.1), e = 1. The
  // left contact approaches at 1 (target 1); the right one separates at 0.1
  // (target 0) but is pushed into action by the middle disk.
  const double e = 1.0;
  const Eigen::Vector3d u(1.0, 0.0, 0.1);
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
  for (int i = 0; i < 3; ++i)
    bodies.emplace_back(1.0, kRadius, Vec2{2.0 * kRadius * i, 0.0}, Vec2{u[i], 0.0});
  contacts.push_back(make_contact(0, 1, Vec2{1.0, 0.0}, Vec2{kRadius, 0.0}, 0.0));
  contacts.push_back(make_contact(1, 2, Vec2{1.0, 0.0}, Vec2{3.0 * kRadius, 0.0}, 0.0));
  std::vector<ContactImpulse> impulses;
  const SolveReport report = ContactSolver(e, 0.0).solve(bodies, contacts, &impulses);

  // Fixed point with both contacts active: v2 - v1 = e (u1 - u2),
  // v3 - v2 = max(0, -e (u3 - u2)) = 0, and momentum v1 + v2 + v3 = sum(u).
  Eigen::Matrix3d a;
  a << -1, 1, 0, 0, -1, 1, 1, 1, 1;
  const Eigen::Vector3d rhs(e * (u[0] - u[1]), std::max(0.0, -e * (u[2] - u[1])), u.sum());
  const Eigen::Vector3d v = a.partialPivLu().solve(rhs);
  // Both impulses must push for that guess to be the fixed point.
  const double lambda_left = u[0] - v[0];
  const double lambda_right = v[2] - u[2];
  ASSERT_GT(lambda_left, 0.0);
  ASSERT_GT(lambda_right, 0.0);

  ASSERT_TRUE(report.converged);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(bodies[i].velocity().x, v[i], kTight);
  EXPECT_NEAR(v[0], -0.3, kTight);  // the contract's quoted values
  EXPECT_NEAR(v[1], 0.7, kTight);
  EXPECT_NEAR(impulses[0].normal, lambda_left, kTight);
  EXPECT_NEAR(impulses[1].normal, lambda_right, kTight);
  const double energy_before = 0.5 * u.squaredNorm();
  const double energy_after = 0.5 * v.squaredNorm();
  EXPECT_NEAR(report.kinetic_energy_before, energy_before, kTight);
  EXPECT_NEAR(report.kinetic_energy_after, energy_after, kTight);
  EXPECT_NEAR(energy_before, 0.505, kTight);
  EXPECT_NEAR(energy_after, 0.535, kTight);
  EXPECT_GT(report.kinetic_energy_after, report.kinetic_energy_before);
}

}  // namespace
}  // namespace collision2d
