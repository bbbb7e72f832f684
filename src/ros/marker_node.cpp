// MarkerNode: a subscriber that keeps the newest world state and a timer that
// turns it into markers at most ~max_rate times per second.
#include "collision2d/ros/marker_node.h"

#include <cstdint>
#include <string>

#include <visualization_msgs/MarkerArray.h>

#include "node_params.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
// rviz redraws at about 30 Hz by default: more arrays than that are not seen.
constexpr double kDefaultMaxRateHz = 30.0;
// Only the newest state matters; older ones are dropped on arrival.
constexpr std::uint32_t kStateQueueSize = 1;
constexpr std::uint32_t kMarkerQueueSize = 1;
// The drag handles over the bodies: faint, so the bodies keep their colours.
constexpr double kDefaultDragHandleAlpha = 0.01;

double max_rate_from_params(const ::ros::NodeHandle& private_handle)
{
  double rate = kDefaultMaxRateHz;
  read_param(private_handle, "max_rate", rate);
  if (!(rate > 0.0))
  {
    ROS_WARN("~max_rate must be > 0 Hz; using %g", kDefaultMaxRateHz);
    return kDefaultMaxRateHz;
  }
  return rate;
}

}  // namespace

MarkerOptions marker_options_from_params(const ::ros::NodeHandle& private_handle)
{
  MarkerOptions options;
  read_param(private_handle, "frame_id", options.frame_id);
  read_param(private_handle, "show_contacts", options.show_contacts);
  read_param(private_handle, "show_velocities", options.show_velocities);
  read_param(private_handle, "show_labels", options.show_labels);
  read_param(private_handle, "impulse_scale", options.impulse_scale);
  read_param(private_handle, "velocity_scale", options.velocity_scale);
  return options;
}

MarkerNode::MarkerNode(const ::ros::NodeHandle& node_handle, const ::ros::NodeHandle& private_handle)
  : node_handle_(node_handle), builder_(marker_options_from_params(private_handle))
{
  const double max_rate = max_rate_from_params(private_handle);
  publisher_ = node_handle_.advertise<visualization_msgs::MarkerArray>("markers", kMarkerQueueSize, /*latch=*/true);
  subscriber_ = node_handle_.subscribe("world_state", kStateQueueSize, &MarkerNode::on_state, this);
  bool draggable = true;
  read_param(private_handle, "draggable", draggable);
  if (draggable)
  {
    double handle_alpha = kDefaultDragHandleAlpha;
    read_param(private_handle, "drag_handle_alpha", handle_alpha);
    dragger_ = std::make_unique<BodyDragger>(node_handle_, builder_.options().frame_id,
                                             static_cast<float>(handle_alpha));
  }
  timer_ = node_handle_.createWallTimer(::ros::WallDuration(1.0 / max_rate),
                                        [this](const ::ros::WallTimerEvent&) { on_tick(); });
}

void MarkerNode::on_state(const WorldState::ConstPtr& state)
{
  pending_ = state;
}

void MarkerNode::on_tick()
{
  if (!pending_)
  {
    return;
  }
  publisher_.publish(builder_.build(*pending_));
  if (dragger_)
  {
    dragger_->update(*pending_);
  }
  pending_.reset();
}

}  // namespace ros_interface
}  // namespace collision2d
