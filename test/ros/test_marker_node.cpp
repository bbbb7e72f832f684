// rostest client of the marker node: the world node runs test/ros/marker_scene.yaml
// (still, nothing touching), the marker node draws it, and this client keeps
// what rviz would show (MarkerModel). The markers must match the scene's
// bodies as the scene file defines them (count, types, positions, radii,
// vertices), and removing a body or resetting the world must leave no ghosts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <visualization_msgs/MarkerArray.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/markers.h"
#include "marker_model.h"

namespace collision2d
{
namespace
{
namespace ns = ros_interface::marker_ns;
using test::MarkerModel;
using test::Point2;
using visualization_msgs::Marker;

constexpr double kServiceWait = 30.0;  // s, node start-up under a loaded machine
constexpr double kMarkerWait = 10.0;   // s, for the marker node to catch up
constexpr double kTol = 1e-9;          // m
constexpr const char* kFrame = "rviz_frame";

// test/ros/marker_scene.yaml, body by body (ids in file order).
constexpr std::uint32_t kFloor = 0, kWheel = 1, kPlank = 2, kWedge = 3, kPusher = 4;
constexpr std::size_t kSceneBodies = 5;
constexpr double kWheelX = -2.0, kWheelY = 1.0, kWheelRadius = 0.5, kWheelTheta = 0.7;
constexpr double kPusherX = 5.0, kPusherY = 4.0, kPusherRadius = 0.3;

/// What rviz shows: every array the marker node published, applied in order.
class MarkerListener
{
public:
  explicit MarkerListener(ros::NodeHandle& handle)
    : subscriber_(handle.subscribe("markers", 100, &MarkerListener::on_markers, this))
  {
  }

  /// Waits until `condition(model)` holds; false after kMarkerWait seconds.
  bool wait_for(const std::function<bool(const MarkerModel&)>& condition)
  {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kMarkerWait);
    while (std::chrono::steady_clock::now() < deadline)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (condition(model_))
        {
          return true;
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  MarkerModel model() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return model_;
  }

  bool saw_foreign_frame() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return foreign_frame_;
  }

private:
  void on_markers(const visualization_msgs::MarkerArray::ConstPtr& array)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    model_.apply(*array);
    for (const auto& marker : array->markers)
    {
      foreign_frame_ = foreign_frame_ || marker.header.frame_id != kFrame;
    }
  }

  mutable std::mutex mutex_;
  MarkerModel model_;
  bool foreign_frame_ = false;
  ros::Subscriber subscriber_;
};

template <typename Service>
Service call(const char* name, Service srv = Service())
{
  EXPECT_TRUE(ros::service::waitForService(name, ros::Duration(kServiceWait))) << name;
  EXPECT_TRUE(ros::service::call(name, srv)) << name << ": transport failed";
  return srv;
}

void reset_world()
{
  const auto srv = call<std_srvs::Trigger>("reset_world");
  ASSERT_TRUE(srv.response.success) << srv.response.message;
}

bool shows_exactly(const MarkerModel& m, const std::vector<std::uint32_t>& ids)
{
  if (m.count(ns::kBodies) != ids.size() || m.count(ns::kLabels) != ids.size())
  {
    return false;
  }
  return std::all_of(ids.begin(), ids.end(), [&](std::uint32_t id) { return m.find(ns::kBodies, id) != nullptr; });
}

std::vector<std::uint32_t> scene_ids()
{
  return {kFloor, kWheel, kPlank, kWedge, kPusher};
}

bool near(Point2 a, Point2 b)
{
  return std::hypot(a.x - b.x, a.y - b.y) < kTol;
}

