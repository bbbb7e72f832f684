// Narrow phase: manifolds checked against geometry worked out by hand, and
// random pairs checked against an independent overlap/distance oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "collision2d/collide.h"
#include "random_scene.h"

namespace collision2d
{
namespace
{
constexpr double kPi = 3.141592653589793;
constexpr double kTight = 1e-12;

Body disk(double r, Vec2 p)
{
  return Body(1.0, r, p, {0.0, 0.0});
}

Body box(double w, double h, Vec2 p, double theta = 0.0)
{
  const double x = 0.5 * w;
  const double y = 0.5 * h;
  return Body(1.0, {{-x, -y}, {x, -y}, {x, y}, {-x, y}}, p, {0.0, 0.0}, theta);
}

void expect_near(Vec2 got, Vec2 want, double tol, const char* what)
{
  EXPECT_NEAR(got.x, want.x, tol) << what;
  EXPECT_NEAR(got.y, want.y, tol) << what;
}

Manifold must_collide(const Body& a, const Body& b, double touch_tolerance = 0.0)
{
  Manifold m;
  EXPECT_TRUE(collide(a, b, m, touch_tolerance));
  return m;
}

TEST(Collide, DisksMeetAlongTheLineOfCentres)
{
  // Centres 1.5 apart along (0.8, 0.6); radii 1 and 0.6 overlap by 0.1.
  const Body a = disk(1.0, {0.0, 0.0});
  const Body b = disk(0.6, {1.2, 0.9});
  const Manifold m = must_collide(a, b);
  ASSERT_EQ(m.count, 1);
  expect_near(m.normal, {0.8, 0.6}, kTight, "normal");
  EXPECT_NEAR(m.points[0].penetration, 0.1, kTight);
  // Halfway through the overlap: equally deep inside both disks.
  const Vec2 p = m.points[0].point;
  EXPECT_NEAR(a.radius() - length(p - a.position()), b.radius() - length(p - b.position()), kTight);

  const Manifold swapped = must_collide(b, a);
  expect_near(swapped.normal, {-0.8, -0.6}, kTight, "swapped normal");
}

TEST(Collide, CoincidentDiskCentresThrow)
{
  Manifold m;
  EXPECT_THROW(collide(disk(1.0, {2.0, 3.0}), disk(0.5, {2.0, 3.0}), m), std::runtime_error);
}

TEST(PortableHypot, AgreesWithStdHypotToAnUlpAtEveryScale)
{
  // Tiny and huge components take the scaled paths: no false zero, no overflow.
  const double scales[] = {1e-300, 1e-160, 1e-20, 1.0, 1e20, 1e160, 1e300};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double scale : scales)
  {
    for (int i = 0; i < 1000; ++i)
    {
      const double x = scale * unit(rng);
      const double y = scale * unit(rng);
      const double expected = std::hypot(x, y);
      EXPECT_NEAR(portable_hypot(x, y), expected, 2.0 * std::numeric_limits<double>::epsilon() * expected)
          << x << ", " << y;
    }
  }
  EXPECT_EQ(portable_hypot(0.0, 0.0), 0.0);
  EXPECT_GT(portable_hypot(1e-320, 0.0), 0.0);
  EXPECT_EQ(portable_hypot(-3.0, 4.0), 5.0);
  EXPECT_TRUE(std::isinf(portable_hypot(std::numeric_limits<double>::infinity(), std::nan(""))));
  EXPECT_TRUE(std::isnan(portable_hypot(1.0, std::nan(""))));
}

TEST(Collide, ExactTouchingIsAContactOnlyWithATolerance)
{
  Manifold m;
  // Disks: 1 + 0.5 = 1.5 exactly.
  EXPECT_FALSE(collide(disk(1.0, {0.0, 0.0}), disk(0.5, {1.5, 0.0}), m));
  ASSERT_TRUE(collide(disk(1.0, {0.0, 0.0}), disk(0.5, {1.5, 0.0}), m, 1e-9));
  EXPECT_EQ(m.points[0].penetration, 0.0);
  // Disk on a box face.
  EXPECT_FALSE(collide(box(2.0, 2.0, {0.0, 0.0}), disk(0.5, {0.25, 1.5}), m));
  ASSERT_TRUE(collide(box(2.0, 2.0, {0.0, 0.0}), disk(0.5, {0.25, 1.5}), m, 1e-9));
  EXPECT_EQ(m.points[0].penetration, 0.0);
  // Box resting exactly on a box: a two-point manifold of zero depth.
  EXPECT_FALSE(collide(box(2.0, 2.0, {0.0, 0.0}), box(2.0, 2.0, {0.5, 2.0}), m));
  ASSERT_TRUE(collide(box(2.0, 2.0, {0.0, 0.0}), box(2.0, 2.0, {0.5, 2.0}), m, 1e-9));
  EXPECT_EQ(m.count, 2);
  EXPECT_EQ(m.points[0].penetration, 0.0);
}

TEST(Collide, ToleranceAcceptsGapsUpToItsValueOnly)
{
  const double gap = 1e-3;
  Manifold m;
  const Body a = disk(1.0, {0.0, 0.0});
  const Body b = disk(1.0, {2.0 + gap, 0.0});
  EXPECT_FALSE(collide(a, b, m, 0.5 * gap));
  EXPECT_TRUE(collide(a, b, m, 2.0 * gap));
  EXPECT_EQ(m.points[0].penetration, 0.0);
}

TEST(Collide, DiskOnARotatedPolygonFace)
{
  // In the box frame the disk sits over the top face, 0.1 deep; the whole
  // picture is then turned by 30 degrees and shifted.
  const double theta = kPi / 6.0;
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const Vec2 origin{5.0, -2.0};
  const Body poly = box(2.0, 2.0, origin, theta);
  const Body ball = disk(0.5, origin + rotate({0.3, 1.4}, c, s));
  const Manifold m = must_collide(poly, ball);
  ASSERT_EQ(m.count, 1);
  expect_near(m.normal, rotate({0.0, 1.0}, c, s), kTight, "normal");
  EXPECT_NEAR(m.points[0].penetration, 0.1, kTight);
  expect_near(m.points[0].point, origin + rotate({0.3, 0.95}, c, s), kTight, "point halfway through the overlap");

  // Disk first: same depth, normal from the disk toward the polygon.
  const Manifold flipped = must_collide(ball, poly);
  expect_near(flipped.normal, rotate({0.0, -1.0}, c, s), kTight, "flipped normal");
  EXPECT_NEAR(flipped.points[0].penetration, 0.1, kTight);
}

TEST(Collide, DiskInAVertexRegionMeetsTheCorner)
{
  // Centre 0.4 from the corner (1, 1) along (0.6, 0.8): 0.1 deep.
  const Body poly = box(2.0, 2.0, {0.0, 0.0});
  const Manifold m = must_collide(poly, disk(0.5, {1.24, 1.32}));
  ASSERT_EQ(m.count, 1);
  expect_near(m.normal, {0.6, 0.8}, kTight, "normal");
  EXPECT_NEAR(m.points[0].penetration, 0.1, kTight);

  // Within 0.5 of both face planes, but 0.566 from the corner: no contact.
  Manifold miss;
  EXPECT_FALSE(collide(poly, disk(0.5, {1.4, 1.4}), miss));
}

TEST(Collide, DiskCentreInsideUsesTheFaceOfLeastPenetration)
{
  // Centre 0.3 below the top face and deeper from every other face.
  const Manifold m = must_collide(box(2.0, 2.0, {0.0, 0.0}), disk(0.2, {0.1, 0.7}));
  ASSERT_EQ(m.count, 1);
  expect_near(m.normal, {0.0, 1.0}, kTight, "normal");
  EXPECT_NEAR(m.points[0].penetration, 0.5, kTight);
}

TEST(Collide, BoxOnBoxFaceToFaceGivesTwoPoints)
{
  // Unit box 0.1 into the top face of a 2x2 box, fully over it.
  const Manifold m = must_collide(box(2.0, 2.0, {0.0, 0.0}), box(1.0, 1.0, {0.3, 1.4}));
  ASSERT_EQ(m.count, 2);
  expect_near(m.normal, {0.0, 1.0}, kTight, "normal");
  const double xs[2] = {m.points[0].point.x, m.points[1].point.x};
  EXPECT_NEAR(std::min(xs[0], xs[1]), -0.2, kTight);
  EXPECT_NEAR(std::max(xs[0], xs[1]), 0.8, kTight);
  for (const ManifoldPoint& p : m.points)
  {
    EXPECT_NEAR(p.penetration, 0.1, kTight);
  }
  EXPECT_NE(m.points[0].feature, m.points[1].feature);
}

TEST(Collide, TiltedBoxPointsHaveTheirOwnDepths)
{
  const Body lower = box(2.0, 2.0, {0.0, 0.0});
  const Body upper = box(1.0, 1.0, {0.2, 1.45}, 0.05);
  const Manifold m = must_collide(lower, upper);
  ASSERT_EQ(m.count, 2);
  expect_near(m.normal, {0.0, 1.0}, kTight, "normal");
  // Each bottom corner of the tilted box is below y = 1 by its own depth and
  // its point lies halfway between the corner and the face.
  for (std::size_t k = 0; k < 2; ++k)
  {
    const Vec2 corner = upper.world_vertex(k);
    const double depth = 1.0 - corner.y;
    const auto same_x = [&](const ManifoldPoint& p) { return std::abs(p.point.x - corner.x) < kTight; };
    const ManifoldPoint* p = same_x(m.points[0]) ? &m.points[0] : same_x(m.points[1]) ? &m.points[1] : nullptr;
    ASSERT_NE(p, nullptr) << "no point at corner " << k;
    EXPECT_NEAR(p->penetration, depth, kTight);
    EXPECT_NEAR(p->point.y, 1.0 - 0.5 * depth, kTight);
  }
  EXPECT_GT(std::abs(m.points[0].penetration - m.points[1].penetration), 0.01);
}

TEST(Collide, OverhangingBoxIsClippedToTheReferenceFace)
{
  // The upper box spans x in [0.7, 1.7]; the lower box's top face ends at 1.
  const Manifold m = must_collide(box(2.0, 2.0, {0.0, 0.0}), box(1.0, 1.0, {1.2, 1.4}));
  ASSERT_EQ(m.count, 2);
  expect_near(m.normal, {0.0, 1.0}, kTight, "normal");
  const double xs[2] = {m.points[0].point.x, m.points[1].point.x};
  EXPECT_NEAR(std::min(xs[0], xs[1]), 0.7, kTight);
  EXPECT_NEAR(std::max(xs[0], xs[1]), 1.0, kTight);
}

TEST(Collide, RotatedBoxCornerIntoAFaceGivesOnePoint)
{
  // A unit box turned 45 degrees, its lowest corner 0.05 below y = 1.
  const double half_diagonal = 0.5 * std::sqrt(2.0);
  const Body flat = box(2.0, 2.0, {0.0, 0.0});
  const Body diamond = box(1.0, 1.0, {0.1, 1.0 + half_diagonal - 0.05}, kPi / 4.0);
  for (bool flat_first : {true, false})
  {
    const Manifold m = flat_first ? must_collide(flat, diamond) : must_collide(diamond, flat);
    ASSERT_EQ(m.count, 1);
    expect_near(m.normal, flat_first ? Vec2{0.0, 1.0} : Vec2{0.0, -1.0}, kTight, "normal");
    EXPECT_NEAR(m.points[0].penetration, 0.05, kTight);
    expect_near(m.points[0].point, {0.1, 0.975}, kTight, "point");
  }
}

TEST(Collide, FeatureIdsPersistUnderSmallMotion)
{
  const Body lower = box(2.0, 2.0, {0.0, 0.0});
  const Manifold before = must_collide(lower, box(1.0, 1.0, {0.3, 1.4}, 0.01));
  const Manifold after = must_collide(lower, box(1.0, 1.0, {0.31, 1.41}, 0.012));
  ASSERT_EQ(before.count, 2);
  ASSERT_EQ(after.count, 2);
  EXPECT_EQ(before.points[0].feature, after.points[0].feature);
  EXPECT_EQ(before.points[1].feature, after.points[1].feature);
  // A different face in contact gives different ids.
  const Manifold side = must_collide(lower, box(1.0, 1.0, {1.4, 0.3}, 0.01));
  EXPECT_NE(side.points[0].feature, before.points[0].feature);
  EXPECT_NE(side.points[0].feature, before.points[1].feature);
}

// ---------------------------------------------------------------------------
// Independent oracle for random pairs: overlap from segment intersection and
// containment, distances from point-segment distances (no separating axes).

struct Outline
{
  std::vector<Vec2> v;
};

Outline world_outline(const Body& b)
{
  Outline o;
  for (std::size_t i = 0; i < b.vertex_count(); ++i)
  {
    o.v.push_back(b.world_vertex(i));
  }
  return o;
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b)
{
  const double t = std::clamp(dot(p - a, b - a) / length_sq(b - a), 0.0, 1.0);
  return length(p - (a + t * (b - a)));
}

double distance_to_boundary(Vec2 p, const Outline& o)
{
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < o.v.size(); ++i)
  {
    d = std::min(d, point_segment_distance(p, o.v[i], o.v[(i + 1) % o.v.size()]));
  }
  return d;
}

