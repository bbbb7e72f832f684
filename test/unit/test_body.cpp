// Body construction, mass properties from closed forms, validation and the
// kinematic accessors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/body.h"

namespace collision2d
{
namespace
{
constexpr double kPi = 3.141592653589793;
constexpr double kTight = 1e-12;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<Vec2> box_from_corner(double w, double h, Vec2 corner)
{
  return {corner, corner + Vec2{w, 0.0}, corner + Vec2{w, h}, corner + Vec2{0.0, h}};
}

/// Asserts that `make` throws std::invalid_argument whose message names `field`.
void expect_rejected(const std::function<void()>& make, const std::string& field)
{
  try
  {
    make();
    ADD_FAILURE() << "accepted invalid " << field;
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

/// First moment of area of an outline about the origin (shoelace form): zero
/// exactly when the origin is the area centroid.
Vec2 first_moment_of_area(const std::vector<Vec2>& v)
{
  Vec2 sum;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    const Vec2 p = v[i];
    const Vec2 q = v[(i + 1) % v.size()];
    sum += cross(p, q) * (p + q) / 6.0;
  }
  return sum;
}

TEST(Body, DiskHasHalfMRSquaredInertia)
{
  const double m = 3.0;
  const double r = 0.5;
  const Body disk(m, r, {1.0, 2.0}, {0.5, -1.0}, 4.0);
  EXPECT_EQ(disk.shape(), Shape::Disk);
  EXPECT_DOUBLE_EQ(disk.inertia(), 0.5 * m * r * r);
  EXPECT_DOUBLE_EQ(disk.inv_inertia(), 1.0 / (0.5 * m * r * r));
  EXPECT_DOUBLE_EQ(disk.inv_mass(), 1.0 / m);
  EXPECT_DOUBLE_EQ(disk.radius(), r);
  EXPECT_EQ(disk.vertex_count(), 0u);
}

TEST(Body, BoxInertiaIsMassTimesSumOfSquaresOverTwelve)
{
  const double m = 2.5;
  const double w = 3.0;
  const double h = 0.4;
  const Body box(m, box_from_corner(w, h, {0.0, 0.0}), {0.0, 0.0}, {0.0, 0.0});
  EXPECT_NEAR(box.inertia(), m * (w * w + h * h) / 12.0, kTight);
  EXPECT_NEAR(box.radius(), 0.5 * std::hypot(w, h), kTight);
}

TEST(Body, TriangleInertiaMatchesSideLengthFormula)
{
  // Polar moment of a uniform triangle about its centroid: m (a^2 + b^2 + c^2) / 36.
  const std::vector<Vec2> tri{{0.0, 0.0}, {4.0, 0.0}, {1.0, 3.0}};
  const double m = 7.0;
  const Body body(m, tri, {0.0, 0.0}, {0.0, 0.0});
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < 3; ++i)
  {
    sum_sq += length_sq(tri[(i + 1) % 3] - tri[i]);
  }
  EXPECT_NEAR(body.inertia(), m * sum_sq / 36.0, 1e-12 * m * sum_sq);
}

TEST(Body, PolygonInertiaIsNotTheDiskFormula)
{
  const Body box(1.0, box_from_corner(2.0, 2.0, {-1.0, -1.0}), {0.0, 0.0}, {0.0, 0.0});
  EXPECT_GT(std::abs(box.inertia() - 0.5 * box.mass() * box.radius() * box.radius()), 0.1);
}

TEST(Body, OffCentreVerticesAreRecentredOnTheAreaCentroid)
{
  // A trapezoid whose vertex mean differs from its area centroid.
  const std::vector<Vec2> outline{{10.0, 5.0}, {16.0, 5.0}, {12.0, 7.0}, {10.0, 7.0}};
  const Body body(1.0, outline, {0.0, 0.0}, {0.0, 0.0});
  const Vec2 moment = first_moment_of_area(body.local_vertices());
  EXPECT_NEAR(moment.x, 0.0, 1e-12);
  EXPECT_NEAR(moment.y, 0.0, 1e-12);
  Vec2 vertex_mean;
  for (const Vec2& v : body.local_vertices())
  {
    vertex_mean += v / 4.0;
  }
  EXPECT_GT(length(vertex_mean), 0.05) << "recentred on the vertex mean instead of the area centroid";
  // The shape itself is unchanged: edges keep their vectors.
  for (std::size_t i = 0; i < 4; ++i)
  {
    const Vec2 want = outline[(i + 1) % 4] - outline[i];
    const Vec2 got = body.local_vertices()[(i + 1) % 4] - body.local_vertices()[i];
    EXPECT_NEAR(length(want - got), 0.0, 1e-12);
  }
}

TEST(Body, RightTriangleCentroidIsAThirdOfTheLegs)
{
  const Body body(1.0, {{0.0, 0.0}, {3.0, 0.0}, {0.0, 3.0}}, {0.0, 0.0}, {0.0, 0.0});
  EXPECT_NEAR(body.local_vertices()[0].x, -1.0, kTight);
  EXPECT_NEAR(body.local_vertices()[0].y, -1.0, kTight);
  EXPECT_NEAR(body.radius(), std::hypot(2.0, 1.0), kTight);
}

TEST(Body, FaceNormalsAreOutwardUnitVectors)
{
  const Body box(1.0, box_from_corner(2.0, 1.0, {0.0, 0.0}), {0.0, 0.0}, {0.0, 0.0});
  const std::vector<Vec2> want{{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
  ASSERT_EQ(box.local_face_normals().size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(length(box.local_face_normals()[i] - want[i]), 0.0, kTight) << "face " << i;
  }
}

TEST(Body, CollinearAndRepeatedVerticesAreDropped)
{
  const std::vector<Vec2> outline{{-1.0, -1.0}, {0.0, -1.0}, {1.0, -1.0}, {1.0, -1.0},
                                  {1.0, 1.0},   {-1.0, 1.0}};
  const Body body(1.0, outline, {0.0, 0.0}, {0.0, 0.0});
  EXPECT_EQ(body.vertex_count(), 4u);
  EXPECT_NEAR(body.inertia(), (4.0 + 4.0) / 12.0, kTight);
}

TEST(Body, RejectsEveryInvalidInput)
{
  const std::vector<Vec2> box = box_from_corner(1.0, 1.0, {0.0, 0.0});
  const Vec2 zero{0.0, 0.0};
  for (double bad : {0.0, -1.0, kNaN, kInf})
  {
    expect_rejected([&] { Body(bad, 1.0, zero, zero); }, "mass");
    expect_rejected([&] { Body(bad, box, zero, zero); }, "mass");
  }
  for (double bad : {0.0, -0.5, kNaN, kInf})
  {
    expect_rejected([&] { Body(1.0, bad, zero, zero); }, "radius");
  }
  expect_rejected([&] { Body(1.0, 1.0, {kNaN, 0.0}, zero); }, "position");
  expect_rejected([&] { Body(1.0, 1.0, zero, {0.0, kInf}); }, "velocity");
  expect_rejected([&] { Body(1.0, 1.0, zero, zero, kNaN); }, "omega");
  expect_rejected([&] { Body(1.0, box, {kInf, 0.0}, zero); }, "position");
  expect_rejected([&] { Body(1.0, box, zero, {kNaN, 0.0}); }, "velocity");
  expect_rejected([&] { Body(1.0, box, zero, zero, kNaN); }, "theta");
  expect_rejected([&] { Body(1.0, box, zero, zero, 0.0, kInf); }, "omega");
  expect_rejected([&] { Body(1.0, {{0.0, 0.0}, {1.0, 0.0}, {0.0, kNaN}}, zero, zero); }, "vertices[2]");
}

TEST(Body, RejectsBadOutlines)
{
  const Vec2 zero{0.0, 0.0};
  // Too few vertices.
  expect_rejected([&] { Body(1.0, std::vector<Vec2>{{0.0, 0.0}, {1.0, 0.0}}, zero, zero); }, "vertices");
  // Clockwise.
  expect_rejected([&] { Body(1.0, {{0.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {1.0, 0.0}}, zero, zero); }, "area");
  // All on one line, and all the same point.
  expect_rejected([&] { Body(1.0, {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}}, zero, zero); }, "area");
  expect_rejected([&] { Body(1.0, {{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}}, zero, zero); }, "area");
  // Reflex vertex (an arrow head).
  expect_rejected([&] { Body(1.0, {{0.0, 0.0}, {2.0, 1.0}, {0.0, 2.0}, {1.0, 1.0}}, zero, zero); }, "convex");
  // Pentagram: every turn is left, but it winds twice.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k)
  {
    const double angle = 2.0 * kPi * (2 * k) / 5.0;
    star.push_back({std::cos(angle), std::sin(angle)});
  }
  expect_rejected([&] { Body(1.0, star, zero, zero); }, "convex");
  // A spike that doubles back on itself.
  expect_rejected([&] { Body(1.0, {{0.0, 0.0}, {2.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}, zero, zero); }, "convex");
}

TEST(Body, PoseAccessorsRotateTheOutline)
{
  Body box(1.0, box_from_corner(2.0, 2.0, {-1.0, -1.0}), {3.0, 4.0}, {0.0, 0.0});
  box.set_theta(0.5 * kPi);
  EXPECT_NEAR(box.cos_theta(), 0.0, kTight);
  EXPECT_NEAR(box.sin_theta(), 1.0, kTight);
  // Local (-1,-1) turned a quarter counter-clockwise is (1,-1).
  EXPECT_NEAR(length(box.world_vertex(0) - Vec2{4.0, 3.0}), 0.0, kTight);
  EXPECT_NEAR(length(box.world_face_normal(0) - Vec2{1.0, 0.0}), 0.0, kTight);
  box.set_theta(0.25 * kPi);
  const Aabb box_aabb = box.aabb();
  EXPECT_NEAR(box_aabb.hi.x - 3.0, std::sqrt(2.0), kTight);
  EXPECT_NEAR(4.0 - box_aabb.lo.y, std::sqrt(2.0), kTight);
  const Aabb disk_aabb = Body(1.0, 0.5, {1.0, -1.0}, {0.0, 0.0}).aabb();
  EXPECT_DOUBLE_EQ(disk_aabb.lo.x, 0.5);
  EXPECT_DOUBLE_EQ(disk_aabb.hi.y, -0.5);
}

TEST(Body, EnergyAndMomentaFollowTheirDefinitions)
{
  const double m = 2.0;
  const double r = 0.5;
  const Vec2 p{1.0, 2.0};
  const Vec2 v{3.0, -1.0};
  const double w = 4.0;
  const Body disk(m, r, p, v, w);
  const double inertia = 0.5 * m * r * r;
  EXPECT_DOUBLE_EQ(disk.kinetic_energy(), 0.5 * m * (9.0 + 1.0) + 0.5 * inertia * w * w);
  EXPECT_DOUBLE_EQ(disk.momentum().x, m * v.x);
  // I w + m (p x v) with p x v = 1 * (-1) - 2 * 3 = -7.
  EXPECT_DOUBLE_EQ(disk.angular_momentum(), inertia * w + m * -7.0);
  // Rim point straight above the centre moves at v + w x (0, r).
  const Vec2 rim = disk.velocity_at(p + Vec2{0.0, r});
  EXPECT_DOUBLE_EQ(rim.x, v.x - w * r);
  EXPECT_DOUBLE_EQ(rim.y, v.y);
}

TEST(Body, NonDynamicBodiesHaveZeroInverseMass)
{
  Body disk(1.0, 1.0, {0.0, 0.0}, {0.0, 0.0});
  disk.set_type(BodyType::Static);
  EXPECT_EQ(disk.inv_mass(), 0.0);
  EXPECT_EQ(disk.inv_inertia(), 0.0);
  EXPECT_DOUBLE_EQ(disk.mass(), 1.0);
}

}  // namespace
}  // namespace collision2d
