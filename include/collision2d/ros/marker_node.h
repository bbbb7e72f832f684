// The marker node: world_state in, rviz markers out, at most ~max_rate arrays
// per second however fast the world steps; with ~draggable (default true) it
// also serves interactive markers that drag bodies (body_dragger.h).
#pragma once

#include <memory>

#include <ros/ros.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/body_dragger.h"
#include "collision2d/ros/markers.h"

namespace collision2d
{
namespace ros_interface
{
/// The node's MarkerOptions from its private parameters (~frame_id,
/// ~show_contacts, ~show_velocities, ~show_labels, ~impulse_scale,
/// ~velocity_scale); unset parameters keep the defaults of MarkerOptions.
MarkerOptions marker_options_from_params(const ::ros::NodeHandle& private_handle);

class MarkerNode
{
public:
  /// Subscribes to `world_state` and advertises `markers` (latched, so rviz
  /// started later still gets the current world) in `node_handle`'s namespace.
  MarkerNode(const ::ros::NodeHandle& node_handle, const ::ros::NodeHandle& private_handle);

private:
  void on_state(const WorldState::ConstPtr& state);
  void on_tick();

  ::ros::NodeHandle node_handle_;
  MarkerBuilder builder_;
  ::ros::Subscriber subscriber_;
  ::ros::Publisher publisher_;
  ::ros::WallTimer timer_;
  std::unique_ptr<BodyDragger> dragger_;  ///< null with ~draggable false
  /// Newest state not yet drawn: states in between are skipped, the last one
  /// never is.
  WorldState::ConstPtr pending_;
};

}  // namespace ros_interface
}  // namespace collision2d
