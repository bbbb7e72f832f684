// Far from the origin: at 1e6 m, where one ulp of a coordinate is
// 1.2e-10 m, contacts, impacts and a resting stack behave as at the origin.
// Each scene is built twice, at the origin and shifted by kOffset, and the
// results are compared after removing the shift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/collide.h"
#include "collision2d/contact_solver.h"
#include "collision2d/exact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "extremes_support.h"
#include "solver_test_support.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
const Vec2 kOffset{1e6, -1e6};  // m
/// Coordinates carry about 1.2e-10 m of round-off at 1e6 m; depths and
/// points are differences of such coordinates, a few ulps each.
constexpr double kGeometryTol = 1e-8;  // m
constexpr double kNormalTol = 1e-9;    // unit-vector components
/// Velocities after one solve: lever arms come from differences of far
/// coordinates (relative error ~1e-10 on a 1 m arm), scaled by the speed.
constexpr double kVelocityRelativeTol = 1e-9;
constexpr double kSpeed = 3.0;  // m/s

std::vector<Body> shifted(std::vector<Body> bodies, Vec2 offset)
{
  for (Body& b : bodies)
  {
    b.set_position(b.position() + offset);
  }
  return bodies;
}

/// A mix of pairs: disk-disk, disk-box, box-box face to face and corner first.
std::vector<Body> contact_scene()
{
  return {Body(1.0, 0.5, {0.0, 0.0}, {kSpeed, 0.5}),
          Body(2.0, 0.5, {0.93, 0.21}, {-kSpeed, 0.0}, 1.0),
          scenes::make_box(3.0, 1.0, 1.0, {1.1, 1.05}, 0.0, {0.0, -kSpeed}, 0.5),
          scenes::make_box(0.5, 1.0, 0.6, {2.05, 1.2}, 0.7, {-1.0, 0.0}, -2.0)};
}

TEST(ExtremesFarOrigin, ContactsMatchTheOrigin)
{
  const std::vector<Body> near = contact_scene();
  const std::vector<Body> far = shifted(near, kOffset);
  const std::vector<Contact> cn = ContactSolver::detect_contacts(near);
  const std::vector<Contact> cf = ContactSolver::detect_contacts(far);
  ASSERT_GE(cn.size(), 3u);
  ASSERT_EQ(cn.size(), cf.size());
  double worst_depth = 0.0;
  double worst_point = 0.0;
  double worst_normal = 0.0;
  for (std::size_t k = 0; k < cn.size(); ++k)
  {
    EXPECT_EQ(cn[k].a, cf[k].a);
    EXPECT_EQ(cn[k].b, cf[k].b);
    EXPECT_EQ(cn[k].feature, cf[k].feature);
    worst_depth = std::max(worst_depth, std::abs(cn[k].penetration - cf[k].penetration));
    worst_point = std::max(worst_point, length(cf[k].point - kOffset - cn[k].point));
    worst_normal = std::max(worst_normal, length(cf[k].normal - cn[k].normal));
  }
  EXPECT_LE(worst_depth, kGeometryTol);
  EXPECT_LE(worst_point, kGeometryTol);
  EXPECT_LE(worst_normal, kNormalTol);
  std::printf("%zu contacts at 1e6 m vs the origin:\n", cn.size());
  test::print_figure("depth difference (m)", worst_depth, kGeometryTol);
  test::print_figure("point difference after the shift (m)", worst_point, kGeometryTol);
  test::print_figure("normal difference", worst_normal, kNormalTol);
}

double velocity_difference(const std::vector<Body>& a, const std::vector<Body>& b)
{
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    worst = std::max({worst, length(a[i].velocity() - b[i].velocity()) / kSpeed,
                      std::abs(a[i].omega() - b[i].omega()) / kSpeed});
  }
  return worst;
}

TEST(ExtremesFarOrigin, SolvesMatchTheOrigin)
{
  for (bool exact : {false, true})
  {
    std::vector<Body> near = contact_scene();
    std::vector<Body> far = shifted(near, kOffset);
    const ContactSolver solver(0.5, 0.3, 1000);
    if (exact)
    {
      solve_exact(near, ContactSolver::detect_contacts(near), 0.5, 0.3, 1e-12);
      solve_exact(far, ContactSolver::detect_contacts(far), 0.5, 0.3, 1e-12);
    }
    else
    {
      solver.resolve(near);
      solver.resolve(far);
    }
    const double dv = velocity_difference(near, far);
    double dp = 0.0;
    for (std::size_t i = 0; i < near.size(); ++i)
    {
      dp = std::max(dp, length(far[i].position() - kOffset - near[i].position()));
    }
    EXPECT_LE(dv, kVelocityRelativeTol);
    EXPECT_LE(dp, kGeometryTol);
    test::print_figure(std::string(exact ? "exact" : "iterative") + " solve at 1e6 m: velocity difference (rel)",
                       dv, kVelocityRelativeTol);
    test::print_figure(std::string(exact ? "exact" : "iterative") + " resolve at 1e6 m: position difference (m)",
                       dp, kGeometryTol);
  }
}

