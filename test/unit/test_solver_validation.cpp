// ContactSolver rejects out-of-range and non-finite settings, naming the
// parameter, and rejects contacts that name missing bodies.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Settings
{
  double e = 0.5;
  double mu = 0.3;
  int iterations = 64;
  double tol = 1e-12;
  double bias_factor = 0.2;
  double slop = 1e-3;
};

ContactSolver make(const Settings& s)
{
  return ContactSolver(s.e, s.mu, s.iterations, s.tol, s.bias_factor, s.slop);
}

/// Expects std::invalid_argument whose message names `parameter`.
void expect_rejected(const Settings& s, const std::string& parameter)
{
  try
  {
    make(s);
    ADD_FAILURE() << parameter << " was accepted";
  }
  catch (const std::invalid_argument& error)
  {
    EXPECT_NE(std::string(error.what()).find(parameter), std::string::npos) << error.what();
  }
}

TEST(SolverValidation, RejectsRestitutionOutsideTheUnitInterval)
{
  for (double e : {-1e-9, 1.0 + 1e-9, kNaN, kInf, -kInf})
  {
    Settings s;
    s.e = e;
    expect_rejected(s, "e (restitution)");
  }
}

TEST(SolverValidation, RejectsNegativeOrNonFiniteFriction)
{
  for (double mu : {-1e-9, kNaN, kInf})
  {
    Settings s;
    s.mu = mu;
    expect_rejected(s, "mu");
  }
}

TEST(SolverValidation, RejectsFewerThanOneIteration)
{
  for (int iterations : {0, -5})
  {
    Settings s;
    s.iterations = iterations;
    expect_rejected(s, "iterations");
  }
}

TEST(SolverValidation, RejectsNonPositiveOrNonFiniteTolerance)
{
  for (double tol : {0.0, -1e-12, kNaN, kInf})
  {
    Settings s;
    s.tol = tol;
    expect_rejected(s, "tol");
  }
}

TEST(SolverValidation, RejectsBiasFactorOutsideTheUnitInterval)
{
  for (double bias : {-0.1, 1.1, kNaN})
  {
    Settings s;
    s.bias_factor = bias;
    expect_rejected(s, "bias_factor");
  }
}

TEST(SolverValidation, RejectsNegativeOrNonFiniteSlop)
{
  for (double slop : {-1e-6, kNaN, kInf})
  {
    Settings s;
    s.slop = slop;
    expect_rejected(s, "slop");
  }
}

TEST(SolverValidation, AcceptsTheEdgesOfEveryRange)
{
  Settings low;
  low.e = 0.0;
  low.mu = 0.0;
  low.iterations = 1;
  low.tol = std::numeric_limits<double>::denorm_min();
  low.bias_factor = 0.0;
  low.slop = 0.0;
  const ContactSolver a = make(low);
  EXPECT_EQ(a.restitution(), 0.0);
  EXPECT_EQ(a.max_iterations(), 1);
  Settings high;
  high.e = 1.0;
  high.mu = 1e6;
  high.bias_factor = 1.0;
  const ContactSolver b = make(high);
  EXPECT_EQ(b.restitution(), 1.0);
  EXPECT_EQ(b.bias_factor(), 1.0);
  EXPECT_EQ(b.friction(), 1e6);
}

TEST(SolverValidation, RejectsContactsThatNameMissingBodiesOrBadNormals)
{
  std::vector<Body> bodies;
  bodies.emplace_back(1.0, 0.5, Vec2{0.0, 0.0}, Vec2{1.0, 0.0});
  bodies.emplace_back(1.0, 0.5, Vec2{0.9, 0.0}, Vec2{});
  const ContactSolver solver(0.5, 0.0);
  const std::vector<Contact> bad{
      test::make_contact(0, 2, Vec2{1.0, 0.0}, Vec2{0.45, 0.0}, 0.1),      // missing body
      test::make_contact(1, 1, Vec2{1.0, 0.0}, Vec2{0.45, 0.0}, 0.1),      // same body twice
      test::make_contact(0, 1, Vec2{0.0, 0.0}, Vec2{0.45, 0.0}, 0.1),      // no direction
      test::make_contact(0, 1, Vec2{kNaN, 0.0}, Vec2{0.45, 0.0}, 0.1),     // not finite
      test::make_contact(0, 1, Vec2{1.0, 0.0}, Vec2{0.45, kInf}, 0.1),     // point not finite
  };
  for (const Contact& c : bad)
  {
    std::vector<Body> copy = bodies;
    EXPECT_THROW(solver.solve(copy, {c}), std::invalid_argument);
    EXPECT_THROW(solver.correct_positions(copy, {c}), std::invalid_argument);
    EXPECT_EQ(copy[0].velocity().x, 1.0);  // nothing applied before the rejection
  }
}

}  // namespace
}  // namespace collision2d
