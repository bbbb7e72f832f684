// BodyDragger: interactive markers over the bodies, set_body_state on feedback.
#include "collision2d/ros/body_dragger.h"

#include <cmath>
#include <stdexcept>

#include <visualization_msgs/InteractiveMarker.h>
#include <visualization_msgs/InteractiveMarkerControl.h>
#include <visualization_msgs/Marker.h>

namespace collision2d
{
namespace ros_interface
{
namespace
{
using visualization_msgs::InteractiveMarker;
using visualization_msgs::InteractiveMarkerControl;
using visualization_msgs::InteractiveMarkerFeedback;
using visualization_msgs::Marker;

constexpr const char* kLogger = "drag";
// Velocities are measured over at least this long: mouse events come a few
// ms apart, and shorter differences are mostly jitter.
constexpr double kMinSampleInterval = 0.03;  ///< s
// A body held still this long before the release is let go at rest.
constexpr double kStaleMotion = 0.25;  ///< s
constexpr double kHandleThickness = 0.05;  ///< m
// Above every marker of the body (labels are drawn at 0.15 m): rviz picks the
// nearest object under the mouse, and a press on the disk's radius line would
// otherwise grab the line, which does not drag, and move the camera instead.
constexpr double kHandleZ = 0.25;  ///< m

double yaw_of(const geometry_msgs::Quaternion& q)
{
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

geometry_msgs::Pose body_pose(const BodyMsg& body)
{
  geometry_msgs::Pose pose;
  pose.position.x = body.pose.x;
  pose.position.y = body.pose.y;
  pose.orientation.z = std::sin(0.5 * body.pose.theta);
  pose.orientation.w = std::cos(0.5 * body.pose.theta);
  return pose;
}

InteractiveMarker handle(const BodyMsg& body, const std_msgs::Header& header, float alpha)
{
  InteractiveMarker marker;
  marker.header = header;
  marker.name = std::to_string(body.id);
  marker.description = "body " + marker.name;
  marker.pose = body_pose(body);
  marker.scale = static_cast<float>(2.0 * body.radius);

  InteractiveMarkerControl control;
  control.name = "move";
  // MOVE_PLANE moves in the plane normal to the control's x axis: turned onto z, the world's plane.
  control.orientation.w = M_SQRT1_2;
  control.orientation.y = M_SQRT1_2;
  control.interaction_mode = InteractiveMarkerControl::MOVE_PLANE;
  control.always_visible = true;
  Marker disk;
  disk.type = Marker::CYLINDER;
  disk.pose.position.z = kHandleZ;
  disk.pose.orientation.w = 1.0;
  disk.scale.x = disk.scale.y = 2.0 * body.radius;
  disk.scale.z = kHandleThickness;
  disk.color.r = disk.color.g = disk.color.b = 1.0F;
  disk.color.a = alpha;
  control.markers.push_back(disk);
  marker.controls.push_back(control);
  return marker;
}

}  // namespace

BodyDragger::BodyDragger(::ros::NodeHandle& node_handle, std::string frame_id, float handle_alpha)
  : frame_id_(std::move(frame_id))
  , handle_alpha_(handle_alpha)
  , server_(node_handle.resolveName("drag"))
  , client_(node_handle.serviceClient<SetBodyState>("set_body_state", /*persistent=*/false))
{
}

void BodyDragger::update(const WorldState& state)
{
  std_msgs::Header header;
  header.frame_id = frame_id_.empty() ? state.header.frame_id : frame_id_;  // stamp 0: the latest transform
  std::set<std::string> now_shown;
  for (const BodyMsg& body : state.bodies)
  {
    const std::string name = std::to_string(body.id);
    now_shown.insert(name);
    if (shown_.count(name) == 0)
    {
      server_.insert(handle(body, header, handle_alpha_),
                     [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f) { on_feedback(f); });
    }
    else if (!(drag_.active && drag_.id == body.id))
    {
      server_.setPose(name, body_pose(body), header);
    }
  }
  for (const std::string& name : shown_)
  {
    if (now_shown.count(name) == 0)
    {
      server_.erase(name);
    }
  }
  shown_ = std::move(now_shown);
  server_.applyChanges();
}

void BodyDragger::on_feedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
{
  std::uint32_t id = 0;
  try
  {
    id = static_cast<std::uint32_t>(std::stoul(feedback->marker_name));
  }
  catch (const std::exception&)
  {
    return;  // not one of ours
  }
  const ::ros::WallTime now = ::ros::WallTime::now();
  const geometry_msgs::Pose& pose = feedback->pose;
  switch (feedback->event_type)
  {
    case InteractiveMarkerFeedback::MOUSE_DOWN:
      drag_ = Drag{true, id, pose.position.x, pose.position.y, now, now, 0.0, 0.0};
      send(id, pose, 0.0, 0.0, true);
      break;
    case InteractiveMarkerFeedback::POSE_UPDATE:
    {
      if (!drag_.active || drag_.id != id)
      {
        drag_ = Drag{true, id, pose.position.x, pose.position.y, now, now, 0.0, 0.0};
      }
      const double dt = (now - drag_.sampled).toSec();
      if (dt >= kMinSampleInterval)
      {
        drag_.vx = (pose.position.x - drag_.x) / dt;
        drag_.vy = (pose.position.y - drag_.y) / dt;
        drag_.x = pose.position.x;
        drag_.y = pose.position.y;
        drag_.sampled = now;
      }
      drag_.moved = now;
      send(id, pose, drag_.vx, drag_.vy, true);
      break;
    }
    case InteractiveMarkerFeedback::MOUSE_UP:
    {
      const bool moving = drag_.active && drag_.id == id && (now - drag_.moved).toSec() < kStaleMotion;
      send(id, pose, moving ? drag_.vx : 0.0, moving ? drag_.vy : 0.0, false);
      drag_ = Drag{};
      break;
    }
    default:
      break;
  }
}

void BodyDragger::send(std::uint32_t id, const geometry_msgs::Pose& pose, double vx, double vy, bool hold)
{
  SetBodyState srv;
  srv.request.id = id;
  srv.request.pose.x = pose.position.x;
  srv.request.pose.y = pose.position.y;
  srv.request.pose.theta = yaw_of(pose.orientation);
  srv.request.twist.linear.x = vx;
  srv.request.twist.linear.y = vy;
  srv.request.hold = hold;
  if (!client_.call(srv))
  {
    ROS_WARN_THROTTLE_NAMED(1.0, kLogger, "set_body_state unavailable: body %u not moved", id);
  }
  else if (!srv.response.success)
  {
    ROS_WARN_NAMED(kLogger, "set_body_state refused: %s", srv.response.message.c_str());
  }
}

}  // namespace ros_interface
}  // namespace collision2d
