// `.collision` parsing (every line type, every rejection with its line), the
// shipped scenarios, and the numbers in the report.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/scenario_io.h"

namespace collision2d
{
namespace
{
constexpr const char* kSource = "test.collision";

Scenario parse(const std::string& text)
{
  std::istringstream in(text);
  return parse_scenario(in, kSource);
}

TEST(ParseScenario, ReadsEveryLineType)
{
  const Scenario s = parse(
      "# a comment line\n"
      "\n"
      "body 2.5 0.75 1.25 -3.5 4 -0.5        # disk without spin\n"
      "   body 1 0.5 0 10 0 0 -2.25\n"
      "poly 3 7 8 0.5 -1 2 0.25 4  -1 -0.5  1 -0.5  1 0.5  -1 0.5   # box\n"
      "restitution 0.8   # trailing comment\n"
      "friction 0.35\n");
  ASSERT_EQ(s.bodies.size(), 3u);
  EXPECT_EQ(s.restitution, 0.8);
  EXPECT_EQ(s.friction, 0.35);

  const Body& a = s.bodies[0];
  EXPECT_EQ(a.shape(), Shape::Disk);
  EXPECT_EQ(a.mass(), 2.5);  // decimals come back exactly as written
  EXPECT_EQ(a.radius(), 0.75);
  EXPECT_EQ(a.position(), (Vec2{1.25, -3.5}));
  EXPECT_EQ(a.velocity(), (Vec2{4, -0.5}));
  EXPECT_EQ(a.omega(), 0.0);
  EXPECT_EQ(s.bodies[1].omega(), -2.25);

  const Body& box = s.bodies[2];
  EXPECT_EQ(box.shape(), Shape::Polygon);
  EXPECT_EQ(box.mass(), 3.0);
  EXPECT_EQ(box.position(), (Vec2{7, 8}));
  EXPECT_EQ(box.theta(), 0.5);
  EXPECT_EQ(box.velocity(), (Vec2{-1, 2}));
  EXPECT_EQ(box.omega(), 0.25);
  ASSERT_EQ(box.vertex_count(), 4u);
  // Already centred on its centroid, so the vertices come back as written.
  const std::vector<Vec2> expected{{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}};
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    EXPECT_NEAR(box.local_vertices()[i].x, expected[i].x, 1e-15);
    EXPECT_NEAR(box.local_vertices()[i].y, expected[i].y, 1e-15);
  }
}

TEST(ParseScenario, FrictionDefaultsToZero)
{
  const Scenario s = parse("restitution 0.5\nbody 1 1 0 0 0 0\nbody 1 1 3 0 0 0\n");
  EXPECT_EQ(s.friction, 0.0);
  EXPECT_EQ(s.restitution, 0.5);
}

struct Rejection
{
  const char* what;
  std::string text;
  int line;
  const char* fragment;
};

/// Two valid bodies and a restitution; each case appends its bad line as line 4.
const std::string kValid = "body 1 0.5 0 0 1 0\nbody 1 0.5 3 0 -1 0\nrestitution 0.5\n";

TEST(ParseScenario, RejectsMalformedInputNamingTheLine)
{
  const std::vector<Rejection> cases{
      {"unknown keyword", kValid + "bodyy 1 1 0 0 0 0\n", 4, "unknown keyword 'bodyy'"},
      {"missing field", kValid + "body 1 0.5 0 0 1\n", 4, "missing field vy"},
      {"missing poly vertex", kValid + "poly 1 0 0 0 0 0 0 3 0 0 1 0 0\n", 4, "vertex count mismatch"},
      {"missing setting value", "restitution\n", 1, "missing field e"},
      {"extra field", kValid + "body 1 0.5 0 0 1 0 0 7\n", 4, "1 extra field(s), starting at '7'"},
      {"extra setting field", kValid + "friction 0.1 0.2\n", 4, "extra field"},
      {"non-numeric", kValid + "body 1 0.5 0 zero 1 0\n", 4, "field py of 'body' is not a number: 'zero'"},
      {"number with junk", kValid + "body 1 0.5 0 0 1.5x 0\n", 4, "field vx of 'body' is not a number"},
      {"infinite", kValid + "body 1 0.5 0 0 inf 0\n", 4, "field vx of 'body' is not finite"},
      {"nan", kValid + "poly 1 0 0 nan 0 0 0 3 0 0 1 0 0 1\n", 4, "field theta of 'poly' is not finite"},
      {"overflow", kValid + "body 1e999 0.5 0 0 0 0\n", 4, "field m of 'body' is not finite"},
      {"too many vertices", kValid + "poly 1 0 0 0 0 0 0 3 0 0 1 0 0 1 5 5\n", 4, "vertex count mismatch"},
      {"fractional k", kValid + "poly 1 0 0 0 0 0 0 1.5 0 0 1 0 0\n", 4, "whole number"},
      {"negative mass", kValid + "body -1 0.5 0 0 0 0\n", 4, "invalid body"},
      {"zero radius", kValid + "body 1 0 0 0 0 0\n", 4, "invalid body"},
      {"clockwise polygon", kValid + "poly 1 0 0 0 0 0 0 3 0 0 0 1 1 0\n", 4, "invalid body"},
      {"two-vertex polygon", kValid + "poly 1 0 0 0 0 0 0 2 0 0 1 0\n", 4, "invalid body"},
      {"duplicate before range", kValid + "friction 0\nrestitution 1.5\n", 5, "duplicate 'restitution'"},
      {"restitution above 1", "body 1 1 0 0 0 0\nrestitution 1.5\n", 2, "restitution must be in [0, 1], got 1.5"},
      {"negative restitution", "restitution -0.1\n", 1, "restitution must be in [0, 1]"},
      {"negative friction", kValid + "friction -0.2\n", 4, "friction must be >= 0, got -0.2"},
      {"duplicate restitution", kValid + "restitution 0.5\n", 4, "duplicate 'restitution' (first given on line 3)"},
      {"duplicate friction", kValid + "friction 0.1\n\nfriction 0.1\n", 6,
       "duplicate 'friction' (first given on line 4)"},
      {"one body", "body 1 1 0 0 0 0\nrestitution 0.5\n# end\n", 3, "at least 2 bodies, found 1"},
      {"no restitution", "body 1 1 0 0 0 0\nbody 1 1 3 0 0 0\n", 2, "missing 'restitution <e>'"},
  };
  for (const Rejection& c : cases)
  {
    const std::string where = std::string(kSource) + ":" + std::to_string(c.line) + ": ";
    try
    {
      parse(c.text);
      ADD_FAILURE() << c.what << ": accepted";
    }
    catch (const std::runtime_error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(where, 0), 0u) << c.what << ": " << message;
      EXPECT_NE(message.find(c.fragment), std::string::npos) << c.what << ": " << message;
    }
  }
}