/// The fill tiles the polygon (corners are its vertices, areas add up) and the
/// outline visits its vertices in order, closed, starting anywhere.
void expect_polygon(const MarkerModel& m, std::uint32_t id, const std::vector<Point2>& world, double area)
{
  SCOPED_TRACE("polygon body " + std::to_string(id));
  const Marker* fill = m.find(ns::kBodies, id);
  const Marker* outline = m.find(ns::kOutlines, id);
  ASSERT_NE(fill, nullptr);
  ASSERT_NE(outline, nullptr);
  EXPECT_EQ(fill->type, Marker::TRIANGLE_LIST);
  ASSERT_EQ(fill->points.size(), 3 * (world.size() - 2));
  double covered = 0.0;
  for (std::size_t t = 0; t < fill->points.size(); t += 3)
  {
    const Point2 a = test::to_world(*fill, fill->points[t]);
    const Point2 b = test::to_world(*fill, fill->points[t + 1]);
    const Point2 c = test::to_world(*fill, fill->points[t + 2]);
    covered += 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    for (const Point2& p : {a, b, c})
    {
      EXPECT_TRUE(std::any_of(world.begin(), world.end(), [&](Point2 v) { return near(v, p); }))
          << "triangle corner (" << p.x << ", " << p.y << ") is not a vertex";
    }
  }
  EXPECT_NEAR(covered, area, kTol);

  EXPECT_EQ(outline->type, Marker::LINE_STRIP);
  ASSERT_EQ(outline->points.size(), world.size() + 1);
  const Point2 first = test::to_world(*outline, outline->points[0]);
  const auto start = std::find_if(world.begin(), world.end(), [&](Point2 v) { return near(v, first); });
  ASSERT_NE(start, world.end()) << "outline starts off the polygon";
  const std::size_t offset = static_cast<std::size_t>(start - world.begin());
  for (std::size_t i = 0; i < outline->points.size(); ++i)
  {
    const Point2 p = test::to_world(*outline, outline->points[i]);
    EXPECT_TRUE(near(p, world[(offset + i) % world.size()])) << "outline point " << i;
  }
}

void expect_disk(const MarkerModel& m, std::uint32_t id, double x, double y, double radius)
{
  SCOPED_TRACE("disk body " + std::to_string(id));
  const Marker* fill = m.find(ns::kBodies, id);
  ASSERT_NE(fill, nullptr);
  EXPECT_EQ(fill->type, Marker::CYLINDER);
  EXPECT_NEAR(fill->pose.position.x, x, kTol);
  EXPECT_NEAR(fill->pose.position.y, y, kTol);
  EXPECT_NEAR(fill->scale.x, 2.0 * radius, kTol);
  EXPECT_NEAR(fill->scale.y, 2.0 * radius, kTol);
  EXPECT_NE(m.find(ns::kRotation, id), nullptr);
  EXPECT_EQ(m.find(ns::kOutlines, id), nullptr);
}

std::vector<Point2> placed(const std::vector<Point2>& local, double x, double y, double theta)
{
  std::vector<Point2> out;
  for (const Point2& p : local)
  {
    out.push_back(test::place(p, x, y, theta));
  }
  return out;
}

class MarkerNodeTest : public ::testing::Test
{
protected:
  void SetUp() override { reset_world(); }

  ros::NodeHandle handle_;
  MarkerListener listener_{handle_};
};

TEST_F(MarkerNodeTest, WorldHasTheSceneIds)
{
  const auto srv = call<GetWorld>("get_world");
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  ASSERT_EQ(srv.response.state.bodies.size(), kSceneBodies);
  for (std::size_t i = 0; i < kSceneBodies; ++i)
  {
    EXPECT_EQ(srv.response.state.bodies[i].id, scene_ids()[i]) << "the expectations below assume file order";
  }
}

