// Non-finite input (robustness): every core entry point rejects NaN
// and infinities with an error that names what was wrong, finite input whose
// derived mass properties leave the double range is rejected rather than
// turned into NaN, and a random soak asserts that finite input never gives a
// non-finite output (resolve, step and World::step).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scenario_io.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/random_scenes.h"
#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
const std::vector<double> kBadValues = {kNan, kInf, -kInf};

/// Runs `call`, expects exception type E whose message contains `needle`.
template <typename E>
void expect_error(const std::function<void()>& call, const std::string& needle, const std::string& what)
{
  try
  {
    call();
    ADD_FAILURE() << what << ": no exception";
  }
  catch (const E& e)
  {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos)
        << what << ": message '" << e.what() << "' does not mention '" << needle << "'";
  }
  catch (const std::exception& e)
  {
    ADD_FAILURE() << what << ": wrong exception type: " << e.what();
  }
}

std::string show(double v)
{
  std::ostringstream out;
  out << v;
  return out.str();
}

std::vector<Vec2> unit_box() { return scenes::box_outline(1.0, 1.0); }

TEST(ExtremesNonFinite, DiskConstructorNamesTheField)
{
  for (double bad : kBadValues)
  {
    const std::string tag = " = " + show(bad);
    expect_error<std::invalid_argument>([&] { Body(bad, 1.0, {}, {}); }, "mass", "mass" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, bad, {}, {}); }, "radius", "radius" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, 1.0, {bad, 0.0}, {}); }, "position", "position" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, 1.0, {}, {0.0, bad}); }, "velocity", "velocity" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, 1.0, {}, {}, bad); }, "omega", "omega" + tag);
  }
}

TEST(ExtremesNonFinite, PolygonConstructorNamesTheField)
{
  for (double bad : kBadValues)
  {
    const std::string tag = " = " + show(bad);
    std::vector<Vec2> outline = unit_box();
    outline[2].y = bad;
    expect_error<std::invalid_argument>([&] { Body(1.0, outline, {}, {}); }, "vertices[2]", "vertex" + tag);
    expect_error<std::invalid_argument>([&] { Body(bad, unit_box(), {}, {}); }, "mass", "mass" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, unit_box(), {bad, 0.0}, {}); }, "position", "position" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, unit_box(), {}, {bad, 0.0}); }, "velocity", "velocity" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, unit_box(), {}, {}, bad); }, "theta", "theta" + tag);
    expect_error<std::invalid_argument>([&] { Body(1.0, unit_box(), {}, {}, 0.0, bad); }, "omega", "omega" + tag);
  }
}

// Finite arguments whose products leave the double range: before the fix
// these built bodies with inverse inertia inf (radius 1e-200) or inertia inf
// (radius 1e200), and the first contact or energy computed NaN.
TEST(ExtremesNonFinite, FiniteInputOutsideTheDoubleRangeIsRejected)
{
  const std::string needle = "unusable mass properties";
  expect_error<std::invalid_argument>([] { Body(1.0, 1e-200, {}, {}); }, needle, "radius 1e-200");
  expect_error<std::invalid_argument>([] { Body(1.0, 1e200, {}, {}); }, needle, "radius 1e200");
  expect_error<std::invalid_argument>([] { Body(1e-320, 1.0, {}, {}); }, needle, "mass 1e-320");
  expect_error<std::invalid_argument>([] { Body(1e308, 100.0, {}, {}); }, needle, "mass 1e308, radius 100");
  expect_error<std::invalid_argument>([] { Body(1.0, scenes::box_outline(1e200, 1e200), {}, {}); }, "Body",
                                      "box 1e200");
  expect_error<std::invalid_argument>([] { Body(1e-320, scenes::box_outline(1.0, 1.0), {}, {}); }, needle,
                                      "polygon mass 1e-320");
  // The extremes the other suites use stay accepted.
  EXPECT_NO_THROW(Body(1e-6, 1e-4, {1e6, 1e6}, {1e4, 0.0}, 1e4));
  EXPECT_NO_THROW(Body(1e6, scenes::box_outline(1e4, 1e4), {}, {}));
}