TEST(LoadScenario, EveryShippedScenarioLoads)
{
  // Tests run from the repository root.
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator("config/scenarios"))
  {
    if (entry.path().extension() != ".collision")
    {
      continue;
    }
    ++count;
    SCOPED_TRACE(entry.path().string());
    Scenario s;
    ASSERT_NO_THROW(s = load_scenario(entry.path().string()));
    EXPECT_GE(s.bodies.size(), 2u);
    EXPECT_GE(s.restitution, 0.0);
    EXPECT_LE(s.restitution, 1.0);
    EXPECT_GE(s.friction, 0.0);
  }
  EXPECT_GE(count, 4);
}

TEST(LoadScenario, MissingFileNamesThePath)
{
  try
  {
    load_scenario("config/scenarios/does_not_exist.collision");
    FAIL() << "loaded a missing file";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("does_not_exist.collision"), std::string::npos);
  }
}

// ----------------------------------------------------------------- report

/// The three numbers (before, after, change) on the report row starting with `label`.
std::vector<double> row(const std::string& report, const std::string& label)
{
  std::istringstream lines(report);
  std::string line;
  while (std::getline(lines, line))
  {
    if (line.rfind(label, 0) == 0)
    {
      std::istringstream numbers(line.substr(label.size()));
      std::vector<double> values(3);
      numbers >> values[0] >> values[1] >> values[2];
      EXPECT_TRUE(numbers) << line;
      return values;
    }
  }
  ADD_FAILURE() << "no row " << label;
  return {0, 0, 0};
}

double total_energy(const std::vector<Body>& bodies)
{
  double sum = 0.0;
  for (const Body& b : bodies)
  {
    sum += b.kinetic_energy();
  }
  return sum;
}

TEST(WriteReport, ShowsContactsSolverAndTotalsBeforeAndAfter)
{
  const std::vector<Body> before{Body(1.0, 0.5, {0, 0}, {1, 0}), Body(2.0, 0.5, {0.9, 0.2}, {-1, 0.5}, 0.3)};
  std::vector<Body> after = before;
  after[0].set_velocity({-0.5, 0.25});
  after[1].set_velocity({-0.25, 0.375});
  Contact contact;
  contact.a = 0;
  contact.b = 1;
  contact.normal = {1, 0};
  contact.point = {0.45, 0.1};
  contact.penetration = 0.125;
  SolveReport report;
  report.iterations = 7;
  report.max_residual = 1e-13;
  report.converged = true;

  std::ostringstream out;
  write_report(out, before, after, {contact}, report);
  const std::string text = out.str();
  EXPECT_NE(text.find("contacts: 1"), std::string::npos) << text;
  EXPECT_NE(text.find("0-1"), std::string::npos);
  EXPECT_NE(text.find("(0.45, 0.1)"), std::string::npos);
  EXPECT_NE(text.find("depth 0.125"), std::string::npos);
  EXPECT_NE(text.find("7 iterations"), std::string::npos);
  EXPECT_NE(text.find("converged yes"), std::string::npos);

  const std::vector<double> energy = row(text, "kinetic energy (J)");
  EXPECT_NEAR(energy[0], total_energy(before), 1e-9);
  EXPECT_NEAR(energy[1], total_energy(after), 1e-9);
  EXPECT_NEAR(energy[2], total_energy(after) - total_energy(before), 1e-9);
  const std::vector<double> px = row(text, "momentum x (kg m/s)");
  EXPECT_NEAR(px[0], 1.0 - 2.0, 1e-12);
  EXPECT_NEAR(px[1], -0.5 - 0.5, 1e-12);
  const std::vector<double> l = row(text, "angular momentum (kg m^2/s)");
  EXPECT_NEAR(l[0], before[0].angular_momentum() + before[1].angular_momentum(), 1e-9);
  EXPECT_NEAR(l[1], after[0].angular_momentum() + after[1].angular_momentum(), 1e-9);
  EXPECT_EQ(text.find("energy rose"), std::string::npos);  // it fell here
}

TEST(WriteReport, FlagsAnEnergyRise)
{
  const std::vector<Body> before{Body(1.0, 0.5, {0, 0}, {1, 0}), Body(1.0, 0.5, {3, 0}, {0, 0})};
  std::vector<Body> after = before;
  after[1].set_velocity({0.5, 0});
  std::ostringstream out;
  write_report(out, before, after, {}, SolveReport{});
  EXPECT_NE(out.str().find("energy rose"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("contacts: 0"), std::string::npos);
}

}  // namespace
}  // namespace collision2d
