// Exact (pivoting) contact solve on islands: stacks at extreme mass ratios,
// infeasible and oversized islands falling back, islands coupled only through
// dynamic bodies, and random islands, each against the solver's contract.
#include <gtest/gtest.h>

#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/exact_solver.h"
#include "collision2d/scenes/random_scenes.h"
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
using test::kTol;
using test::make_contact;
using test::normal_speed;
using test::Outcome;
using test::Resting;
using test::solve;
using test::static_box;

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

TEST(ExactSolver, OversizedIslandFallsBackAndSmallerOnesSolve)
{
  // A touching row of disks: one island of n - 1 contacts, 4 unknowns each
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

TEST(ExactSolver, StaticBodiesDoNotCoupleIslandsAndKinematicOnesKeepTheirVelocity)
{
  // Two disks on one static floor (two islands), a kinematic paddle hitting
  // a third disk (one island), and a contact between floor and paddle (no
  // dynamic body: no impulse).
  std::vector<Body> bodies = {static_box(10.0, 0.5, {0, -0.5}), disk(1.0, 0.5, {-3, 0.5}, {0, -1}),
                              disk(2.0, 0.5, {3, 0.5}, {0, -2}), box(1.0, 0.5, 0.5, {6, 0.5}, {-1, 0}),
                              disk(1.0, 0.5, {5, 0.5}, {0, 0})};
  bodies[3].set_type(BodyType::Kinematic);
  const std::vector<Contact> contacts = {
      make_contact(0, 1, {0, 1}, {-3, 0}, 0.0), make_contact(0, 2, {0, 1}, {3, 0}, 0.0),
      make_contact(0, 3, {0, 1}, {6, 0}, 0.0), make_contact(3, 4, {-1, 0}, {5.5, 0.5}, 0.0)};
  const Outcome out = solve(bodies, contacts, 0.5, 0.0);
  EXPECT_EQ(out.report.island_count, 3u);
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

TEST(ExactSolver, RandomIslandsHonourTheContract)
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
