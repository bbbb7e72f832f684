// Helpers shared by the exact-solver tests: bodies and contacts built by hand,
// one solve with its impulses and report, and the solver's contract
// recomputed from the bodies and impulses the solver returns.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/contact_solver.h"
#include "collision2d/exact_solver.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace test
{
constexpr double kTol = 1e-12;            // solver tolerance passed in
constexpr double kContractTol = 1e-12;    // relative to the velocity scale
constexpr double kStepSpeed = 9.81 / 60;  // m/s gained under gravity in one 60 Hz frame

inline Body disk(double mass, double radius, Vec2 position, Vec2 velocity)
{
  return Body(mass, radius, position, velocity);
}

inline Body box(double mass, double half_w, double half_h, Vec2 position, Vec2 velocity)
{
  return Body(mass, {{-half_w, -half_h}, {half_w, -half_h}, {half_w, half_h}, {-half_w, half_h}}, position,
              velocity);
}

inline Body static_box(double half_w, double half_h, Vec2 position)
{
  Body b = box(1.0, half_w, half_h, position, {0.0, 0.0});
  b.set_type(BodyType::Static);
  return b;
}

/// Inverse effective mass of a contact along `dir`, from the bodies alone.
inline double inverse_effective_mass(const std::vector<Body>& bodies, const Contact& c, Vec2 dir)
{
  const Body& a = bodies[c.a];
  const Body& b = bodies[c.b];
  const double ra = cross(c.point - a.position(), dir);
  const double rb = cross(c.point - b.position(), dir);
  return a.inv_mass() + b.inv_mass() + a.inv_inertia() * ra * ra + b.inv_inertia() * rb * rb;
}

/// The speeds the problem involves: contact speeds before and after and the
/// speed change each impulse makes on its own contact.
inline double velocity_scale(const std::vector<Body>& before, const std::vector<Body>& after,
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
inline void expect_impulses_explain_velocities(const std::vector<Body>& before, const std::vector<Body>& after,
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
inline double expect_contract(const std::vector<Body>& before, const std::vector<Body>& after,
                              const std::vector<Contact>& contacts, const std::vector<ContactImpulse>& impulses,
                              double e, double mu, double relative_tol)
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

inline Outcome solve(const std::vector<Body>& bodies, const std::vector<Contact>& contacts, double e, double mu)
{
  Outcome out{bodies, {}, {}};
  out.report = solve_exact(out.bodies, contacts, e, mu, kTol, &out.impulses);
  return out;
}

/// Disks a < b touching along the line of centres.
inline Contact disk_contact(const std::vector<Body>& bodies, std::size_t a, std::size_t b)
{
  const Vec2 d = bodies[b].position() - bodies[a].position();
  const Vec2 n = d / length(d);
  return make_contact(a, b, n, bodies[a].position() + bodies[a].radius() * n, 0.0);
}

/// Bodies at rest on one another and the contacts between them.
struct Resting
{
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

}  // namespace test
}  // namespace collision2d
