// world_state, /tf and /clock of the world node.
#include "collision2d/ros/world_outputs.h"

#include <cmath>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <rosgraph_msgs/Clock.h>

#include "node_params.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr std::int64_t kMinStampStepNs = 1000;  // 1 us between two changes' stamps
constexpr std::uint32_t kClockQueueSize = 10;

geometry_msgs::TransformStamped body_transform(const BodyMsg& body, const std_msgs::Header& header,
                                               const std::string& prefix)
{
  geometry_msgs::TransformStamped transform;
  transform.header = header;
  transform.child_frame_id = prefix + std::to_string(body.id);
  transform.transform.translation.x = body.pose.x;
  transform.transform.translation.y = body.pose.y;
  transform.transform.rotation.z = std::sin(0.5 * body.pose.theta);
  transform.transform.rotation.w = std::cos(0.5 * body.pose.theta);
  return transform;
}

}  // namespace

::ros::Time SimClock::stamp(double world_time)
{
  const auto world_ns = static_cast<std::int64_t>(std::llround(world_time * 1e9));
  if (offset_ns_ + world_ns <= last_ns_)
  {
    offset_ns_ = last_ns_ + kMinStampStepNs - world_ns;
  }
  last_ns_ = offset_ns_ + world_ns;
  ::ros::Time time;
  time.fromNSec(static_cast<std::uint64_t>(last_ns_));
  return time;
}

WorldOutputOptions world_output_options_from_params(const ::ros::NodeHandle& private_handle)
{
  WorldOutputOptions options;
  read_param(private_handle, "publish_tf", options.publish_tf);
  read_param(private_handle, "publish_clock", options.publish_clock);
  read_param(private_handle, "body_frame_prefix", options.body_frame_prefix);
  return options;
}

WorldOutputs::WorldOutputs(::ros::NodeHandle& node_handle, WorldOutputOptions options) : options_(std::move(options))
{
  state_publisher_ = node_handle.advertise<WorldState>("world_state", 1, /*latch=*/true);
  if (options_.publish_clock)
  {
    clock_publisher_ = node_handle.advertise<rosgraph_msgs::Clock>("/clock", kClockQueueSize);
  }
  if (options_.publish_tf)
  {
    tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
  }
}

::ros::Time WorldOutputs::stamp(const WorldClock& clock)
{
  return options_.publish_clock ? sim_clock_.stamp(clock.time) : ::ros::Time::now();
}

void WorldOutputs::publish(const WorldState& state)
{
  state_publisher_.publish(state);
  if (tf_broadcaster_)
  {
    std::vector<geometry_msgs::TransformStamped> transforms;
    transforms.reserve(state.bodies.size());
    for (const BodyMsg& body : state.bodies)
    {
      transforms.push_back(body_transform(body, state.header, options_.body_frame_prefix));
    }
    tf_broadcaster_->sendTransform(transforms);
  }
  if (options_.publish_clock)
  {
    rosgraph_msgs::Clock clock;
    clock.clock = state.header.stamp;
    clock_publisher_.publish(clock);
  }
}

}  // namespace ros_interface
}  // namespace collision2d