bool inside(Vec2 p, const Outline& o)
{
  for (std::size_t i = 0; i < o.v.size(); ++i)
  {
    if (cross(o.v[(i + 1) % o.v.size()] - o.v[i], p - o.v[i]) <= 0.0)
    {
      return false;
    }
  }
  return true;
}

/// Signed distance between a disk and a polygon: negative is overlap depth.
double disk_polygon_gap(const Body& d, const Outline& o)
{
  const double boundary = distance_to_boundary(d.position(), o);
  return inside(d.position(), o) ? -(boundary + d.radius()) : boundary - d.radius();
}

/// Gap between two convex polygons, or -1 when they overlap (depth unknown).
double polygon_polygon_gap(const Outline& a, const Outline& b)
{
  double gap = std::numeric_limits<double>::infinity();
  for (const Vec2& p : a.v)
  {
    if (inside(p, b))
    {
      return -1.0;
    }
    gap = std::min(gap, distance_to_boundary(p, b));
  }
  for (const Vec2& p : b.v)
  {
    if (inside(p, a))
    {
      return -1.0;
    }
    gap = std::min(gap, distance_to_boundary(p, a));
  }
  // Convex outlines with no vertex inside the other overlap only if edges cross.
  for (std::size_t i = 0; i < a.v.size(); ++i)
  {
    const Vec2 p = a.v[i];
    const Vec2 q = a.v[(i + 1) % a.v.size()];
    for (std::size_t j = 0; j < b.v.size(); ++j)
    {
      const Vec2 r = b.v[j];
      const Vec2 s = b.v[(j + 1) % b.v.size()];
      if (cross(q - p, r - p) * cross(q - p, s - p) < 0.0 && cross(s - r, p - r) * cross(s - r, q - r) < 0.0)
      {
        return -1.0;
      }
    }
  }
  return gap;
}

