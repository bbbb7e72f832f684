// Exact time of impact against analytic roots, checked independently with a
// separating-axis gap, and ContactSolver::step at the impact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/time_of_impact.h"

namespace collision2d
{
namespace
{
constexpr double kPi = 3.141592653589793;
constexpr double kSqrt2 = 1.4142135623730951;
/// Roots are closed forms evaluated in double precision.
constexpr double kRootTol = 1e-12;
/// Gap (m) that still counts as touching for bodies of size ~1 after the
/// move to t*: round-off of p + t v, well inside the solver's touch tolerance.
constexpr double kTouchGap = 1e-9;

Body disk(double radius, Vec2 position, Vec2 velocity = {}, double mass = 1.0)
{
  return Body(mass, radius, position, velocity);
}

Body box(double half_x, double half_y, Vec2 position, Vec2 velocity = {}, double theta = 0.0, double mass = 1.0)
{
  const std::vector<Vec2> corners{{-half_x, -half_y}, {half_x, -half_y}, {half_x, half_y}, {-half_x, half_y}};
  return Body(mass, corners, position, velocity, theta);
}

/// Regular k-gon of circumradius r, rotated by theta.
Body regular_polygon(int k, double r, Vec2 position, Vec2 velocity, double theta)
{
  std::vector<Vec2> vertices;
  for (int i = 0; i < k; ++i)
  {
    const double angle = 2.0 * kPi * i / k;
    vertices.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  return Body(1.0, vertices, position, velocity, theta);
}

Body moved(const Body& body, double t)
{
  Body copy = body;
  copy.set_position(body.position() + t * body.velocity());
  return copy;
}

/// Largest gap between the projections of two polygons on the face normals of
/// `faces`: positive iff that polygon's faces separate them.
double face_separation(const Body& faces, const Body& other)
{
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < faces.vertex_count(); ++i)
  {
    const Vec2 n = faces.world_face_normal(i);
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < other.vertex_count(); ++j)
    {
      lowest = std::min(lowest, dot(n, other.world_vertex(j) - faces.world_vertex(i)));
    }
    best = std::max(best, lowest);
  }
  return best;
}

/// Signed distance from point p to a convex polygon (negative inside).
double polygon_distance(const Body& poly, Vec2 p)
{
  double inside = -std::numeric_limits<double>::infinity();
  double outside_sq = std::numeric_limits<double>::infinity();
  const std::size_t n = poly.vertex_count();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec2 a = poly.world_vertex(i);
    const Vec2 e = poly.world_vertex((i + 1) % n) - a;
    inside = std::max(inside, dot(poly.world_face_normal(i), p - a));
    const double s = std::clamp(dot(p - a, e) / length_sq(e), 0.0, 1.0);
    outside_sq = std::min(outside_sq, length_sq(p - (a + s * e)));
  }
  return inside > 0.0 ? std::sqrt(outside_sq) : inside;
}

/// Independent gap between two bodies: zero exactly when they touch, positive
/// when apart, negative when overlapping (the separating-axis gap for two
/// polygons, the Euclidean one when a disk is involved).
double gap(const Body& a, const Body& b)
{
  if (a.shape() == Shape::Disk && b.shape() == Shape::Disk)
  {
    return length(b.position() - a.position()) - a.radius() - b.radius();
  }
  if (a.shape() == Shape::Disk)
  {
    return polygon_distance(b, a.position()) - a.radius();
  }
  if (b.shape() == Shape::Disk)
  {
    return polygon_distance(a, b.position()) - b.radius();
  }
  return std::max(face_separation(a, b), face_separation(b, a));
}

double toi(const Body& a, const Body& b) { return time_of_impact(a, a.velocity(), b, b.velocity()); }

// ---------------------------------------------------------------- pair roots

TEST(TimeOfImpact, DisksHeadOnMeetAtTheLinearRoot)
{
  // Gap 3 - 1.5 = 1.5 m closed at 3 m/s.
  EXPECT_NEAR(toi(disk(1.0, {0, 0}, {2, 0}), disk(0.5, {3, 0}, {-1, 0})), 0.5, kRootTol);
}

TEST(TimeOfImpact, DisksOffAxisMeetAtTheQuadraticRoot)
{
  // |(3 - 4t, 1)| = 1.5  =>  t = (3 - sqrt(1.25)) / 4; split the motion over both.
  const double expected = (3.0 - std::sqrt(1.25)) / 4.0;
  EXPECT_NEAR(toi(disk(1.0, {0, 0}, {1, 0}), disk(0.5, {3, 1}, {-3, 0})), expected, kRootTol);
  // Same relative motion, passed explicitly to the pair function.
  const Body a = disk(1.0, {0, 0});
  const Body b = disk(0.5, {3, 1});
  EXPECT_NEAR(time_of_impact(a, {2, 0}, b, {-2, 0}), expected, kRootTol);
}

