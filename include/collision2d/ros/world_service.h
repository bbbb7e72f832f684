// The node's world behind one mutex. Every change is validated and built on a
// copy (World is a value type) that replaces the world only on success, so a
// failed request leaves the world exactly as it was. Uses the message types
// but no node handle, so it is unit-testable without a master.
//
// Reads never wait for a step: each change also stores the resulting
// WorldState (the committed state) under its own small mutex, and GetWorld,
// state() and settings() read that, while steps and edits serialize on the
// world's mutex.
//
// Snapshots: SaveWorld/LoadWorld write and read world_snapshot.h files, and
// with an autosave period the service saves after every change and after
// each step that completes a multiple of the period, so a restarted node
// that restores the file loses at most the frames since that save.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ros/time.h>

#include "collision2d/ros/messages.h"
// After messages.h: these reach Body only through WorldState, already read.
#include <std_srvs/Trigger.h>

#include "collision2d/ros/world_snapshot.h"
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
  std::string snapshot_path;                 ///< SaveWorld/LoadWorld default, autosave file
  std::uint32_t autosave_period = 0;         ///< frames between autosaves; 0 = off
};

class WorldService
{
public:
  /// Called with the new state after every change (steps included), while
  /// the lock is held, so listeners see the states in order.
  using ChangeListener = std::function<void(const WorldState&)>;
  /// The header.stamp of the state after a change, given the world's clock
  /// then; called in the order of the changes. Default: ::ros::Time::now().
  using StampSource = std::function<::ros::Time(const WorldClock&)>;

  explicit WorldService(WorldServiceOptions options);

  void set_change_listener(ChangeListener listener);
  /// Also restamps the current state, so set it before the first listener.
  void set_stamp_source(StampSource stamp);
  const WorldServiceOptions& options() const { return options_; }

  // Service handlers: never throw; bad input gives success = false and a
  // message naming the body and field, and the world stays as it was.
  void step(const StepWorld::Request& request, StepWorld::Response& response);
  void load_scene(const LoadScene::Request& request, LoadScene::Response& response);
  void set_world(const SetWorld::Request& request, SetWorld::Response& response);
  void get_world(GetWorld::Response& response) const;
  void add_body(const AddBody::Request& request, AddBody::Response& response);
  void remove_body(const RemoveBody::Request& request, RemoveBody::Response& response);
  /// One body's pose and twist; with hold it moves as KINEMATIC until a call
  /// without hold (world_service_bodies.cpp).
  void set_body_state(const SetBodyState::Request& request, SetBodyState::Response& response);
  /// Back to the world as the last LoadScene, SetWorld or LoadWorld (or the start) made it.
  void reset(std_srvs::Trigger::Response& response);
  void save_world(const SaveWorld::Request& request, SaveWorld::Response& response);
  void load_world(const LoadWorld::Request& request, LoadWorld::Response& response);

  /// One frame of the world's dt (the free-running timer). Throws on failure.
  void step_frame();
  /// Replaces the settings by change(the settings now), computed under the
  /// world's lock so no other edit lands in between; returns the new settings.
  /// Throws InvalidRequest naming the field (from change or the table); the
  /// world is unchanged then.
  WorldSettings edit_settings(const std::function<WorldSettings(const WorldSettings&)>& change);
  /// The committed settings and state: never wait for a step in progress.
  WorldSettings settings() const;
  WorldState state() const;
  /// Shipped scene names: files in scenes_dir, then the built-in standard
  /// scenes not shadowed by a file.
  std::vector<std::string> available_scenes() const;
  /// The scene named `scene` (or at that path). Throws InvalidRequest.
  Scene find_scene(const std::string& scene) const;
  /// Loads a scene as the current and reset world. Throws InvalidRequest.
  void load(const std::string& scene);
  /// Writes the world to `path` ("" = options().snapshot_path) and returns
  /// the frame count saved. Throws InvalidRequest naming the file.
  std::uint64_t save_snapshot(const std::string& path);
  /// Replaces the world by the snapshot (or YAML scene) at `path` ("" =
  /// options().snapshot_path), clock and ids included. Throws InvalidRequest;
  /// the world is unchanged then.
  void load_snapshot(const std::string& path);

private:
  using Lock = std::lock_guard<std::mutex>;

  enum class Change
  {
    Step,      ///< frames advanced: autosaves when a period completes
    Edit,      ///< same world edited (bodies, settings, reset): autosaves
    NewWorld,  ///< replaced (load, set, restore): also the new reset point; autosaves
  };

  /// Checks a world about to replace the current one: the body limit, and
  /// for a scene that no two centres coincide. A saved world may hold such
  /// bodies (stepping can bring them there, and the world steps them on).
  void check_bodies(const Scene& scene, bool saved_world) const;
  /// Installs `world` (the caller holds the lock), tells
  /// the listener and autosaves.
  void commit(World&& world, const std::string& scene, Change change);
  /// What every change does after it: publish and keep the committed state, autosave.
  void after_change(Change change);
  StepReport step_locked(int frames, double dt);
  WorldState state_locked() const;
  /// The state last committed; shared, so readers copy it outside any lock.
  std::shared_ptr<const WorldState> committed() const;

  /// Frames and time since the scene was loaded, across restores: the
  /// world's own clock, which a restore sets to the saved one.
  WorldClock clock_locked() const;
  std::string snapshot_path_or_default(const std::string& path) const;
  std::uint64_t save_snapshot_locked(const std::string& path) const;
  /// Failures are logged, never thrown: a full disk must not stop the world.
  void autosave_locked(Change change);

  WorldServiceOptions options_;
  ChangeListener listener_;
  mutable std::mutex mutex_;
  World world_;
  std::string scene_;
  ActiveEffects active_;
  World reset_world_;
  std::string reset_scene_;
  std::uint64_t last_autosave_frame_ = 0;
  /// Own type of each body held as kinematic by set_body_state.
  std::map<BodyId, BodyType> held_;
  StampSource stamp_;

  mutable std::mutex committed_mutex_;  ///< guards only the two below, never held long
  std::shared_ptr<const WorldState> committed_;
  WorldSettings committed_settings_;
};

}  // namespace ros_interface
}  // namespace collision2d
