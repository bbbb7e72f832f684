// Extreme geometry: sliver polygons of aspect 1000, 64-gons,
// nearly parallel faces, exact touching, deep overlap (a centre inside the
// other body) and coincident centres (a clear error, never NaN).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/collide.h"
#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "extremes_support.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
constexpr double kPi = 3.141592653589793;
constexpr double kGeometryTol = 1e-12;  // m: closed-form depths of exact inputs
constexpr double kMomentumTol = 1e-12;  // relative to the momentum scale
constexpr double kAspect = 1000.0;

std::vector<Vec2> regular_polygon(int n, double circumradius)
{
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * kPi * i / n;
    v.push_back({circumradius * std::cos(a), circumradius * std::sin(a)});
  }
  return v;
}

Manifold must_collide(const Body& a, const Body& b, double tolerance = 0.0)
{
  Manifold m;
  EXPECT_TRUE(collide(a, b, m, tolerance));
  EXPECT_NEAR(length(m.normal), 1.0, 1e-14);
  return m;
}

/// Solves the pair (e = 0) and checks the result is finite, conserves momentum
/// and leaves no contact approaching.
void check_solve(std::vector<Body> bodies, const char* what)
{
  const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  ASSERT_FALSE(contacts.empty()) << what;
  const Vec2 p = test::total_momentum(bodies);
  double scale = 0.0;
  for (const Body& b : bodies)
  {
    scale += length(b.momentum());
  }
  const ContactSolver solver(0.0, 0.0, 1000, 1e-12);
  solver.solve(bodies, contacts);
  ASSERT_TRUE(test::all_finite(bodies)) << what;
  EXPECT_LE(length(test::total_momentum(bodies) - p), kMomentumTol * scale) << what;
  for (const Contact& c : contacts)
  {
    EXPECT_GE(test::normal_speed(bodies, c), -1e-9) << what;
  }
  solver.correct_positions(bodies, contacts);
  ASSERT_TRUE(test::all_finite(bodies)) << what;
}

TEST(ExtremesGeometry, SliverPolygonsCollideAndSolve)
{
  const std::vector<Vec2> sliver = scenes::box_outline(1.0, 1.0 / kAspect);
  // Crossing at right angles: overlap is the thin square where they cross.
  const Body a(1.0, sliver, {0.0, 0.0}, {0.0, 1.0});
  const Body b(1.0, sliver, {0.0, 0.0004}, {0.0, -1.0}, kPi / 2.0);
  // Least overlap over the four axes: along y, b reaches 0.5004 above a's
  // centre and a's bottom is at -0.0005, so b must rise by 0.5001 m.
  const Manifold m = must_collide(a, b);
  for (int k = 0; k < m.count; ++k)
  {
    EXPECT_NEAR(m.points[k].penetration, 0.5001, kGeometryTol);
  }
  check_solve({a, b}, "crossing slivers");
  // End to end along their length, overlapping by a tenth of the thickness.
  const Body c(1.0, sliver, {1.0 - 1e-4, 0.0}, {-1.0, 0.0});
  const Manifold end = must_collide(a, c);
  EXPECT_NEAR(end.normal.x, 1.0, 1e-12);
  EXPECT_NEAR(end.points[0].penetration, 1e-4, kGeometryTol);
  check_solve({a, c}, "end-to-end slivers");
}

/// Centre height of a 1 m x 1 mm sliver dropped 1 cm onto rough ground after
/// `frames` frames, and how much it still moved over the last 60 frames.
struct SliverRest
{
  double height = 0.0;
  double still_moving = 0.0;
};

SliverRest drop_sliver(int substeps, double slop, long frames)
{
  Scene scene;
  scenes::add_ground(scene, scenes::GroundParams{});
  const double thickness = 1.0 / kAspect;
  scene.bodies.push_back(SceneBody{scenes::make_box(1.0, 1.0, thickness, {0.0, 0.5 * thickness + 0.01}),
                                   scenes::rough_material(), "sliver"});
  scene.settings.substeps = substeps;
  scene.settings.slop = slop;
  World world = make_world(scene);
  constexpr long kStillFrames = 60;
  double before = 0.0;
  for (long f = 0; f < frames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    EXPECT_LE(std::abs(world.body(1).theta()), 1e-9);
    if (f == frames - kStillFrames)
    {
      before = world.body(1).position().y;
    }
  }
  return {world.body(1).position().y, std::abs(world.body(1).position().y - before)};
}

