// Finite input far beyond the supported ranges can overflow double precision
// mid-solve. Every entry point must then refuse with std::overflow_error that
// names the body, and ContactSolver's entry points must leave the bodies
// exactly as they came in, instead of handing back inf or NaN.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scenario_io.h"
#include "collision2d/world.h"
#include "extremes_support.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
// Two disks closing at 3e308 m/s, each speed finite: the approach speed, and
// with it every impulse, is inf.
const char* const kOverflowingScenario =
    "body 1 1 0 0 1.5e308 0\n"
    "body 1 1 1.5 0 -1.5e308 0\n"
    "restitution 0.5\n"
    "friction 3\n";

// Found by fuzz_scenario (then minimised): a disk of radius 6.7e31 m swallows
// a small disk and a triangle whose contact points lie 1e31 m from their
// centres. Before the solver's arithmetic became the shared kernel's, each
// Gauss-Seidel pass multiplied the triangle's spin until it reached inf; now
// the passes stay finite. Either outcome is allowed, never a NaN.
const char* const kFuzzRegressionScenario =
    "body 0.5 33 5 0.79 0.03 5\n"
    "body 0.5 66666666666666666666666666666663 0 0 0 3\n"
    "poly 1 1.09 0 0 1 0 0 3 -0.6 0 0.3 -5 3 0.5\n"
    "restitution 0.5\n"
    "friction 3\n";

bool same_state(const std::vector<Body>& a, const std::vector<Body>& b)
{
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (!(a[i].position() == b[i].position() && a[i].theta() == b[i].theta() &&
          a[i].velocity() == b[i].velocity() && a[i].omega() == b[i].omega()))
      return false;
  }
  return a.size() == b.size();
}

std::vector<Body> scenario_bodies(const char* text)
{
  std::istringstream in(text);
  return parse_scenario(in, "overflow").bodies;
}

std::vector<Body> overflowing_bodies() { return scenario_bodies(kOverflowingScenario); }

TEST(Overflow, FuzzRegressionIsFiniteOrRefused)
{
  const std::vector<Body> before = scenario_bodies(kFuzzRegressionScenario);
  for (SolverMode mode : {SolverMode::Iterative, SolverMode::Exact})
  {
    ContactSolver solver(0.5, 3.0);
    solver.set_mode(mode);
    std::vector<Body> bodies = before;
    try
    {
      solver.resolve(bodies);
      EXPECT_TRUE(test::all_finite(bodies));
    }
    catch (const std::overflow_error& e)
    {
      EXPECT_TRUE(same_state(before, bodies)) << e.what();
    }
  }
}

TEST(Overflow, ResolveRefusesAndLeavesTheBodiesAsTheyWere)
{
  const std::vector<Body> before = overflowing_bodies();
  const ContactSolver solver(0.5, 3.0);
  std::vector<Body> bodies = before;
  try
  {
    solver.resolve(bodies);
    ADD_FAILURE() << "resolve returned; the approach speed should overflow";
  }
  catch (const std::overflow_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("body "), std::string::npos) << e.what();
  }
  EXPECT_TRUE(same_state(before, bodies));
}

TEST(Overflow, StepAndSolveRefuseToo)
{
  const std::vector<Body> before = overflowing_bodies();
  const ContactSolver solver(0.5, 3.0);
  std::vector<Body> bodies = before;
  EXPECT_THROW(solver.step(bodies), std::overflow_error);
  EXPECT_TRUE(same_state(before, bodies));

  const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  EXPECT_THROW(solver.solve(bodies, contacts), std::overflow_error);
  EXPECT_TRUE(same_state(before, bodies));
  ContactSolver exact = solver;
  exact.set_mode(SolverMode::Exact);
  EXPECT_THROW(exact.solve(bodies, contacts), std::overflow_error);
  EXPECT_TRUE(same_state(before, bodies));
}

