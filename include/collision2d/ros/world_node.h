// The collision2d world node: parameters, services, the latched world_state
// topic, the free-running timer and dynamic_reconfigure around a WorldService
// and the stateless ResolveContacts handler.
//
// Logging: rosconsole loggers ros.collision2d.<name>: "node" (start-up),
// "requests" (a WARN for every refused request or setting), "world" (loads,
// resets, edits, settings changes), "step" (DEBUG, every step).
//
// Threads: an AsyncSpinner with ~threads threads serves the callbacks, so
// ResolveContacts calls run in parallel (they share nothing but a copy of the
// node's solver settings); world changes serialize on the WorldService mutex,
// and reads (get_world) take only the committed state, never waiting for a step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <collision2d/Collision2dConfig.h>
#include "collision2d/ros/messages.h"

#include "collision2d/ros/world_outputs.h"
#include "collision2d/ros/world_service.h"

namespace collision2d
{
namespace ros_interface
{
class WorldNode
{
public:
  /// Reads the parameters, restores the snapshot (~restore_on_start) or
  /// loads ~scene, and starts serving (once spun).
  WorldNode(const ::ros::NodeHandle& node_handle, const ::ros::NodeHandle& private_handle);

  /// Serves with ~threads threads until ROS shuts down.
  void spin();

private:
  /// True when ~snapshot_path was restored; false (logged) when there is
  /// none, restoring is off, or the file is unreadable.
  bool restore_snapshot();
  void load_initial_scene();
  void advertise_services();
  void start_reconfigure();
  void start_timer();
  /// The INFO line at start: scene, bodies, main settings, outputs, services.
  void log_start_summary() const;
  void on_reconfigure(Collision2dConfig& config, std::uint32_t level);
  /// Shows the world's settings in dynamic_reconfigure after the world was replaced.
  void show_world_settings();
  SolverSettings solver_settings() const;

  ::ros::NodeHandle node_handle_;
  ::ros::NodeHandle private_handle_;
  int threads_;
  double rate_;
  WorldOutputs outputs_;
  WorldService world_;

  mutable std::mutex solver_mutex_;  ///< guards only the copy of solver_settings_
  SolverSettings solver_settings_;

  std::vector<::ros::ServiceServer> services_;
  ::ros::WallTimer timer_;

  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<Collision2dConfig>> reconfigure_;
  Collision2dConfig config_;  ///< last config seen, guarded by reconfigure_mutex_
  bool reconfigure_started_ = false;
};

}  // namespace ros_interface
}  // namespace collision2d