TEST(ExtremesFarOrigin, HeadOnImpactMatchesTheFormula)
{
  const double m1 = 1.0;
  const double m2 = 7.0;
  const double e = 0.8;
  std::vector<Body> bodies = shifted(
      {Body(m1, 0.5, {0.0, 0.0}, {kSpeed, 0.0}), Body(m2, 0.5, {0.999, 0.0}, {-kSpeed, 0.0})}, kOffset);
  ContactSolver(e, 0.0).solve(bodies, ContactSolver::detect_contacts(bodies));
  const double v1 = (m1 * kSpeed - m2 * kSpeed - m2 * e * 2.0 * kSpeed) / (m1 + m2);
  const double v2 = (m1 * kSpeed - m2 * kSpeed + m1 * e * 2.0 * kSpeed) / (m1 + m2);
  const double err = std::max(std::abs(bodies[0].velocity().x - v1), std::abs(bodies[1].velocity().x - v2)) / kSpeed;
  EXPECT_LE(err, kVelocityRelativeTol);
  test::print_figure("1D impact at 1e6 m vs formula (relative)", err, kVelocityRelativeTol);
}

/// A column of boxes on the ground with its base at `at`.
Scene column_at(Vec2 at)
{
  Scene scene;
  scenes::GroundParams ground;
  ground.x = at.x;
  ground.top = at.y;
  ground.width = 10.0;
  scenes::add_ground(scene, ground);
  scenes::ColumnParams column;
  column.count = 5;
  column.at = at + Vec2{0.0, 0.5};
  scenes::add_column(scene, column);
  return scene;
}

/// Largest horizontal offset, tilt and vertical change of the boxes between
/// `settled` (positions after the first second) and now; for a resting stack
/// all three stay at round-off.
double stack_drift(const World& world, const std::vector<Vec2>& settled, Vec2 base)
{
  double worst = 0.0;
  for (BodyId id : world.body_ids())
  {
    const Body& b = world.body(id);
    worst = std::max({worst, std::abs(b.position().x - base.x), std::abs(b.theta()),
                      std::abs(b.position().y - settled[id].y)});
  }
  return worst;
}

TEST(ExtremesFarOrigin, StackBehavesAsAtTheOrigin)
{
  World near = make_world(column_at({0.0, 0.0}));
  World far = make_world(column_at(kOffset));
  constexpr int kSettleFrames = 60;
  near.step(kSettleFrames);
  far.step(kSettleFrames);
  const std::vector<Vec2> near_settled = test::positions(near);
  const std::vector<Vec2> far_settled = test::positions(far);
  const long frames = test::sized(600, 120, "far-origin stack frames");
  for (long f = 0; f < frames; ++f)
  {
    near.step();
    far.step();
  }
  // The two worlds' motions relative to their own base: round-off at 1e6 m
  // feeds the stack's tiny motions, and must stay tiny.
  constexpr double kStackTol = 1e-6;    // m and rad
  // A stack still settles slowly after its first second (3e-5 m over the
  // next ten seconds); sideways drift and tilt stay at round-off.
  constexpr double kDriftBound = 1e-4;  // m and rad, after settling
  double worst = 0.0;
  for (BodyId id : near.body_ids())
  {
    const Body& n = near.body(id);
    const Body& f = far.body(id);
    worst = std::max({worst, length(f.position() - kOffset - n.position()), std::abs(f.theta() - n.theta())});
  }
  const double drift_near = stack_drift(near, near_settled, {0.0, 0.0});
  const double drift_far = stack_drift(far, far_settled, kOffset);
  EXPECT_LE(worst, kStackTol);
  EXPECT_LE(drift_near, kDriftBound);
  EXPECT_LE(drift_far, kDriftBound);
  std::printf("5-box column, %ld frames after %d settling frames, at the origin and at 1e6 m:\n", frames,
              kSettleFrames);
  test::print_figure("difference between the two stacks (m, rad)", worst, kStackTol);
  test::print_figure("drift after settling at the origin (m, rad)", drift_near, kDriftBound);
  test::print_figure("drift after settling at 1e6 m (m, rad)", drift_far, kDriftBound);
}

}  // namespace
}  // namespace collision2d