// The world's resting depth is about slop + g h^2 (1 + m r^2 / I) / 4 per
// two-point contact (the Fx2D correction shares each point's effective
// mass with rotation), an absolute length: about 1.5 mm with the defaults
// (slop 1 mm, 4 substeps). A sliver 1 mm thick therefore comes to rest fully
// embedded in its support (stable, not falling through); with the slop scaled
// to its thickness and 16 substeps it rests on top. Thin bodies need slop and
// substeps chosen for their thickness.
TEST(ExtremesGeometry, SliverRestsOnTheGround)
{
  const double thickness = 1.0 / kAspect;
  const long frames = test::sized(300, 120, "sliver frames");
  constexpr double kStill = 1e-6;  // m over the last second: at rest
  const SliverRest defaults = drop_sliver(4, WorldSettings().slop, frames);
  const double floor = -2.0 * thickness;  // m: embedded, but stopped
  EXPECT_GE(defaults.height, floor);
  EXPECT_LE(defaults.still_moving, kStill);
  test::print_figure("sliver (aspect 1000), default settings: centre height (m)", defaults.height, floor);
  test::print_figure("  ... motion over its last second (m)", defaults.still_moving, kStill);

  const SliverRest tuned = drop_sliver(16, thickness / 100.0, frames);
  const double on_top = 0.4 * thickness;  // m: sunk by at most a tenth of its thickness
  EXPECT_GE(tuned.height, on_top);
  EXPECT_LE(tuned.still_moving, kStill);
  test::print_figure("sliver, slop = thickness/100, 16 substeps: centre height (m)", tuned.height, on_top);
}

TEST(ExtremesGeometry, SixtyFourGon)
{
  constexpr int kSides = 64;
  const double apothem = std::cos(kPi / kSides);
  const Body polygon(2.0, regular_polygon(kSides, 1.0), {0.0, 0.0}, {0.5, 0.0});
  // Inertia of a regular n-gon: m R^2 (1 + 2 cos^2(pi/n)) / 6.
  EXPECT_NEAR(polygon.inertia(), 2.0 * (1.0 + 2.0 * apothem * apothem) / 6.0, 1e-12);
  // A disk against the middle of face 0 (normal at angle pi/64).
  const Vec2 face_normal{std::cos(kPi / kSides), std::sin(kPi / kSides)};
  const Body disk(1.0, 0.25, (apothem + 0.2) * face_normal, {-0.5, 0.0});
  const Manifold m = must_collide(polygon, disk);
  EXPECT_NEAR(m.points[0].penetration, 0.05, kGeometryTol);
  EXPECT_NEAR(m.normal.x, face_normal.x, 1e-12);
  EXPECT_NEAR(m.normal.y, face_normal.y, 1e-12);
  // Two 64-gons: the normal lies within one face angle of the line of centres.
  const Body other(1.0, regular_polygon(kSides, 1.0), {1.95, 0.3}, {-0.5, 0.0}, 0.01);
  const Manifold pp = must_collide(polygon, other);
  const Vec2 centres = other.position() - polygon.position();
  const double angle = std::acos(std::clamp(dot(pp.normal, centres / length(centres)), -1.0, 1.0));
  EXPECT_LE(angle, 2.0 * kPi / kSides);
  check_solve({polygon, disk}, "64-gon and disk");
  check_solve({polygon, other}, "two 64-gons");
}

