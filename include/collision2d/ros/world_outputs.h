// What the world node publishes after every change: the latched world_state,
// and where enabled each body's frame on /tf and the world's time on /clock.
//
// Stamps: with ~publish_clock, header.stamp (of world_state, /tf and /clock)
// is the node's sim clock, the world's sim time continued across loads and
// resets so it never runs backwards; without it, header.stamp is
// ::ros::Time::now() when the change was committed (wall time, or /clock's
// time when another node publishes it and /use_sim_time is set).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/world_snapshot.h"

namespace collision2d
{
namespace ros_interface
{
/// The world's sim time as a clock that never runs backwards: when the world
/// restarts (a load or reset sets its time back) the clock continues from its
/// last reading, and a change that does not advance the world's time still
/// gets a later stamp (1 us), so tf never sees a repeated stamp.
class SimClock
{
public:
  ::ros::Time stamp(double world_time);

private:
  std::int64_t offset_ns_ = 0;
  std::int64_t last_ns_ = -1;
};

struct WorldOutputOptions
{
  bool publish_tf = false;
  bool publish_clock = false;
  std::string body_frame_prefix = "body_";  ///< child frame: prefix + body id
};

/// ~publish_tf, ~publish_clock and ~body_frame_prefix.
WorldOutputOptions world_output_options_from_params(const ::ros::NodeHandle& private_handle);

class WorldOutputs
{
public:
  /// Advertises world_state in `node_handle`'s namespace and /clock.
  WorldOutputs(::ros::NodeHandle& node_handle, WorldOutputOptions options);

  /// header.stamp for a state of the world at `clock` (see the file comment).
  ::ros::Time stamp(const WorldClock& clock);
  void publish(const WorldState& state);
  const WorldOutputOptions& options() const { return options_; }

private:
  WorldOutputOptions options_;
  ::ros::Publisher state_publisher_;
  ::ros::Publisher clock_publisher_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;
  SimClock sim_clock_;
};

}  // namespace ros_interface
}  // namespace collision2d