/// Overlap of the two outlines' projections on n (how far b must move along n).
double projected_overlap(const Outline& a, const Outline& b, Vec2 n)
{
  double a_max = -std::numeric_limits<double>::infinity();
  double b_min = std::numeric_limits<double>::infinity();
  for (const Vec2& p : a.v)
  {
    a_max = std::max(a_max, dot(n, p));
  }
  for (const Vec2& p : b.v)
  {
    b_min = std::min(b_min, dot(n, p));
  }
  return a_max - b_min;
}

/// Separation below which a random pair is too close to touching to judge.
constexpr double kNearTouch = 1e-9;
constexpr int kRandomPairs = 20000;

TEST(Collide, RandomPairsAgreeWithAnIndependentOracle)
{
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int overlaps = 0;
  int two_point = 0;
  for (int trial = 0; trial < kRandomPairs; ++trial)
  {
    const std::vector<Body> pair = test::random_scene(rng(), 2, {1.5, 1.5});
    const Body& a = pair[0];
    const Body& b = pair[1];
    Manifold m;
    const bool hit = collide(a, b, m);
    if (hit)
    {
      ++overlaps;
      two_point += m.count == 2;
      EXPECT_NEAR(length(m.normal), 1.0, 1e-12);
      for (int k = 0; k < m.count; ++k)
      {
        EXPECT_GT(m.points[k].penetration, 0.0);
      }
    }
    const bool a_disk = a.shape() == Shape::Disk;
    const bool b_disk = b.shape() == Shape::Disk;
    if (a_disk && b_disk)
    {
      const double gap = length(b.position() - a.position()) - a.radius() - b.radius();
      if (std::abs(gap) < kNearTouch)
      {
        continue;
      }
      ASSERT_EQ(hit, gap < 0.0) << "trial " << trial;
      if (hit)
      {
        EXPECT_NEAR(m.points[0].penetration, -gap, 1e-12);
      }
    }
    else if (a_disk != b_disk)
    {
      const Body& d = a_disk ? a : b;
      const double gap = disk_polygon_gap(d, world_outline(a_disk ? b : a));
      if (std::abs(gap) < kNearTouch)
      {
        continue;
      }
      ASSERT_EQ(hit, gap < 0.0) << "trial " << trial;
      if (hit)
      {
        EXPECT_NEAR(m.points[0].penetration, -gap, 1e-9) << "trial " << trial;
      }
    }
    else
    {
      const Outline oa = world_outline(a);
      const Outline ob = world_outline(b);
      const double gap = polygon_polygon_gap(oa, ob);
      if (gap >= 0.0 && gap < kNearTouch)
      {
        continue;
      }
      ASSERT_EQ(hit, gap < 0.0) << "trial " << trial;
      if (!hit)
      {
        continue;
      }
      // The normal is a minimal-translation direction: moving b along it by
      // the overlap separates them, and no face normal needs (much) less.
      const double along_normal = projected_overlap(oa, ob, m.normal);
      double least = std::numeric_limits<double>::infinity();
      for (const Body* body : {&a, &b})
      {
        for (std::size_t i = 0; i < body->vertex_count(); ++i)
        {
          const Vec2 n = body->world_face_normal(i);
          least = std::min(least, projected_overlap(oa, ob, body == &a ? n : -n));
        }
      }
      // Near-ties may keep the first body's face (collide.cpp: 1e-3 of its
      // depth plus 2e-3 of the pair's size); allow exactly that much.
      EXPECT_LE(along_normal * (1.0 - 1e-3), least + 2e-3 * (a.radius() + b.radius()) + 1e-12) << "trial " << trial;
      for (int k = 0; k < m.count; ++k)
      {
        EXPECT_LE(m.points[k].penetration, along_normal + 1e-9) << "trial " << trial;
      }
    }
  }
  // The scene generator must actually exercise overlaps and manifolds.
  EXPECT_GT(overlaps, kRandomPairs / 10);
  EXPECT_GT(two_point, 10);
}

}  // namespace
}  // namespace collision2d