TEST(TimeOfImpact, BoxesApproachingFaceToFace)
{
  // Faces at x = 1 and x = 4 - 0.5 - 5t meet at t = 0.5.
  EXPECT_NEAR(toi(box(1, 1, {0, 0}), box(0.5, 0.5, {4, 0.2}, {-5, 0})), 0.5, kRootTol);
  // Vertically, both moving: faces y = 1 + 2t and y = 3 - 0.25 - 3.5t meet at t = 1.75 / 5.5.
  EXPECT_NEAR(toi(box(1, 1, {0, 0}, {0.3, 2}), box(2, 0.25, {0.5, 3}, {0.3, -3.5})), 1.75 / 5.5, kRootTol);
}

TEST(TimeOfImpact, DiskAgainstBoxCornerIsTheCircleVertexRoot)
{
  // Centre c(t) = (3 - 3t, 2 - 1.2t) reaches distance 0.5 from the corner (1, 1):
  // 10.44 t^2 - 14.4 t + 4.75 = 0.
  const double a = 10.44;
  const double b = -14.4;
  const double c = 4.75;
  const double expected = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  const Body ball = disk(0.5, {3, 2}, {-3, -1.2});
  const Body block = box(1, 1, {0, 0});
  // The root is a corner hit: the centre is beyond both faces of that corner.
  const Vec2 centre = moved(ball, expected).position();
  ASSERT_GT(centre.x, 1.0);
  ASSERT_GT(centre.y, 1.0);
  EXPECT_NEAR(toi(ball, block), expected, kRootTol);
  EXPECT_NEAR(toi(block, ball), expected, kRootTol);
}

TEST(TimeOfImpact, DiskOntoTheTopVertexOfARotatedBox)
{
  // A unit box turned 45 degrees has its top vertex at (0, sqrt 2). A disk of
  // radius 0.5 falling at x = 0.3 touches it when its centre is 0.4 above it.
  const Body diamond = box(1, 1, {0, 0}, {}, kPi / 4);
  const Body ball = disk(0.5, {0.3, 3}, {0, -3});
  EXPECT_NEAR(toi(diamond, ball), (3.0 - kSqrt2 - 0.4) / 3.0, kRootTol);
}

TEST(TimeOfImpact, RotatedBoxesMeetFaceToFace)
{
  // Two diamonds (half side 0.5, vertex radius r = sqrt 2 / 2), the second
  // 0.2 higher: the parallel faces x + y = r and x + y = x_b + 0.2 - r meet
  // when x_b = 4 - 6t = 2r - 0.2.
  const double r = kSqrt2 / 2;
  const Body a = box(0.5, 0.5, {0, 0}, {}, kPi / 4);
  const Body b = box(0.5, 0.5, {4, 0.2}, {-6, 0}, -3 * kPi / 4);
  EXPECT_NEAR(toi(a, b), (4.2 - 2 * r) / 6.0, kRootTol);
}

TEST(TimeOfImpact, VertexOfRotatedBoxAgainstAFace)
{
  // Diamond tip at x_b - r against the face x = 1.
  const double r = kSqrt2 / 2;
  const Body block = box(1, 1, {0, 0});
  const Body diamond = box(0.5, 0.5, {4, 0.3}, {-6, 0}, kPi / 4);
  EXPECT_NEAR(toi(block, diamond), (3.0 - r) / 6.0, kRootTol);
}

TEST(TimeOfImpact, FastSmallDiskDoesNotTunnelThroughAThinBox)
{
  // 100 m in one step past a 0.02 m wall: apart at both ends of the step.
  const Body bullet = disk(0.05, {-5, 0}, {100, 0}, 0.1);
  const Body wall = box(0.01, 1, {0, 0});
  ASSERT_GT(gap(bullet, wall), 0.0);
  ASSERT_GT(gap(moved(bullet, 1.0), wall), 0.0);
  EXPECT_NEAR(toi(bullet, wall), (5.0 - 0.05 - 0.01) / 100.0, kRootTol);
}

