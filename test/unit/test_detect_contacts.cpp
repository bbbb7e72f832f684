// ContactSolver::detect_contacts: broad plus narrow phase must report exactly
// what an all-pairs collide() reports, with normals from lower to higher index.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "collision2d/collide.h"
#include "collision2d/contact_solver.h"
#include "random_scene.h"

namespace collision2d
{
namespace
{
std::vector<Contact> all_pairs(const std::vector<Body>& bodies, double relative_tolerance)
{
  std::vector<Contact> contacts;
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    for (std::size_t j = i + 1; j < bodies.size(); ++j)
    {
      Manifold m;
      if (collide(bodies[i], bodies[j], m, relative_tolerance * (bodies[i].radius() + bodies[j].radius())))
      {
        for (int k = 0; k < m.count; ++k)
        {
          contacts.push_back({i, j, m.normal, m.points[k].point, m.points[k].penetration, m.points[k].feature});
        }
      }
    }
  }
  return contacts;
}

void expect_same(const std::vector<Contact>& got, const std::vector<Contact>& want)
{
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < got.size(); ++k)
  {
    EXPECT_EQ(got[k].a, want[k].a);
    EXPECT_EQ(got[k].b, want[k].b);
    EXPECT_EQ(got[k].normal, want[k].normal);
    EXPECT_EQ(got[k].point, want[k].point);
    EXPECT_EQ(got[k].penetration, want[k].penetration);
    EXPECT_EQ(got[k].feature, want[k].feature);
  }
}

TEST(DetectContacts, EqualsAllPairsCollideOnRandomScenes)
{
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const std::vector<Body> bodies = test::random_scene(seed, 300, {15.0, 15.0});
    const std::vector<Contact> want = all_pairs(bodies, 0.0);
    EXPECT_GT(want.size(), 20u) << "scene too sparse to test anything";
    expect_same(ContactSolver::detect_contacts(bodies), want);
    // A generous relative tolerance adds near pairs; still identical.
    expect_same(ContactSolver::detect_contacts(bodies, 0.05), all_pairs(bodies, 0.05));
  }
}

TEST(DetectContacts, NormalPointsFromLowerToHigherIndex)
{
  // Body 0 is right of body 1, so the normal must point in -x.
  const std::vector<Body> bodies{Body(1.0, 1.0, {1.5, 0.0}, {0.0, 0.0}), Body(1.0, 1.0, {0.0, 0.0}, {0.0, 0.0})};
  const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].a, 0u);
  EXPECT_EQ(contacts[0].b, 1u);
  EXPECT_DOUBLE_EQ(contacts[0].normal.x, -1.0);
  EXPECT_DOUBLE_EQ(contacts[0].penetration, 0.5);
}

TEST(DetectContacts, TwoPointManifoldGivesTwoRecordsOfOnePair)
{
  const std::vector<Vec2> unit_box{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const std::vector<Body> bodies{Body(1.0, unit_box, {0.2, 0.95}, {0.0, 0.0}),
                                 Body(1.0, unit_box, {0.0, 0.0}, {0.0, 0.0})};
  const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  ASSERT_EQ(contacts.size(), 2u);
  for (const Contact& c : contacts)
  {
    EXPECT_EQ(c.a, 0u);
    EXPECT_EQ(c.b, 1u);
    EXPECT_NEAR(c.normal.y, -1.0, 1e-12);
    EXPECT_NEAR(c.penetration, 0.05, 1e-12);
  }
}

TEST(DetectContacts, RelativeToleranceScalesWithThePairSize)
{
  // Radii sum 2 with a gap of 1e-3: counts at 1e-3 relative (2e-3 m), not at
  // 1e-4 (2e-4 m), and never without a tolerance.
  const std::vector<Body> bodies{Body(1.0, 1.0, {0.0, 0.0}, {0.0, 0.0}), Body(1.0, 1.0, {2.001, 0.0}, {0.0, 0.0})};
  EXPECT_TRUE(ContactSolver::detect_contacts(bodies).empty());
  EXPECT_TRUE(ContactSolver::detect_contacts(bodies, 1e-4).empty());
  const std::vector<Contact> near = ContactSolver::detect_contacts(bodies, 1e-3);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0].penetration, 0.0);
  EXPECT_THROW(ContactSolver::detect_contacts(bodies, -1e-3), std::invalid_argument);
}

TEST(DetectContacts, PairsOfNonDynamicBodiesAreSkipped)
{
  std::vector<Body> bodies{Body(1.0, 1.0, {0.0, 0.0}, {0.0, 0.0}), Body(1.0, 1.0, {1.5, 0.0}, {0.0, 0.0}),
                           Body(1.0, 1.0, {0.75, 1.0}, {0.0, 0.0})};
  bodies[0].set_type(BodyType::Static);
  bodies[1].set_type(BodyType::Kinematic);
  const std::vector<Contact> contacts = ContactSolver::detect_contacts(bodies);
  ASSERT_EQ(contacts.size(), 2u);  // (0,2) and (1,2); (0,1) carries nothing
  EXPECT_EQ(contacts[0].a, 0u);
  EXPECT_EQ(contacts[0].b, 2u);
  EXPECT_EQ(contacts[1].a, 1u);
  EXPECT_EQ(contacts[1].b, 2u);
}

TEST(DetectContacts, CoincidentDiskCentresThrow)
{
  const std::vector<Body> bodies{Body(1.0, 1.0, {0.0, 0.0}, {0.0, 0.0}), Body(2.0, 0.5, {0.0, 0.0}, {0.0, 0.0})};
  EXPECT_THROW(ContactSolver::detect_contacts(bodies), std::runtime_error);
}

}  // namespace
}  // namespace collision2d