TEST(ExtremesNonFinite, ContactSolverSettingsAreRejected)
{
  for (double bad : kBadValues)
  {
    const std::string tag = " = " + show(bad);
    expect_error<std::invalid_argument>([&] { ContactSolver(bad, 0.0); }, "restitution", "e" + tag);
    expect_error<std::invalid_argument>([&] { ContactSolver(0.5, bad); }, "friction", "mu" + tag);
    expect_error<std::invalid_argument>([&] { ContactSolver(0.5, 0.0, 8, bad); }, "tol", "tol" + tag);
    expect_error<std::invalid_argument>([&] { ContactSolver(0.5, 0.0, 8, 1e-9, bad); }, "bias_factor",
                                        "bias" + tag);
    expect_error<std::invalid_argument>([&] { ContactSolver(0.5, 0.0, 8, 1e-9, 0.2, bad); }, "slop", "slop" + tag);
  }
}

/// Two overlapping disks, body 1 then spoiled through a setter.
std::vector<Body> spoiled(const std::function<void(Body&)>& spoil)
{
  std::vector<Body> bodies = {Body(1.0, 0.5, {0.0, 0.0}, {1.0, 0.0}), Body(1.0, 0.5, {0.9, 0.0}, {-1.0, 0.0})};
  spoil(bodies[1]);
  return bodies;
}

TEST(ExtremesNonFinite, ContactSolverEntryPointsRejectNonFiniteBodies)
{
  const ContactSolver solver(0.5, 0.3);
  const std::vector<Contact> contacts = ContactSolver::detect_contacts(spoiled([](Body&) {}));
  ASSERT_EQ(contacts.size(), 1u);
  const std::vector<std::pair<std::string, std::function<void(Body&)>>> spoilers = {
      {"position", [](Body& b) { b.set_position({kNan, 0.9}); }},
      {"theta", [](Body& b) { b.set_theta(kInf); }},
      {"velocity", [](Body& b) { b.set_velocity({-1.0, kInf}); }},
      {"omega", [](Body& b) { b.set_omega(-kInf); }},
  };
  for (const auto& spoiler : spoilers)
  {
    const std::string needle = "body 1: " + spoiler.first;
    std::vector<Body> bodies = spoiled(spoiler.second);
    expect_error<std::invalid_argument>([&] { ContactSolver::detect_contacts(bodies); }, needle, "detect");
    expect_error<std::invalid_argument>([&] { ContactSolver::detect_contacts(bodies, 1e-9); }, needle, "detect tol");
    expect_error<std::invalid_argument>([&] { solver.solve(bodies, contacts); }, needle, "solve");
    expect_error<std::invalid_argument>([&] { solver.correct_positions(bodies, contacts); }, needle, "correct");
    expect_error<std::invalid_argument>([&] { solver.resolve(bodies); }, needle, "resolve");
    expect_error<std::invalid_argument>([&] { ContactSolver::time_of_impact(bodies); }, needle, "toi");
    expect_error<std::invalid_argument>([&] { solver.step(bodies); }, needle, "step");
  }
}

TEST(ExtremesNonFinite, ContactSolverRejectsNonFiniteContacts)
{
  const ContactSolver solver(0.5, 0.3);
  std::vector<Body> bodies = spoiled([](Body&) {});
  std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  contacts[0].penetration = kNan;
  expect_error<std::invalid_argument>([&] { solver.solve(bodies, contacts); }, "contact 0", "penetration");
  contacts = ContactSolver::detect_contacts(bodies);
  contacts[0].normal = {kInf, 0.0};
  expect_error<std::invalid_argument>([&] { solver.correct_positions(bodies, contacts); }, "contact 0", "normal");
  expect_error<std::invalid_argument>([&] { ContactSolver::detect_contacts(bodies, kNan); }, "touch_tolerance",
                                      "touch tolerance");
}

