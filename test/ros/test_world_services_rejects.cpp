// rostest client of the world services, the refusals (linked into
// test_world_services.cpp's binary): every bad-input class is answered with
// success = false, a message naming the body and field, and the world
// (GetWorld) left exactly as it was.
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "world_services_test_support.h"

namespace collision2d
{
namespace
{
using namespace world_services_test;  // NOLINT: the shared helpers and fixture

TEST_F(WorldServices, OverflowingStepIsRefusedAndTheWorldKept)
{
  // Gravity 1e308 m/s^2 with one-second frames: the second frame's velocity
  // passes the largest double. Finite, so validation lets it through; the
  // step must refuse instead of publishing inf, and keep the world.
  SetWorld::Request request;
  request.bodies = before_.bodies;
  request.settings = before_.settings;
  request.settings.gravity.y = -1e308;
  request.settings.dt = 1.0;
  const SetWorld set = call<SetWorld>("set_world", request);
  ASSERT_TRUE(set.response.success) << set.response.message;
  before_ = get_world();

  StepWorld::Request step_request;
  step_request.frames = 3;
  const StepWorld stepped = call<StepWorld>("step_world", step_request);
  expect_rejected(stepped.response, "overflowed to a non-finite state");
  EXPECT_TRUE(contains(stepped.response.message, "step_world failed")) << stepped.response.message;
}

TEST_F(WorldServices, NonFiniteNumbers)
{
  BodyMsg bad = disk_msg(0, {0.0, 0.0});
  bad.pose.x = kNaN;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): pose.x = nan is not finite");
  bad = disk_msg(0, {0.0, 0.0});
  bad.twist.linear.y = kInf;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): twist.linear.y = inf is not finite");
  AddBody::Request add;
  add.body = disk_msg(0, {1.0, 1.0});
  add.body.radius = kNaN;
  expect_rejected(call<AddBody>("add_body", add).response, "body: radius = nan is not finite");
}

TEST_F(WorldServices, NonPositiveMassOrRadius)
{
  expect_rejected(set_with_bad_second(disk_msg(0, {0.0, 0.0}, {}, 0.5, 0.0)), "bodies[1] (id 7): mass = 0 must be > 0");
  expect_rejected(set_with_bad_second(disk_msg(0, {0.0, 0.0}, {}, -0.1)),
                  "bodies[1] (id 7): radius = -0.1 must be > 0");
}

TEST_F(WorldServices, BadOutlines)
{
  BodyMsg bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  bad.vertices.resize(2);
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices: 2 given, a POLYGON needs at least 3");
  bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  std::reverse(bad.vertices.begin(), bad.vertices.end());
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices are clockwise");
  bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  bad.vertices[2].x = 0.0;  // (0.5, 0.5) -> (0, -0.2): a dent at vertex 2
  bad.vertices[2].y = -0.2;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices[2]: the outline turns clockwise here");
  bad = box_msg(0, 1.0, 1.0, {0.0, 0.0});
  bad.vertices.resize(3);
  for (std::size_t i = 0; i < 3; ++i)
  {
    bad.vertices[i].x = 0.5 * i;  // three distinct points on a line
    bad.vertices[i].y = 0.0;
  }
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): vertices enclose zero area");
}

TEST_F(WorldServices, UnknownShapeType)
{
  BodyMsg bad = disk_msg(0, {0.0, 0.0});
  bad.shape = 2;
  expect_rejected(set_with_bad_second(bad), "bodies[1] (id 7): shape = 2 is not DISK (0) or POLYGON (1)");
}

TEST_F(WorldServices, CoincidentCentres)
{
  expect_rejected(set_with_bad_second(disk_msg(0, {-10.0, 5.0})), "bodies[0] (id 3) and bodies[1] (id 7)");
  AddBody::Request add;
  add.body = disk_msg(0, {before_.bodies.back().pose.x, before_.bodies.back().pose.y}, {}, 0.1);
  expect_rejected(call<AddBody>("add_body", add).response,
                  "centre coincides with that of body id " + std::to_string(before_.bodies.back().id));
}

TEST_F(WorldServices, OutOfRangeSettings)
{
  SetWorld::Request request;
  request.bodies = {disk_msg(0, {0.0, 0.0})};
  request.settings = before_.settings;
  request.settings.substeps = 0;
  expect_rejected(call<SetWorld>("set_world", request).response, "substeps");
  request.settings = before_.settings;
  request.settings.friction = 9;
  expect_rejected(call<SetWorld>("set_world", request).response, "settings: friction = 9 is not AUTO (0), ON (1) or OFF (2)");
  request.settings = before_.settings;
  request.settings.solver_mode = 7;
  expect_rejected(call<SetWorld>("set_world", request).response,
                  "settings: solver_mode = 7 is not SOLVER_ITERATIVE (0) or SOLVER_EXACT (1)");
  request.settings = before_.settings;
  request.settings.position_iterations = 0;
  expect_rejected(call<SetWorld>("set_world", request).response, "position_iterations");

  StepWorld::Request step_request;
  step_request.frames = 0;
  expect_rejected(call<StepWorld>("step_world", step_request).response, "frames = 0 must be in [1, 2000]");
  step_request.frames = kMaxFrames + 1;
  expect_rejected(call<StepWorld>("step_world", step_request).response, "frames = 2001");
  step_request.frames = 1;
  step_request.dt = kNaN;
  expect_rejected(call<StepWorld>("step_world", step_request).response, "dt = nan is not finite");

  ResolveContacts::Request resolve;
  resolve.bodies = {disk_msg(0, {0.0, 0.0})};
  resolve.settings = ros_test::solver_settings(-0.5, 0.0);
  expect_rejected(call<ResolveContacts>("resolve_contacts", resolve).response,
                  "settings: restitution = -0.5 must be in [0, 1]");
}

TEST_F(WorldServices, UnknownSceneOrBody)
{
  LoadScene::Request request;
  request.scene = "no_such_scene";
  const LoadScene srv = call<LoadScene>("load_scene", request);
  expect_rejected(srv.response, "unknown scene 'no_such_scene' (known: ");
  EXPECT_TRUE(std::find(srv.response.available.begin(), srv.response.available.end(), "pyramid") !=
              srv.response.available.end());
  request.scene = "/nonexistent/scene.yaml";
  expect_rejected(call<LoadScene>("load_scene", request).response, "scene '/nonexistent/scene.yaml'");

  RemoveBody::Request remove;
  remove.id = 123456;
  expect_rejected(call<RemoveBody>("remove_body", remove).response, "id 123456: no body with this id");
}

TEST_F(WorldServices, MoreBodiesThanTheLimit)
{
  SetWorld::Request request;
  request.keep_settings = true;
  for (std::uint32_t i = 0; i <= kMaxBodies; ++i)
  {
    request.bodies.push_back(disk_msg(i, {2.0 * i, 0.0}));
  }
  expect_rejected(call<SetWorld>("set_world", request).response, "65 given, more than the limit of 64");
  // A shipped scene above the limit is refused the same way (pyramid: 210 boxes).
  LoadScene::Request load_request;
  load_request.scene = "pyramid";
  expect_rejected(call<LoadScene>("load_scene", load_request).response, "more than the limit of 64");
}

}  // namespace
}  // namespace collision2d
