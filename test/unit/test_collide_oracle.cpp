// Narrow phase: random pairs checked against an independent overlap/distance
// oracle (segment intersection and containment, no separating axes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "collision2d/collide.h"
#include "random_scene.h"

namespace collision2d
{
namespace
{
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
