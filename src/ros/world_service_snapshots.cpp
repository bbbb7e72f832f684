// SaveWorld, LoadWorld and the autosave of the world service.
#include "collision2d/ros/world_service.h"

#include <exception>

#include <ros/console.h>

#include "collision2d/ros/printable.h"
#include "collision2d/ros/validation.h"
#include "service_reply.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
/// Autosave failures (a full disk) repeat every frame; log them at most this often.
constexpr double kAutosaveErrorLogPeriod = 10.0;  ///< s

}  // namespace

void WorldService::save_world(const SaveWorld::Request& request, SaveWorld::Response& response)
{
  serve(response, "save_world", [&] {
    response.path = snapshot_path_or_default(request.path);
    response.frame_count = save_snapshot(response.path);
    response.success = true;
    response.message = "saved frame " + std::to_string(response.frame_count) + " to " + response.path;
  });
}

void WorldService::load_world(const LoadWorld::Request& request, LoadWorld::Response& response)
{
  serve(response, "load_world", [&] {
    const std::string path = snapshot_path_or_default(request.path);
    load_snapshot(path);
    summarize_world(*committed(), request.return_state, response);
    response.success = true;
    response.message = "restored frame " + std::to_string(response.frame_count) + " with " +
                       std::to_string(response.body_count) + " bodies from " + path;
  });
}

std::uint64_t WorldService::save_snapshot(const std::string& path)
{
  const std::string file = snapshot_path_or_default(path);
  Lock lock(mutex_);
  return save_snapshot_locked(file);
}

void WorldService::load_snapshot(const std::string& path)
{
  const std::string file = snapshot_path_or_default(path);
  WorldSnapshot snapshot;
  try
  {
    snapshot = load_snapshot_file(file);
  }
  catch (const std::exception& e)
  {
    reject("snapshot", e.what());
  }
  check_bodies(snapshot.scene, snapshot.saved_world);
  World world;
  try
  {
    world = restore_world(snapshot);
  }
  catch (const std::invalid_argument& e)
  {
    reject("snapshot '" + file + "'", e.what());
  }
  Lock lock(mutex_);
  active_ = ActiveEffects{};
  commit(std::move(world), snapshot.scene.name, Change::NewWorld);
  ROS_INFO_NAMED(kWorldLogger, "restored frame %llu of scene '%s' with %zu bodies from %s",
                 static_cast<unsigned long long>(snapshot.clock.frames), printable_text(snapshot.scene.name).c_str(),
                 world_.body_count(), printable_text(file).c_str());
}

std::string WorldService::snapshot_path_or_default(const std::string& path) const
{
  if (!path.empty())
  {
    return path;
  }
  if (options_.snapshot_path.empty())
  {
    reject("path", "no path given and no default (parameter ~snapshot_path)");
  }
  return options_.snapshot_path;
}

std::uint64_t WorldService::save_snapshot_locked(const std::string& path) const
{
  WorldSnapshot snapshot = take_snapshot(world_, scene_);
  // A hold is the dragging client's, not the world's: a body held now is
  // saved as what it is when released, as no restore can release it.
  for (std::size_t i = 0; i < snapshot.ids.size(); ++i)
  {
    const auto held = held_.find(snapshot.ids[i]);
    if (held != held_.end())
    {
      snapshot.scene.bodies[i].body.set_type(held->second);
    }
  }
  try
  {
    save_snapshot_file(snapshot, path);
  }
  catch (const std::exception& e)
  {
    reject("snapshot", e.what());
  }
  return snapshot.clock.frames;
}

void WorldService::autosave_locked(Change change)
{
  const std::uint64_t period = options_.autosave_period;
  if (period == 0 || options_.snapshot_path.empty())
  {
    return;
  }
  const std::uint64_t frame = clock_locked().frames;
  if (change == Change::Step && frame / period == last_autosave_frame_ / period)
  {
    return;  // no multiple of the period completed by this step
  }
  try
  {
    last_autosave_frame_ = save_snapshot_locked(options_.snapshot_path);
  }
  catch (const std::exception& e)
  {
    ROS_ERROR_THROTTLE_NAMED(kAutosaveErrorLogPeriod, kWorldLogger, "autosave failed: %s", e.what());
  }
}

}  // namespace ros_interface
}  // namespace collision2d
