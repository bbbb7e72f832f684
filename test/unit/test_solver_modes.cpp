// ContactSolver's mode switch: SolverMode::Exact reaches the exact fixed
// point through the public API, and falls back to the iterative solve (with
// the report saying so) when pivoting cannot answer.
#include <gtest/gtest.h>

#include <vector>

#include "collision2d/contact_solver.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
using test::make_contact;

constexpr double kVelocityTol = 1e-12;  // m/s

// The contract's three equal touching disks, velocities (1, 0, 0.1), e = 1.
std::vector<Body> three_disks()
{
  return {Body(1.0, 0.5, {0.0, 0.0}, {1.0, 0.0}), Body(1.0, 0.5, {1.0, 0.0}, {0.0, 0.0}),
          Body(1.0, 0.5, {2.0, 0.0}, {0.1, 0.0})};
}

std::vector<Contact> three_disk_contacts()
{
  return {make_contact(0, 1, {1, 0}, {0.5, 0}, 0.0), make_contact(1, 2, {1, 0}, {1.5, 0}, 0.0)};
}

TEST(SolverModes, DefaultIsIterativeAndExactCanBeSelected)
{
  ContactSolver solver(1.0, 0.0);
  EXPECT_EQ(solver.mode(), SolverMode::Iterative);
  solver.set_mode(SolverMode::Exact);
  EXPECT_EQ(solver.mode(), SolverMode::Exact);
}

TEST(SolverModes, ExactModeHitsTheFixedPointWithoutIterating)
{
  // Fixed point from the two active rows: 2 l1 - l2 = 2 (target e * 1) and
  // 2 l2 - l1 = -0.1 (target 0 for the separating pair): l1 = 1.3, l2 = 0.6.
  const double l2 = (2.0 * 0.5 - 0.1) / 1.5;
  const double l1 = 2.0 * l2 + 0.1;
  ContactSolver solver(1.0, 0.0);
  solver.set_mode(SolverMode::Exact);
  std::vector<Body> bodies = three_disks();
  std::vector<ContactImpulse> impulses;
  const SolveReport report = solver.solve(bodies, three_disk_contacts(), &impulses);
  EXPECT_FALSE(report.exact_fallback);
  EXPECT_TRUE(report.converged);
  EXPECT_NEAR(bodies[0].velocity().x, 1.0 - l1, kVelocityTol);
  EXPECT_NEAR(bodies[1].velocity().x, l1 - l2, kVelocityTol);
  EXPECT_NEAR(bodies[2].velocity().x, 0.1 + l2, kVelocityTol);
  ASSERT_EQ(impulses.size(), 2u);
  EXPECT_NEAR(impulses[0].normal, l1, kVelocityTol);
  EXPECT_NEAR(impulses[1].normal, l2, kVelocityTol);
}

TEST(SolverModes, ExactFailureFallsBackToTheIterativeSolve)
{
  // A disk pinched between two touching static walls, moving right with
  // e = 1: no non-negative impulses meet both targets, so pivoting fails.
  // The fallback must be exactly what the iterative mode computes.
  auto wall = [](double x) {
    Body b(1.0, {{-0.5, -2.0}, {0.5, -2.0}, {0.5, 2.0}, {-0.5, 2.0}}, {x, 0.0}, {0.0, 0.0});
    b.set_type(BodyType::Static);
    return b;
  };
  const std::vector<Body> input = {wall(-1.0), Body(1.0, 0.5, {0.0, 0.0}, {2.0, 0.5}), wall(1.0)};
  const std::vector<Contact> contacts = {make_contact(0, 1, {1, 0}, {-0.5, 0}, 0.0),
                                         make_contact(1, 2, {1, 0}, {0.5, 0}, 0.0)};
  ContactSolver exact(1.0, 0.0, 200);
  exact.set_mode(SolverMode::Exact);
  const ContactSolver iterative(1.0, 0.0, 200);

  std::vector<Body> by_exact = input;
  std::vector<Body> by_iterative = input;
  std::vector<ContactImpulse> impulses;
  const SolveReport exact_report = exact.solve(by_exact, contacts, &impulses);
  const SolveReport iterative_report = iterative.solve(by_iterative, contacts);
  EXPECT_TRUE(exact_report.exact_fallback);
  EXPECT_FALSE(iterative_report.exact_fallback);
  EXPECT_EQ(exact_report.iterations, iterative_report.iterations);
  EXPECT_EQ(by_exact[1].velocity(), by_iterative[1].velocity());
  // The walls never move, whatever the mode.
  EXPECT_EQ(by_exact[0].velocity(), input[0].velocity());
  EXPECT_EQ(by_exact[2].velocity(), input[2].velocity());
  // No target can hold here, but impulses still only push.
  ASSERT_EQ(impulses.size(), contacts.size());
  for (const ContactImpulse& impulse : impulses)
    EXPECT_GE(impulse.normal, 0.0);
}

}  // namespace
}  // namespace collision2d
