// Narrow phase: manifolds checked against geometry worked out by hand (disks,
// disks on polygon faces and corners, box on box), touch tolerances, portable_hypot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "collision2d/collide.h"

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

}  // namespace
}  // namespace collision2d