TEST(ExtremesNonFinite, WorldSettingsNameTheField)
{
  const std::vector<std::pair<std::string, std::function<void(WorldSettings&, double)>>> fields = {
      {"gravity", [](WorldSettings& s, double v) { s.gravity.y = v; }},
      {"dt", [](WorldSettings& s, double v) { s.dt = v; }},
      {"slop", [](WorldSettings& s, double v) { s.slop = v; }},
      {"compliance", [](WorldSettings& s, double v) { s.compliance = v; }},
      {"restitution_threshold", [](WorldSettings& s, double v) { s.restitution_threshold = v; }},
      {"toi_displacement_fraction", [](WorldSettings& s, double v) { s.toi_displacement_fraction = v; }},
      {"sleep_linear_speed", [](WorldSettings& s, double v) { s.sleep_linear_speed = v; }},
      {"sleep_angular_speed", [](WorldSettings& s, double v) { s.sleep_angular_speed = v; }},
      {"sleep_time", [](WorldSettings& s, double v) { s.sleep_time = v; }},
  };
  World world;
  const double dt_before = world.settings().dt;
  for (const auto& field : fields)
  {
    for (double bad : kBadValues)
    {
      WorldSettings s;
      field.second(s, bad);
      const std::string what = field.first + " = " + show(bad);
      expect_error<std::invalid_argument>([&] { World w(s); }, field.first, "ctor " + what);
      expect_error<std::invalid_argument>([&] { world.set_settings(s); }, field.first, "set_settings " + what);
    }
  }
  EXPECT_EQ(world.settings().dt, dt_before);
}

TEST(ExtremesNonFinite, WorldBodiesAndMaterialsAreRejected)
{
  World world;
  const BodyId id = world.add_body(Body(1.0, 0.5, {0.0, 1.0}, {0.0, 0.0}));
  for (double bad : kBadValues)
  {
    const std::string tag = " = " + show(bad);
    expect_error<std::invalid_argument>([&] { world.add_body(Body(1.0, 0.5, {}, {}), Material{bad, 0.0, 0.0}); },
                                        "restitution", "restitution" + tag);
    expect_error<std::invalid_argument>([&] { world.add_body(Body(1.0, 0.5, {}, {}), Material{0.0, bad, 0.0}); },
                                        "static_friction", "static friction" + tag);
    expect_error<std::invalid_argument>([&] { world.add_body(Body(1.0, 0.5, {}, {}), Material{0.0, 0.0, bad}); },
                                        "kinetic_friction", "kinetic friction" + tag);
    expect_error<std::invalid_argument>([&] { world.set_body_state(id, {bad, 0.0}, 0.0, {}, 0.0); }, "non-finite",
                                        "set_body_state position" + tag);
    expect_error<std::invalid_argument>([&] { world.set_body_state(id, {}, 0.0, {}, bad); }, "non-finite",
                                        "set_body_state omega" + tag);
  }
  EXPECT_EQ(world.body_count(), 1u);
  EXPECT_EQ(world.body(id).position(), (Vec2{0.0, 1.0}));
}

// A body spoiled through its (unchecked) setters must not enter a world:
// one NaN body would turn its contact partners NaN on the next step.
TEST(ExtremesNonFinite, WorldAddBodyRejectsNonFiniteState)
{
  World world;
  Body body(1.0, 0.5, {0.0, 0.0}, {0.0, 0.0});
  body.set_velocity({kNan, 0.0});
  expect_error<std::invalid_argument>([&] { world.add_body(body); }, "velocity", "add_body NaN velocity");
  EXPECT_EQ(world.body_count(), 0u);
}

TEST(ExtremesNonFinite, ScenarioParserNamesTheLine)
{
  const std::vector<std::string> bad_tokens = {"nan", "NaN", "inf", "-inf", "1e999", "-1e400", "infinity"};
  for (const std::string& token : bad_tokens)
  {
    const std::vector<std::string> inputs = {
        "restitution 0.5\nbody 1 0.5 0 0 1 0\nbody 1 0.5 " + token + " 0 -1 0\n",
        "restitution 0.5\nbody 1 0.5 0 0 1 0\npoly 1 0 0 0 0 0 0 3 0 0 1 0 0 " + token + "\n",
        "restitution 0.5\nbody 1 0.5 0 0 1 0\nbody 1 0.5 1 0 -1 0 " + token + "\n",
        "restitution 0.5\nfriction 0.2\nbody 1 0.5 0 0 1 0\nbody " + token + " 0.5 1 0 -1 0\n",
    };
    for (const std::string& text : inputs)
    {
      std::istringstream in(text);
      const std::size_t line = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
      expect_error<std::runtime_error>([&] { parse_scenario(in, "x.collision"); },
                                       "x.collision:" + std::to_string(line) + ":", token + " in\n" + text);
    }
  }
  std::istringstream settings("restitution nan\nbody 1 0.5 0 0 1 0\nbody 1 0.5 1 0 -1 0\n");
  expect_error<std::runtime_error>([&] { parse_scenario(settings, "s"); }, "s:1:", "restitution nan");
}