TEST_F(MarkerNodeTest, MarkersMatchTheSceneBodies)
{
  ASSERT_TRUE(listener_.wait_for([](const MarkerModel& m) { return shows_exactly(m, scene_ids()); }))
      << "bodies shown: " << listener_.model().count(ns::kBodies);
  const MarkerModel m = listener_.model();
  EXPECT_FALSE(listener_.saw_foreign_frame()) << "every marker is in ~frame_id";
  EXPECT_EQ(m.count(ns::kContacts), 0U) << "nothing touches";
  EXPECT_EQ(m.count(ns::kOutlines), 3U) << "one per polygon";
  EXPECT_EQ(m.count(ns::kRotation), 2U) << "one per disk";

  expect_polygon(m, kFloor, {{-4.0, -2.5}, {4.0, -2.5}, {4.0, -1.5}, {-4.0, -1.5}}, 8.0);
  expect_polygon(m, kPlank, placed({{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {-1.0, 0.5}}, 3.0, 1.0, 0.5), 2.0);
  const double cx = 2.0 / 3.0, cy = 1.0 / 3.0;  // the wedge's centroid sits at its position
  expect_polygon(m, kWedge, placed({{-cx, -cy}, {2.0 - cx, -cy}, {-cx, 1.0 - cy}}, -4.0, 3.0, 0.0), 1.0);
  expect_disk(m, kWheel, kWheelX, kWheelY, kWheelRadius);
  expect_disk(m, kPusher, kPusherX, kPusherY, kPusherRadius);

  const Marker* radius = m.find(ns::kRotation, kWheel);
  ASSERT_NE(radius, nullptr);
  ASSERT_EQ(radius->points.size(), 2U);
  const Point2 rim = test::to_world(*radius, radius->points[1]);
  const Point2 expected_rim{kWheelX + kWheelRadius * std::cos(kWheelTheta),
                            kWheelY + kWheelRadius * std::sin(kWheelTheta)};
  EXPECT_TRUE(near(rim, expected_rim)) << "the radius line shows the wheel's angle";

  const auto& floor_color = m.find(ns::kBodies, kFloor)->color;
  EXPECT_TRUE(floor_color.r == floor_color.g && floor_color.g == floor_color.b) << "static is grey";
  const auto& pusher_color = m.find(ns::kBodies, kPusher)->color;
  EXPECT_FALSE(pusher_color.r == pusher_color.g && pusher_color.g == pusher_color.b) << "kinematic is not";
}

TEST_F(MarkerNodeTest, RemovedBodyIsDeletedEverywhere)
{
  ASSERT_TRUE(listener_.wait_for([](const MarkerModel& m) { return shows_exactly(m, scene_ids()); }));
  RemoveBody remove;
  remove.request.id = kPlank;
  remove = call("remove_body", remove);
  ASSERT_TRUE(remove.response.success) << remove.response.message;

  EXPECT_TRUE(listener_.wait_for(
      [](const MarkerModel& m) { return shows_exactly(m, {kFloor, kWheel, kWedge, kPusher}); }))
      << "bodies shown after the removal: " << listener_.model().count(ns::kBodies);
  const MarkerModel m = listener_.model();
  EXPECT_EQ(m.find(ns::kOutlines, kPlank), nullptr);
  EXPECT_EQ(m.find(ns::kLabels, kPlank), nullptr);
  EXPECT_NE(m.find(ns::kOutlines, kWedge), nullptr) << "the other polygons stay";
}

TEST_F(MarkerNodeTest, ResetLeavesNoGhostOfAnAddedBody)
{
  ASSERT_TRUE(listener_.wait_for([](const MarkerModel& m) { return shows_exactly(m, scene_ids()); }));
  AddBody add;
  auto& body = add.request.body;
  using BodyMsgT = AddBody::Request::_body_type;
  body.shape = BodyMsgT::DISK;
  body.type = BodyMsgT::DYNAMIC;
  body.mass = 1.0;
  body.radius = 0.4;
  body.pose.x = 0.0;
  body.pose.y = 5.0;
  add = call("add_body", add);
  ASSERT_TRUE(add.response.success) << add.response.message;
  const std::uint32_t added = add.response.id;
  ASSERT_TRUE(listener_.wait_for([added](const MarkerModel& m) {
    const Marker* disk = m.find(ns::kBodies, added);
    return disk != nullptr && std::abs(disk->pose.position.y - 5.0) < kTol;
  })) << "the added body is drawn where it was put";

  reset_world();
  EXPECT_TRUE(listener_.wait_for([](const MarkerModel& m) { return shows_exactly(m, scene_ids()); }))
      << "bodies shown after the reset: " << listener_.model().count(ns::kBodies);
  const MarkerModel m = listener_.model();
  EXPECT_EQ(m.find(ns::kRotation, added), nullptr);
  EXPECT_EQ(m.find(ns::kLabels, added), nullptr);
}

}  // namespace
}  // namespace collision2d

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_marker_node");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