TEST(Overflow, PositionCorrectionRefusesAndPutsTheBodiesBack)
{
  // A finite depth of 1e308 m moves a body at 1.5e308 m past the largest double.
  constexpr double kFar = 1.5e308;
  const std::vector<Body> before = {Body(1.0, 1.0, {kFar, 0.0}, {}), Body(1.0, 1.0, {kFar, 0.0}, {})};
  std::vector<Body> bodies = before;
  Contact contact;
  contact.a = 0;
  contact.b = 1;
  contact.normal = {-1.0, 0.0};
  contact.point = {kFar, 0.0};
  contact.penetration = 1e308;
  const ContactSolver solver(0.0, 0.0, 8, 1e-12, /*bias_factor=*/1.0, /*slop=*/0.0);
  EXPECT_THROW(solver.correct_positions(bodies, {contact}), std::overflow_error);
  EXPECT_TRUE(same_state(before, bodies));
  EXPECT_TRUE(test::all_finite(bodies));
}

TEST(Overflow, WorldStepRefusesNamingTheBody)
{
  // Gravity 1e308 m/s^2 over one-second frames: the second frame's velocity
  // passes the largest double.
  WorldSettings settings;
  settings.gravity = {0.0, -1e308};
  settings.dt = 1.0;
  settings.substeps = 1;
  World world(settings);
  world.add_body(Body(1.0, 1.0, {0.0, 0.0}, {}));
  const BodyId falling = world.add_body(Body(1.0, 1.0, {10.0, 0.0}, {}));
  world.remove_body(world.body_ids().front());
  world.step();
  const World before = world;
  try
  {
    world.step(3);
    ADD_FAILURE() << "step returned a state past the largest double";
  }
  catch (const std::overflow_error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("body " + std::to_string(falling)), std::string::npos) << message;
  }
  // The failed call is undone: the world is as it was before it.
  EXPECT_EQ(world.frame_count(), before.frame_count());
  EXPECT_EQ(world.time(), before.time());
  const Body& now = world.body(falling);
  const Body& then = before.body(falling);
  EXPECT_TRUE(now.position() == then.position() && now.velocity() == then.velocity() &&
              now.theta() == then.theta() && now.omega() == then.omega());
}

TEST(Overflow, RefusedWorldStepPutsTheContactsBack)
{
  // Two overlapping disks are pushed apart (a contact with impulses); then a
  // third, far away, is thrown at 1e308 m/s under 1e308 m/s^2, so the next
  // frame overflows. A one-frame step keeps its starting contacts in the
  // warm-start cache instead of copying them; either way the refused call
  // must put them back.
  for (const bool soft : {true, false})
  {
    for (const int frames : {1, 2})
    {
      WorldSettings settings;
      settings.soft_step = soft;
      settings.gravity = {0.0, 0.0};
      settings.dt = 1.0;
      settings.substeps = 1;
      World world(settings);
      world.add_body(Body(1.0, 1.0, {0.0, 0.0}, {}));
      world.add_body(Body(1.0, 1.0, {1.99, 0.0}, {}));
      const BodyId thrown = world.add_body(Body(1.0, 1.0, {100.0, 0.0}, {}));
      world.step();
      ASSERT_FALSE(world.contacts().empty()) << "soft " << soft;
      settings.gravity = {0.0, -1e308};
      world.set_settings(settings);
      world.set_body_state(thrown, {100.0, 0.0}, 0.0, {0.0, -1e308}, 0.0);
      const World before = world;
      EXPECT_THROW(world.step(frames), std::overflow_error) << "soft " << soft << ", frames " << frames;
      EXPECT_TRUE(test::same_contacts(world.contacts(), before.contacts())) << "soft " << soft << ", frames " << frames;
      EXPECT_EQ(world.frame_count(), before.frame_count());
    }
  }
}

TEST(Overflow, InRangeWorldStepsWithoutRefusal)
{
  // The guard must not fire on the largest promised inputs: 1e4 m/s at 1e6 m.
  World world;
  world.add_body(Body(1.0, 1.0, {1e6, 0.0}, {1e4, 0.0}, 1e4));
  world.add_body(Body(1e6, 1.0, {1e6 + 50.0, 0.0}, {-1e4, 0.0}));
  EXPECT_NO_THROW(world.step(60));
  EXPECT_TRUE(test::all_finite(world));
}

}  // namespace
}  // namespace collision2d