TEST(ExtremesNonFinite, SceneYamlNamesTheKey)
{
  const std::vector<std::string> bad_tokens = {".nan", ".inf", "-.inf", "1e999"};
  for (const std::string& token : bad_tokens)
  {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"gravity: [0, " + token + "]\n", "gravity"},
        {"settings: {dt: " + token + "}\n", "dt"},
        {"bodies:\n  - {shape: disk, mass: 1, radius: " + token + ", position: [0, 0]}\n", "radius"},
        {"bodies:\n  - {shape: disk, mass: 1, radius: 1, position: [0, 0], velocity: [" + token + ", 0]}\n",
         "velocity"},
        {"bodies:\n  - {shape: polygon, mass: 1, vertices: [[0, 0], [1, 0], [0, " + token + "]]}\n", "vertices"},
        {"materials:\n  m: {restitution: " + token + "}\n", "restitution"},
        {"generate:\n  - column: {count: 2, box: " + token + "}\n", "box"},
    };
    for (const auto& c : cases)
    {
      expect_error<std::runtime_error>([&] { scenes::parse_scene_yaml(c.first, "s.yaml"); }, c.second,
                                       token + " in\n" + c.first);
    }
  }
}

// Finite in, finite out: random multi-contact scenes (the solver soak's
// generator) through resolve, step and a few world frames.
TEST(ExtremesNonFinite, RandomSoakGivesFiniteOutput)
{
  const long scene_count = test::sized(1500, 300, "non-finite soak scenes");
  scenes::RandomSceneOptions options;
  options.max_mass_ratio = 1e6;
  options.static_probability = 0.2;
  options.max_speed = 50.0;
  options.max_spin = 50.0;
  scenes::RandomSceneGenerator generator(0xf1417e, options);
  constexpr int kWorldFrames = 3;
  long outputs = 0;
  for (long k = 0; k < scene_count; ++k)
  {
    const scenes::RandomScene scene = generator.next();
    const ContactSolver solver(scene.restitution, scene.friction);
    std::vector<Body> resolved = scene.bodies;
    const SolveReport r1 = solver.resolve(resolved);
    std::vector<Body> stepped = scene.bodies;
    const SolveReport r2 = solver.step(stepped);
    ASSERT_TRUE(test::all_finite(resolved)) << "resolve, scene " << k;
    ASSERT_TRUE(test::all_finite(stepped)) << "step, scene " << k;
    for (const SolveReport& r : {r1, r2})
    {
      ASSERT_TRUE(std::isfinite(r.max_residual) && std::isfinite(r.total_normal_impulse) &&
                  std::isfinite(r.kinetic_energy_after) && std::isfinite(r.time_of_impact))
          << "report, scene " << k;
    }
    World world;
    for (const Body& b : scene.bodies)
    {
      world.add_body(b, Material{scene.restitution, scene.friction, scene.friction});
    }
    const StepReport report = world.step(kWorldFrames);
    ASSERT_TRUE(test::all_finite(world)) << "world, scene " << k;
    ASSERT_TRUE(std::isfinite(report.kinetic_energy) && std::isfinite(report.max_penetration) &&
                std::isfinite(report.velocity_residual))
        << "world report, scene " << k;
    for (const WorldContact& c : world.contacts())
    {
      ASSERT_TRUE(std::isfinite(c.impulse.normal) && std::isfinite(c.impulse.tangent) &&
                  is_finite(c.contact.normal) && is_finite(c.contact.point))
          << "world contact, scene " << k;
    }
    outputs += static_cast<long>(resolved.size() + stepped.size() + world.body_count());
  }
  std::printf("finite-output soak: %ld scenes, %ld body states checked\n", scene_count, outputs);
}

}  // namespace
}  // namespace collision2d