TEST(ExtremesGeometry, NearlyParallelFaces)
{
  const double overlap = 0.01;
  for (double tilt : {1e-12, 1e-9, 1e-6, 1e-3})
  {
    const Body lower = scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.0});
    const Body upper = scenes::make_box(1.0, 1.0, 1.0, {0.0, 1.0 - overlap}, tilt, {0.0, -1.0});
    const Manifold m = must_collide(lower, upper);
    EXPECT_EQ(m.count, 2) << "tilt " << tilt;
    EXPECT_LE(std::abs(m.normal.x), 2.0 * tilt) << "tilt " << tilt;
    // Each corner sits +-half a width times the tilt from the flat overlap.
    for (int k = 0; k < m.count; ++k)
    {
      EXPECT_NEAR(m.points[k].penetration, overlap, 0.5 * std::sin(tilt) + 0.5 * tilt * tilt + 1e-12)
          << "tilt " << tilt;
    }
    check_solve({lower, upper}, "nearly parallel faces");
  }
  // A box tilted by 1e-6 settling on the ground does not tilt further.
  Scene scene;
  scenes::add_ground(scene, scenes::GroundParams{});
  const double tilt = 1e-6;
  scene.bodies.push_back(
      SceneBody{scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.51}, tilt), scenes::rough_material(), "tilted"});
  World world = make_world(scene);
  world.step(static_cast<int>(test::sized(300, 60, "tilted box frames")));
  ASSERT_TRUE(test::all_finite(world));
  EXPECT_LE(std::abs(world.body(1).theta()), tilt);
  test::print_figure("box tilted 1e-6 rad on ground: tilt after settling (rad)", std::abs(world.body(1).theta()),
                     tilt);
}

TEST(ExtremesGeometry, ExactlyTouchingIsNotAContact)
{
  // Radii and positions exact in binary: the gap is exactly zero.
  const Body d1(1.0, 0.5, {0.0, 0.0}, {1.0, 0.0});
  const Body d2(1.0, 0.5, {1.0, 0.0}, {-1.0, 0.0});
  const Body b1 = scenes::make_box(1.0, 1.0, 1.0, {0.0, 2.0});
  const Body b2 = scenes::make_box(1.0, 1.0, 1.0, {1.0, 2.0});
  const Body d3(1.0, 0.5, {0.0, 3.0}, {});  // touches b1's top face
  Manifold m;
  EXPECT_FALSE(collide(d1, d2, m));
  EXPECT_FALSE(collide(b1, b2, m));
  EXPECT_FALSE(collide(b1, d3, m));
  EXPECT_TRUE(ContactSolver::detect_contacts({d1, d2}).empty());
  // With a touch tolerance they are contacts of zero depth.
  for (const auto& pair : {std::make_pair(d1, d2), std::make_pair(b1, b2), std::make_pair(b1, d3)})
  {
    const Manifold t = must_collide(pair.first, pair.second, 1e-9);
    for (int k = 0; k < t.count; ++k)
    {
      EXPECT_EQ(t.points[k].penetration, 0.0);
    }
  }
  // step() takes the impact of a touching, approaching pair (e = 1 swaps).
  std::vector<Body> bodies = {d1, d2};
  const SolveReport report = ContactSolver(1.0, 0.0).step(bodies);
  EXPECT_EQ(report.time_of_impact, 0.0);
  EXPECT_NEAR(bodies[0].velocity().x, -1.0, 1e-12);
  EXPECT_NEAR(bodies[1].velocity().x, 1.0, 1e-12);
}

TEST(ExtremesGeometry, DeepOverlapWithTheCentreInside)
{
  const Body box = scenes::make_box(4.0, 2.0, 2.0, {0.0, 0.0});
  // Disk centre inside the box, 0.4 m from the face x = 1.
  const Body disk(1.0, 0.5, {0.6, 0.1}, {-1.0, 0.0});
  const Manifold m = must_collide(box, disk);
  EXPECT_NEAR(m.points[0].penetration, 0.9, kGeometryTol);
  EXPECT_NEAR(m.normal.x, 1.0, 1e-15);
  // Small box whose centre is inside the big one, nearest face x = 1.
  const Body small = scenes::make_box(1.0, 0.5, 0.5, {0.7, 0.0}, 0.0, {-1.0, 0.0});
  const Manifold mb = must_collide(box, small);
  EXPECT_NEAR(mb.normal.x, 1.0, 1e-15);
  for (int k = 0; k < mb.count; ++k)
  {
    EXPECT_NEAR(mb.points[k].penetration, 0.55, kGeometryTol);
  }
  // Disk centre inside another disk, off-centre.
  const Body big(3.0, 1.0, {0.0, 0.0}, {});
  const Body inner(1.0, 0.3, {0.1, 0.2}, {-1.0, 0.0});
  EXPECT_NEAR(must_collide(big, inner).points[0].penetration, 1.3 - std::hypot(0.1, 0.2), kGeometryTol);
  check_solve({box, disk}, "disk centre inside box");
  check_solve({box, small}, "box centre inside box");
  check_solve({big, inner}, "disk centre inside disk");
  // Repeated correction drives the deep overlap out without NaN.
  std::vector<Body> bodies = {box, disk};
  const ContactSolver solver(0.0, 0.0, 64, 1e-12, 0.5);
  for (int k = 0; k < 60 && !ContactSolver::detect_contacts(bodies).empty(); ++k)
  {
    solver.correct_positions(bodies, ContactSolver::detect_contacts(bodies));
  }
  ASSERT_TRUE(test::all_finite(bodies));
  std::vector<Contact> left = ContactSolver::detect_contacts(bodies);
  EXPECT_LE(left.empty() ? 0.0 : left[0].penetration, 2.0 * solver.slop());
}