TEST(TimeOfImpact, AlreadyOverlappingIsZero)
{
  // Even when moving apart.
  EXPECT_EQ(toi(disk(1, {0, 0}, {-1, 0}), disk(1, {1.9, 0}, {1, 0})), 0.0);
  EXPECT_EQ(toi(box(1, 1, {0, 0}), box(1, 1, {1.5, 1.5}, {5, 5})), 0.0);
  EXPECT_EQ(toi(disk(0.5, {1.2, 0}), box(1, 1, {0, 0})), 0.0);
  // A disk centre inside a polygon.
  EXPECT_EQ(toi(box(1, 1, {0, 0}), disk(0.1, {0.2, 0.3}, {7, 0})), 0.0);
}

TEST(TimeOfImpact, NoTouchWithinTheStepIsOne)
{
  // Passing beside each other.
  EXPECT_EQ(toi(disk(1, {0, 0}), disk(1, {5, 2.5}, {-10, 0})), 1.0);
  EXPECT_EQ(toi(box(1, 1, {0, 0}), box(1, 1, {5, 2.01}, {-10, 0})), 1.0);
  // Moving apart.
  EXPECT_EQ(toi(disk(1, {0, 0}, {-1, 0}), disk(1, {3, 0}, {1, 0})), 1.0);
  EXPECT_EQ(toi(disk(0.5, {3, 0}, {1, 1}), box(1, 1, {0, 0})), 1.0);
  // Approaching but too slowly: they would meet at t = 2.
  EXPECT_EQ(toi(disk(1, {0, 0}), disk(1, {4, 0}, {-1, 0})), 1.0);
  // At rest relative to each other.
  EXPECT_EQ(toi(box(1, 1, {0, 0}, {3, 3}), disk(1, {4, 0}, {3, 3})), 1.0);
}

TEST(TimeOfImpact, TouchingPairIsAnImpactOnlyWhenApproaching)
{
  const Body left = box(1, 1, {0, 0});
  EXPECT_EQ(toi(left, box(1, 1, {2, 0.5}, {-1, 0})), 0.0);
  EXPECT_EQ(toi(left, box(1, 1, {2, 0.5}, {1, 0})), 1.0);
  // Sliding along the shared face is not an impact either.
  EXPECT_EQ(toi(left, box(1, 1, {2, 0.5}, {0, 3})), 1.0);
  EXPECT_EQ(toi(disk(1, {0, 0}), disk(1, {2, 0}, {-1, 0})), 0.0);
  EXPECT_EQ(toi(disk(1, {0, 0}), disk(1, {2, 0}, {1, 0})), 1.0);
}

/// Random convex pairs: at the returned time they touch; before it they are
/// apart; with no impact they never overlap during the step.
TEST(TimeOfImpact, RandomPairsTouchAtTheRootAndNotBefore)
{
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> size(0.2, 1.0);
  constexpr int kPairs = 400;
  constexpr int kSamples = 50;
  int impacts = 0;
  for (int n = 0; n < kPairs; ++n)
  {
    const auto make = [&](Vec2 at) {
      const Vec2 v{4 * unit(rng), 4 * unit(rng)};
      if (n % 3 == 0)
      {
        return disk(size(rng), at, v);
      }
      return regular_polygon(3 + n % 5, size(rng), at, v, kPi * unit(rng));
    };
    const Body a = make({0, 0});
    const Body b = make({3 * unit(rng), 3 * unit(rng)});
    if (gap(a, b) <= 0.0)
    {
      continue;
    }
    const double t = toi(a, b);
    ASSERT_GE(t, 0.0);
    ASSERT_LE(t, 1.0);
    for (int s = 0; s < kSamples; ++s)
    {
      const double before = t * s / kSamples;
      EXPECT_GT(gap(moved(a, before), moved(b, before)), 0.0) << "pair " << n << " at t = " << before;
    }
    if (t < 1.0)
    {
      ++impacts;
      EXPECT_NEAR(gap(moved(a, t), moved(b, t)), 0.0, kTouchGap) << "pair " << n;
    }
  }
  EXPECT_GT(impacts, kPairs / 10);  // the sample really exercises impacts
}

// ------------------------------------------------------------- whole scenes

TEST(ContactSolverTimeOfImpact, EarliestPairWins)
{
  std::vector<Body> bodies{
      disk(0.5, {0, 0}, {1, 0}), disk(0.5, {3, 0}, {-1, 0}),                   // meet at t = 1
      box(0.5, 0.5, {0, 10}), disk(0.5, {2.2, 10}, {-4, 0}),                   // t = 0.3
      box(0.5, 0.5, {0, 20}, {0, 1}), box(0.5, 0.5, {0.3, 22.6}, {0, -1}),     // t = 0.8
  };
  EXPECT_NEAR(ContactSolver::time_of_impact(bodies), 0.3, kRootTol);
  bodies[3].set_velocity({-1, 0});  // now 1.2: beyond the step
  EXPECT_NEAR(ContactSolver::time_of_impact(bodies), 0.8, kRootTol);
}

