// The node's world behind one mutex. Every change is validated and built on a
// copy (World is a value type) that replaces the world only on success, so a
// failed request leaves the world exactly as it was. Uses the message types
// but no node handle, so it is unit-testable without a master.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "collision2d/ros/messages.h"
#include <std_srvs/Trigger.h>

#include "collision2d/scene.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace ros_interface
{
struct WorldServiceOptions
{
  std::size_t max_bodies = 5000;             ///< largest world a request may build
  std::uint32_t max_frames_per_call = 10000;  ///< largest StepWorld.frames
  std::string scenes_dir;                    ///< where LoadScene looks up names
  std::string frame_id = "map";              ///< WorldState.header.frame_id
};

class WorldService
{
public:
  /// Called with the new state after every change (steps included), while
  /// the lock is held, so listeners see the states in order.
  using ChangeListener = std::function<void(const WorldState&)>;

  explicit WorldService(WorldServiceOptions options);

  void set_change_listener(ChangeListener listener);
  const WorldServiceOptions& options() const { return options_; }

  // Service handlers: never throw; bad input gives success = false and a
  // message naming the body and field, and the world stays as it was.
  void step(const StepWorld::Request& request, StepWorld::Response& response);
  void load_scene(const LoadScene::Request& request, LoadScene::Response& response);
  void set_world(const SetWorld::Request& request, SetWorld::Response& response);
  void get_world(GetWorld::Response& response) const;
  void add_body(const AddBody::Request& request, AddBody::Response& response);
  void remove_body(const RemoveBody::Request& request, RemoveBody::Response& response);
  /// Back to the world as the last LoadScene or SetWorld (or the start) made it.
  void reset(std_srvs::Trigger::Response& response);

  /// One frame of the world's dt (the free-running timer). Throws on failure.
  void step_frame();
  /// Throws InvalidRequest naming the field; the world is unchanged then.
  void set_settings(const WorldSettings& settings);
  WorldSettings settings() const;
  WorldState state() const;
  /// Shipped scene names: files in scenes_dir, then the built-in standard
  /// scenes not shadowed by a file.
  std::vector<std::string> available_scenes() const;
  /// The scene named `scene` (or at that path). Throws InvalidRequest.
  Scene find_scene(const std::string& scene) const;
  /// Loads a scene as the current and reset world. Throws InvalidRequest.
  void load(const std::string& scene);

private:
  using Lock = std::lock_guard<std::mutex>;

  /// Checks a world about to replace the current one.
  void check_bodies(const Scene& scene) const;
  /// Installs `world` (the caller holds the lock) and tells the listener.
  void commit(World&& world, const std::string& scene, bool as_reset_point);
  StepReport step_locked(int frames, double dt);
  WorldState state_locked() const;

  WorldServiceOptions options_;
  ChangeListener listener_;
  mutable std::mutex mutex_;
  World world_;
  std::string scene_;
  ActiveEffects active_;
  World reset_world_;
  std::string reset_scene_;
};

}  // namespace ros_interface
}  // namespace collision2d