TEST(ExtremesGeometry, CoincidentCentresGiveAClearErrorNotNaN)
{
  const Body d1(1.0, 0.5, {0.25, -1.0}, {1.0, 0.0});
  const Body d2(2.0, 0.3, {0.25, -1.0}, {0.0, 0.0});
  Manifold m;
  try
  {
    collide(d1, d2, m);
    ADD_FAILURE() << "coincident disks must throw";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("coincident"), std::string::npos) << e.what();
  }
  std::vector<Body> bodies = {d1, d2};
  EXPECT_THROW(ContactSolver::detect_contacts(bodies), std::runtime_error);
  EXPECT_THROW(ContactSolver(0.5, 0.0).resolve(bodies), std::runtime_error);
  EXPECT_THROW(ContactSolver(0.5, 0.0).step(bodies), std::runtime_error);
  EXPECT_TRUE(test::all_finite(bodies)) << "a throwing call must not leave NaN behind";
  // Polygon pairs have a normal even with coincident centres (a face of
  // least penetration), so they solve.
  const Body b1 = scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.0});
  const Body b2 = scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.0}, 0.0, {0.0, 1.0});
  const Body d3(1.0, 0.25, {0.0, 0.0}, {});
  EXPECT_NEAR(must_collide(b1, b2).points[0].penetration, 1.0, kGeometryTol);
  EXPECT_NEAR(must_collide(b1, d3).points[0].penetration, 0.75, kGeometryTol);
  check_solve({b1, b2}, "coincident boxes");
  check_solve({b1, d3}, "disk at a box centre");
}

TEST(ExtremesGeometry, TheWorldPushesCoincidentDisksApart)
{
  // The world separates coincident disks along a fixed direction instead of
  // throwing: at rest, without gravity, they must end touching, their centre
  // of mass where it was.
  constexpr double kRadiusA = 0.5;  // m
  constexpr double kRadiusB = 0.3;  // m
  constexpr double kMassA = 1.0;    // kg
  constexpr double kMassB = 2.0;    // kg
  const Vec2 centre{0.25, -1.0};
  for (const bool soft_step : {false, true})
  {
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};
    settings.soft_step = soft_step;
    World world(settings);
    const BodyId a = world.add_body(Body(kMassA, kRadiusA, centre, {}));
    const BodyId b = world.add_body(Body(kMassB, kRadiusB, centre, {}));
    world.step(60);
    ASSERT_TRUE(test::all_finite(world));
    const Vec2 pa = world.body(a).position();
    const Vec2 pb = world.body(b).position();
    const double gap = length(pb - pa) - (kRadiusA + kRadiusB);
    EXPECT_GT(gap, -2.0 * settings.slop) << (soft_step ? "soft step" : "Fx2D") << ": still overlapping by " << -gap << " m";
    const Vec2 mass_centre = (pa * kMassA + pb * kMassB) / (kMassA + kMassB);
    EXPECT_NEAR(mass_centre.x, centre.x, 1e-9);
    EXPECT_NEAR(mass_centre.y, centre.y, 1e-9);
  }
}

}  // namespace
}  // namespace collision2d