TEST(ContactSolverTimeOfImpact, PairsOfNonDynamicBodiesAreIgnored)
{
  std::vector<Body> bodies{box(1, 1, {0, 0}), box(1, 1, {1, 0}), disk(0.5, {5, 0}, {-5, 0})};
  bodies[0].set_type(BodyType::Static);
  bodies[1].set_type(BodyType::Kinematic);
  // The overlapping static/kinematic pair would give 0; the disk hits the
  // kinematic box's face x = 2 at t = (5 - 0.5 - 2) / 5.
  EXPECT_NEAR(ContactSolver::time_of_impact(bodies), 0.5, kRootTol);
}

TEST(ContactSolverStep, LeavesTheImpactingPairTouchingAndBounced)
{
  const double e = 0.6;
  const ContactSolver solver(e, 0.0);
  std::vector<Body> bodies{disk(0.5, {0, 0}, {2, 0}, 1.0), disk(0.5, {3, 0}, {-1, 0}, 3.0)};
  const Vec2 momentum = bodies[0].momentum() + bodies[1].momentum();
  const double approach = 3.0;

  const SolveReport report = solver.step(bodies);
  EXPECT_NEAR(report.time_of_impact, (3.0 - 1.0) / approach, kRootTol);
  EXPECT_NEAR(gap(bodies[0], bodies[1]), 0.0, kTouchGap);
  // Newton: separating at e times the approach speed; momentum kept.
  EXPECT_NEAR(bodies[1].velocity().x - bodies[0].velocity().x, e * approach, 1e-9);
  const Vec2 after = bodies[0].momentum() + bodies[1].momentum();
  EXPECT_NEAR(after.x, momentum.x, 1e-12);
  EXPECT_NEAR(after.y, momentum.y, 1e-12);

  // Separating now: the next step finds no impact instead of t = 0 again.
  EXPECT_EQ(solver.step(bodies).time_of_impact, 1.0);
}

TEST(ContactSolverStep, StopsAFastBulletAtAThinWall)
{
  const ContactSolver solver(1.0, 0.0);
  std::vector<Body> bodies{disk(0.05, {-5, 0}, {100, 0}, 0.1), box(0.01, 1, {0, 0}, {}, 0.0, 10.0)};
  const SolveReport report = solver.step(bodies);
  EXPECT_NEAR(report.time_of_impact, 0.0494, kRootTol);
  EXPECT_NEAR(gap(bodies[0], bodies[1]), 0.0, kTouchGap);
  EXPECT_LT(bodies[0].position().x, 0.0);  // still on its own side
  EXPECT_LT(bodies[0].velocity().x, 0.0);  // bounced
  EXPECT_GT(bodies[1].velocity().x, 0.0);
  // Elastic: the relative velocity reverses.
  EXPECT_NEAR(bodies[0].velocity().x - bodies[1].velocity().x, -100.0, 1e-9);
}

TEST(ContactSolverStep, InelasticContactDoesNotStallAtTimeZero)
{
  // e = 0 leaves the pair touching with zero relative normal speed: a resting
  // contact must not count as an impact on every following step.
  const ContactSolver solver(0.0, 0.0);
  std::vector<Body> bodies{box(0.5, 0.5, {0, 0}, {1, 0}, 0.0, 1.0), box(0.5, 0.5, {2, 0}, {-1, 0}, 0.0, 2.0)};
  EXPECT_NEAR(solver.step(bodies).time_of_impact, 0.5, kRootTol);
  // Perfectly inelastic: a common velocity, (1 * 1 - 2 * 1) / 3.
  const double common = -1.0 / 3.0;
  EXPECT_NEAR(bodies[0].velocity().x, common, 1e-9);
  EXPECT_NEAR(bodies[1].velocity().x, common, 1e-9);
  const double x0 = bodies[0].position().x;
  constexpr int kSteps = 3;
  for (int i = 0; i < kSteps; ++i)
  {
    EXPECT_EQ(solver.step(bodies).time_of_impact, 1.0);
    EXPECT_NEAR(gap(bodies[0], bodies[1]), 0.0, kTouchGap);
  }
  EXPECT_NEAR(bodies[0].position().x, x0 + kSteps * common, 1e-9);  // moved on together
}

}  // namespace
}  // namespace collision2d
