// Dragging bodies in rviz: an interactive marker on every body of the world
// state (server "drag" in the marker node's namespace, so rviz's
// InteractiveMarkers display reads <ns>/drag/update). Pressing on a body
// holds it as KINEMATIC, moving it sets its pose, and releasing gives it back
// its own type with the velocity of the last drag motion, all through the
// world node's set_body_state service. Feedback poses are taken to be in the
// world's frame (rviz's fixed frame, as in config/collision2d.rviz).
#pragma once

#include <cstdint>
#include <set>
#include <string>

#include <interactive_markers/interactive_marker_server.h>
#include <ros/ros.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>

#include "collision2d/ros/messages.h"

namespace collision2d
{
namespace ros_interface
{
class BodyDragger
{
public:
  /// `frame_id` "" = each state's header.frame_id; `handle_alpha` is the
  /// opacity of the grab disks drawn over the bodies.
  BodyDragger(::ros::NodeHandle& node_handle, std::string frame_id, float handle_alpha);

  /// Adds, moves and removes the interactive markers to match `state`; the
  /// body being dragged stays where the mouse has it.
  void update(const WorldState& state);

private:
  struct Drag
  {
    bool active = false;
    std::uint32_t id = 0;
    double x = 0.0;  ///< pose of the last velocity sample (m)
    double y = 0.0;
    ::ros::WallTime sampled;  ///< when that pose was seen
    ::ros::WallTime moved;    ///< last feedback that moved the body
    double vx = 0.0;          ///< velocity of the last drag motion (m/s)
    double vy = 0.0;
  };

  void on_feedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  /// Calls set_body_state; failures are logged (the world refuses, rviz goes on).
  void send(std::uint32_t id, const geometry_msgs::Pose& pose, double vx, double vy, bool hold);

  std::string frame_id_;
  float handle_alpha_;
  interactive_markers::InteractiveMarkerServer server_;
  ::ros::ServiceClient client_;
  std::set<std::string> shown_;
  Drag drag_;
};

}  // namespace ros_interface
}  // namespace collision2d
