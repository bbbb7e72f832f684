// correct_positions: positions only, penetration beyond slop reduced by
// bias_factor, split by inverse mass, once per pair, static bodies fixed.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "collision2d/contact_solver.h"
#include "solver_test_support.h"

namespace collision2d
{
namespace
{
using test::make_contact;

constexpr double kBias = 0.2;
constexpr double kSlop = 0.01;  // m
constexpr double kTight = 1e-15;  // m, positions are moved by one multiply-add

ContactSolver corrector() { return ContactSolver(0.5, 0.3, 64, 1e-12, kBias, kSlop); }

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

/// Velocities, spins and orientations bitwise equal.
void expect_motion_untouched(const std::vector<Body>& before, const std::vector<Body>& after)
{
  for (std::size_t i = 0; i < before.size(); ++i)
  {
    EXPECT_TRUE(same_bits(before[i].velocity().x, after[i].velocity().x)) << "body " << i;
    EXPECT_TRUE(same_bits(before[i].velocity().y, after[i].velocity().y)) << "body " << i;
    EXPECT_TRUE(same_bits(before[i].omega(), after[i].omega())) << "body " << i;
    EXPECT_TRUE(same_bits(before[i].theta(), after[i].theta())) << "body " << i;
  }
}

/// Two disks overlapping by `depth` along n = (0.6, 0.8), moving and spinning.
std::vector<Body> disk_pair(double m_a, double m_b, double depth, Vec2 n)
{
  const double radius = 0.5;
  std::vector<Body> bodies;
  bodies.emplace_back(m_a, radius, Vec2{1.0, 2.0}, Vec2{0.3, -0.2}, 1.5);
  bodies.emplace_back(m_b, radius, Vec2{1.0, 2.0} + (2.0 * radius - depth) * n, Vec2{-0.1, 0.4}, -2.0);
  return bodies;
}

TEST(PositionCorrection, SplitsTheMoveByInverseMassAndLeavesVelocitiesAlone)
{
  const Vec2 n{0.6, 0.8};
  const double depth = 0.1;
  const double m_a = 1.0;
  const double m_b = 3.0;
  std::vector<Body> bodies = disk_pair(m_a, m_b, depth, n);
  const std::vector<Body> before = bodies;
  const std::vector<Contact> contacts{make_contact(0, 1, n, bodies[0].position() + 0.5 * n, depth)};
  corrector().correct_positions(bodies, contacts);

  const double move = kBias * (depth - kSlop);
  const Vec2 da = bodies[0].position() - before[0].position();
  const Vec2 db = bodies[1].position() - before[1].position();
  // a gets w_a / (w_a + w_b) = m_b / (m_a + m_b) of the move, against n.
  EXPECT_NEAR(dot(da, n), -move * m_b / (m_a + m_b), kTight);
  EXPECT_NEAR(dot(db, n), move * m_a / (m_a + m_b), kTight);
  EXPECT_NEAR(cross(da, n), 0.0, kTight);
  EXPECT_NEAR(dot(db - da, n), move, kTight);
  EXPECT_NEAR(length(da) / length(db), m_b / m_a, 1e-12);  // the heavier body moves less
  expect_motion_untouched(before, bodies);
}

TEST(PositionCorrection, LeavesPenetrationWithinSlopAlone)
{
  const Vec2 n{1.0, 0.0};
  for (double depth : {0.0, 0.5 * kSlop, kSlop})
  {
    std::vector<Body> bodies = disk_pair(1.0, 2.0, depth, n);
    const std::vector<Body> before = bodies;
    corrector().correct_positions(bodies, {make_contact(0, 1, n, bodies[0].position() + 0.5 * n, depth)});
    for (std::size_t i = 0; i < bodies.size(); ++i)
      EXPECT_TRUE(bodies[i].position() == before[i].position()) << "depth " << depth;
  }
}

TEST(PositionCorrection, CorrectsATwoPointManifoldOnceByItsDeepestPoint)
{
  // Two boxes face to face, slightly tilted contact depths at the two corners.
  const std::vector<Vec2> box{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const double shallow = 0.05;
  const double deep = 0.08;
  const Vec2 n{0.0, 1.0};
  std::vector<Body> bodies;
  bodies.emplace_back(2.0, box, Vec2{0.0, 0.0}, Vec2{});
  bodies.emplace_back(2.0, box, Vec2{0.0, 1.0 - deep}, Vec2{});
  const std::vector<Contact> manifold{make_contact(0, 1, n, Vec2{-0.5, 0.5 - shallow}, shallow),
                                      make_contact(0, 1, n, Vec2{0.5, 0.5 - deep}, deep)};
  const std::vector<Body> before = bodies;
  corrector().correct_positions(bodies, manifold);

  // Once for the pair: the gap opens by bias (deep - slop), not by the sum
  // over the two points.
  const double opened = (bodies[1].position() - bodies[0].position()).y - (before[1].position() - before[0].position()).y;
  EXPECT_NEAR(opened, kBias * (deep - kSlop), kTight);
  expect_motion_untouched(before, bodies);

  // The same pair given in the other order, with a third body's contact in
  // between, is still grouped into one correction.
  std::vector<Body> three = before;
  three.emplace_back(1.0, 0.5, Vec2{3.0, 0.0}, Vec2{});
  const std::vector<Contact> mixed{manifold[1], make_contact(1, 2, Vec2{1.0, 0.0}, Vec2{2.5, 0.0}, 0.0),
                                   manifold[0]};
  corrector().correct_positions(three, mixed);
  EXPECT_TRUE(three[0].position() == bodies[0].position());
  EXPECT_TRUE(three[1].position() == bodies[1].position());
}

TEST(PositionCorrection, NeverMovesAStaticBody)
{
  const std::vector<Vec2> slab{{-5.0, -0.5}, {5.0, -0.5}, {5.0, 0.5}, {-5.0, 0.5}};
  const double depth = 0.2;
  std::vector<Body> bodies;
  bodies.emplace_back(1.0, slab, Vec2{0.0, -0.5}, Vec2{});
  bodies[0].set_type(BodyType::Static);
  bodies.emplace_back(1.0, 0.5, Vec2{0.0, 0.5 - depth}, Vec2{0.0, -1.0});
  const std::vector<Body> before = bodies;
  corrector().correct_positions(bodies, {make_contact(0, 1, Vec2{0.0, 1.0}, Vec2{0.0, -depth}, depth)});

  EXPECT_TRUE(same_bits(bodies[0].position().x, before[0].position().x));
  EXPECT_TRUE(same_bits(bodies[0].position().y, before[0].position().y));
  EXPECT_NEAR(bodies[1].position().y - before[1].position().y, kBias * (depth - kSlop), kTight);
  expect_motion_untouched(before, bodies);
}

TEST(PositionCorrection, ReducesDetectedPenetrationByTheBiasFraction)
{
  // Face-to-face boxes through detect_contacts: after one correction the
  // re-detected depth is the old one minus bias (depth - slop).
  const std::vector<Vec2> box{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const double depth = 0.1;
  std::vector<Body> bodies;
  bodies.emplace_back(1.0, box, Vec2{0.0, 0.0}, Vec2{});
  bodies.emplace_back(4.0, box, Vec2{0.2, 1.0 - depth}, Vec2{});
  const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  ASSERT_EQ(contacts.size(), 2u);
  corrector().correct_positions(bodies, contacts);
  const std::vector<Contact> after = ContactSolver::detect_contacts(bodies);
  ASSERT_EQ(after.size(), 2u);
  for (const Contact& c : after)
    EXPECT_NEAR(c.penetration, depth - kBias * (depth - kSlop), 1e-12);
}

}  // namespace
}  // namespace collision2d
