// The soft step keeps a pair's contact points while the pair moves less than
// contact_reuse_distance since they were found (world_contact_reuse.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "collision2d/collide.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace
{
/// The column's top box starts this far off centre (m).
constexpr double kNudge = 1e-6;
/// Simulated time of the column runs (s): a buckling column grows tenfold
/// in about 4 s, so the nudge reaches metres well within it.
constexpr double kColumnSeconds = 30.0;
/// The distance the tests keep points within (m): the default margin.
constexpr double kDistance = 0.02;

/// How far pair (a, b) has moved relative to each other since its origin (in
/// a's frame), by the rule the step keeps points with (m).
double moved_since_origin(const Body& a, const Body& b, const ContactOrigin& o)
{
  const Vec2 then = rotate_inv(o.r_a - o.r_b, std::cos(o.theta_a), std::sin(o.theta_a));
  const Vec2 now = rotate_inv(b.position() - a.position(), a.cos_theta(), a.sin_theta());
  const double extent = std::max(a.type() == BodyType::Static ? 0.0 : a.radius(),
                                 b.type() == BodyType::Static ? 0.0 : b.radius());
  const double turn = (b.theta() - o.theta_b) - (a.theta() - o.theta_a);
  return length(now - then) + extent * std::abs(std::sin(turn));
}

/// The top box's sideways travel over the run (m).
double column_top_travel(double reuse_distance)
{
  Scene scene = scenes::column(20);
  Body& top = scene.bodies.back().body;
  top.set_position(top.position() + Vec2{kNudge, 0.0});
  scene.settings.contact_reuse_distance = reuse_distance;
  World world = make_world(scene);
  const BodyId top_id = world.body_ids().back();
  const double x0 = world.body(top_id).position().x;
  world.step(static_cast<int>(std::lround(kColumnSeconds / scene.settings.dt)));
  return std::abs(world.body(top_id).position().x - x0);
}

TEST(ContactReuse, NudgedColumnStandsOnKeptPointsAndBucklesWithout)
{
  // Found again every frame, each normal tilts with the box below it and its
  // points move with the tilt: the column buckles under its own weight.
  const double kept = column_top_travel(kDistance);
  const double fresh = column_top_travel(0.0);
  std::printf("20-box column, top box nudged %.0e m, %.0f s: top box travels %.3g m (kept points), %.3g m (found "
              "every frame)\n",
              kNudge, kColumnSeconds, kept, fresh);
  EXPECT_LT(kept, 1e-4);
  EXPECT_GT(fresh, 0.1);
}

TEST(ContactReuse, PointsAreKeptExactlyWhileThePairHasMovedLessThanTheDistance)
{
  // A box sliding to rest. Before each frame the rule is applied here by hand
  // to the box's pose and its points' origin: the frame must keep the origin
  // when the box has moved less than the distance since, and find new points
  // (a new origin) otherwise.
  Scene scene = scenes::resting_box();
  scene.bodies.back().body.set_velocity(Vec2{2.0, 0.0});
  scene.settings.contact_reuse_distance = kDistance;
  World world = make_world(scene);
  const BodyId ground = world.body_ids().front();
  const BodyId box = world.body_ids().back();
  const double distance = std::min(kDistance, scene.settings.speculative_margin);
  world.step();
  int found = 0;
  int kept = 0;
  for (int frame = 1; frame < 120; ++frame)
  {
    ASSERT_EQ(world.contacts().size(), 2u) << "frame " << frame;
    const ContactOrigin before = world.contacts().front().origin;
    ASSERT_TRUE(before.known);
    const bool keep = moved_since_origin(world.body(ground), world.body(box), before) < distance;
    world.step();
    const ContactOrigin after = world.contacts().front().origin;
    const bool same = after.theta_b == before.theta_b && after.r_a == before.r_a && after.r_b == before.r_b &&
                      after.separation == before.separation;
    EXPECT_EQ(same, keep) << "frame " << frame;
    (same ? kept : found) += 1;
  }
  std::printf("sliding box: points found again %d times, kept %d frames (distance %.3g m)\n", found, kept, distance);
  EXPECT_GT(found, 0);
  EXPECT_GT(kept, found);
}

TEST(ContactReuse, ACornerOutOfReachIsFoundBeforeItReachesTheGround)
{
  // A 1 m x 0.2 m plank tilted 2 degrees lands on its low corner; its high
  // corner, 3.5 cm up, is beyond the margin, so the first points found have
  // only the low corner. The plank turns down onto its face: the pair is found
  // again before the high corner can reach the ground, even with a distance
  // above the margin (points kept 5 cm let it sink 16 mm into the ground).
  const double tilt = 2.0 * 3.14159265358979323846 / 180.0;
  const double half_length = 0.5;
  const double half_height = 0.1;
  Scene scene = scenes::resting_box();
  const std::vector<Vec2> outline = {
      {-half_length, -half_height}, {half_length, -half_height}, {half_length, half_height}, {-half_length, half_height}};
  const double lowest = half_height * std::cos(tilt) + half_length * std::sin(tilt);
  scene.bodies.back().body = Body(1.0, outline, Vec2{0.0, lowest + 1e-4}, Vec2{0.0, 0.0}, tilt);
  scene.settings.contact_reuse_distance = 0.05;
  ASSERT_GT(2.0 * half_length * std::sin(tilt), scene.settings.speculative_margin);
  World world = make_world(scene);
  double deepest = 0.0;
  for (int frame = 0; frame < 120; ++frame)
  {
    world.step();
    for (const WorldContact& c : world.contacts())
    {
      deepest = std::max(deepest, c.contact.penetration);
    }
  }
  std::printf("plank landing on a corner: deepest penetration %.3g mm, final angle %.3g rad\n", deepest * 1e3,
              world.body(world.body_ids().back()).theta());
  EXPECT_LT(deepest, 1e-3);
  EXPECT_LT(std::abs(world.body(world.body_ids().back()).theta()), 1e-3);
}

TEST(ContactReuse, KeptGapsMatchTheNarrowPhase)
{
  // A settling pyramid: each kept point's gap, followed from its origin to
  // the bodies' poses now, is the gap the narrow phase finds at those poses.
  Scene scene = scenes::pyramid(8);
  scene.settings.contact_reuse_distance = kDistance;
  World world = make_world(scene);
  world.step(120);
  double worst_gap = 0.0;
  double worst_normal = 0.0;
  std::size_t checked = 0;
  for (const WorldContact& c : world.contacts())
  {
    ASSERT_TRUE(c.origin.known);
    const Body& a = world.body(c.a);
    const Body& b = world.body(c.b);
    const ContactOrigin& o = c.origin;
    const Vec2 r_a = rotate(o.r_a, std::cos(a.theta() - o.theta_a), std::sin(a.theta() - o.theta_a));
    const Vec2 r_b = rotate(o.r_b, std::cos(b.theta() - o.theta_b), std::sin(b.theta() - o.theta_b));
    const double followed = o.separation + dot(b.position() - a.position() + r_b - r_a, c.contact.normal);
    Manifold fresh;
    ASSERT_TRUE(collide(a, b, fresh, 0.05));
    for (int k = 0; k < fresh.count; ++k)
    {
      if (fresh.points[k].feature == c.contact.feature)
      {
        worst_gap = std::max(worst_gap, std::abs(fresh.points[k].separation - followed));
        worst_normal = std::max(worst_normal, length(fresh.normal - c.contact.normal));
        ++checked;
      }
    }
  }
  std::printf("%zu of %zu kept points matched by feature: gaps differ by %.3g m at most, normals by %.3g\n", checked,
              world.contacts().size(), worst_gap, worst_normal);
  EXPECT_EQ(checked, world.contacts().size());
  EXPECT_LT(worst_gap, 1e-6);
}

}  // namespace
}  // namespace collision2d
