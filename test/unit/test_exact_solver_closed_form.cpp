// Exact (pivoting) contact solve on cases with a hand solution: closed-form
// impacts over mass ratios, a static wall, resting boxes with redundant
// contacts (a singular Delassus matrix), Coulomb sliding and sticking.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "collision2d/exact_solver.h"
#include "exact_solver_test_support.h"

namespace collision2d
{
namespace
{
using test::box;
using test::disk;
using test::disk_contact;
using test::expect_contract;
using test::kContractTol;
using test::kStepSpeed;
using test::make_contact;
using test::Outcome;
using test::Resting;
using test::solve;
using test::static_box;

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
  EXPECT_EQ(out.report.island_count, 1u);
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

}  // namespace
}  // namespace collision2d
