// The node's world: validated changes built on a copy, installed under one
// mutex only when they succeed; snapshots and the autosave.
#include "collision2d/ros/world_service.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

#include <ros/console.h>
#include <ros/time.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/reports.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/validation.h"
#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/standard_scenes.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
/// Autosave failures (a full disk) repeat every frame; log them at most this often.
constexpr double kAutosaveErrorLogPeriod = 10.0;  ///< s

bool ends_with(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Names are looked up in the scenes folder; anything that reads like a file
/// is loaded as one.
bool looks_like_path(const std::string& scene)
{
  return scene.find('/') != std::string::npos || ends_with(scene, ".yaml") || ends_with(scene, ".yml") ||
         ends_with(scene, ".collision");
}

bool contains(const std::vector<std::string>& names, const std::string& name)
{
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string join(const std::vector<std::string>& names)
{
  std::string out;
  for (const std::string& name : names)
  {
    out += (out.empty() ? "" : ", ") + name;
  }
  return out;
}

std::vector<std::string> scene_files(const std::string& dir)
{
  try
  {
    return scenes::list_scenes(dir);
  }
  catch (const std::exception&)
  {
    return {};  // a missing folder just means no scene files
  }
}

/// Every response type has success and message; nothing else is filled on failure.
template <typename Response>
void fail(Response& response, const std::string& message)
{
  response = Response();
  response.success = false;
  response.message = message;
}

template <typename Response, typename Action>
void serve(Response& response, const char* what, Action action)
{
  try
  {
    action();
  }
  catch (const InvalidRequest& e)
  {
    fail(response, e.what());
  }
  catch (const std::exception& e)
  {
    fail(response, std::string(what) + " failed: " + e.what());
  }
}

}  // namespace

WorldService::WorldService(WorldServiceOptions options) : options_(std::move(options))
{
}

void WorldService::set_change_listener(ChangeListener listener)
{
  Lock lock(mutex_);
  listener_ = std::move(listener);
}

void WorldService::step(const StepWorld::Request& request, StepWorld::Response& response)
{
  serve(response, "step", [&] {
    if (request.frames < 1 || request.frames > options_.max_frames_per_call)
    {
      reject("request", "frames = " + std::to_string(request.frames) + " must be in [1, " +
                            std::to_string(options_.max_frames_per_call) + "] (parameter ~max_frames_per_call)");
    }
    if (request.dt != 0.0)
    {
      require_positive(request.dt, "request", "dt");
    }
    Lock lock(mutex_);
    const Totals before = totals_of(world_);
    const StepReport report = step_locked(static_cast<int>(request.frames), request.dt);
    response.report = step_summary_to_msg(report, before, totals_of(world_));
    response.state = state_locked();
    response.success = true;
    response.message = "stepped " + std::to_string(request.frames) + " frames";
  });
}

void WorldService::load_scene(const LoadScene::Request& request, LoadScene::Response& response)
{
  serve(response, "load", [&] {
    load(request.scene);
    response.state = state();
    response.success = true;
    response.message = "loaded scene '" + response.state.scene + "' with " +
                       std::to_string(response.state.bodies.size()) + " bodies";
  });
  response.available = available_scenes();
}

void WorldService::set_world(const SetWorld::Request& request, SetWorld::Response& response)
{
  serve(response, "set", [&] {
    Scene scene;
    scene.bodies = scene_bodies_from_msgs(request.bodies, options_.max_bodies);
    if (!request.keep_settings)
    {
      scene.settings = world_settings_from_msg(request.settings);
    }
    Lock lock(mutex_);
    if (request.keep_settings)
    {
      scene.settings = world_.settings();
    }
    World world = make_world(scene);
    active_ = ActiveEffects{};
    origin_ = WorldClock{};
    commit(std::move(world), "", Change::NewWorld);
    response.state = state_locked();
    response.success = true;
    response.message = "world set with " + std::to_string(scene.bodies.size()) + " bodies";
  });
}

void WorldService::get_world(GetWorld::Response& response) const
{
  response.state = state();
  response.success = true;
  response.message = "";
}

void WorldService::add_body(const AddBody::Request& request, AddBody::Response& response)
{
  serve(response, "add", [&] {
    const std::string where = "body";
    const SceneBody added = scene_body_from_msg(request.body, where);
    Lock lock(mutex_);
    if (world_.body_count() >= options_.max_bodies)
    {
      reject(where, "the world already holds " + std::to_string(world_.body_count()) +
                        " bodies, the limit (parameter ~max_bodies)");
    }
    for (BodyId id : world_.body_ids())
    {
      if (world_.body(id).position() == added.body.position())
      {
        reject(where, "centre coincides with that of body id " + std::to_string(id) +
                          "; overlapping bodies with one centre have no contact normal");
      }
    }
    World next = world_;
    response.id = next.add_body(added.body, added.material);
    commit(std::move(next), scene_, Change::Edit);
    response.success = true;
    response.message = "added body id " + std::to_string(response.id);
  });
}

void WorldService::remove_body(const RemoveBody::Request& request, RemoveBody::Response& response)
{
  serve(response, "remove", [&] {
    Lock lock(mutex_);
    if (!world_.has_body(request.id))
    {
      reject("id " + std::to_string(request.id), "no body with this id in the world");
    }
    World next = world_;
    next.remove_body(request.id);
    commit(std::move(next), scene_, Change::Edit);
    response.success = true;
    response.message = "removed body id " + std::to_string(request.id);
  });
}

void WorldService::reset(std_srvs::Trigger::Response& response)
{
  Lock lock(mutex_);
  active_ = ActiveEffects{};
  origin_ = reset_origin_;
  commit(World(reset_world_), reset_scene_, Change::Edit);
  response.success = true;
  response.message = "reset to " + (reset_scene_.empty() ? std::string("the last world set") :
                                                           "scene '" + reset_scene_ + "'");
}

void WorldService::step_frame()
{
  Lock lock(mutex_);
  step_locked(1, 0.0);
}

void WorldService::set_settings(const WorldSettings& settings)
{
  Lock lock(mutex_);
  World next = world_;
  try
  {
    next.set_settings(settings);
  }
  catch (const std::invalid_argument& e)
  {
    reject("settings", e.what());
  }
  commit(std::move(next), scene_, Change::Edit);
}

WorldSettings WorldService::settings() const
{
  Lock lock(mutex_);
  return world_.settings();
}

WorldState WorldService::state() const
{
  Lock lock(mutex_);
  return state_locked();
}

std::vector<std::string> WorldService::available_scenes() const
{
  std::vector<std::string> names = scene_files(options_.scenes_dir);
  for (const std::string& name : scenes::standard_scene_names())
  {
    if (!contains(names, name))
    {
      names.push_back(name);
    }
  }
  return names;
}

Scene WorldService::find_scene(const std::string& scene) const
{
  if (scene.empty())
  {
    reject("scene", "no name given (known: " + join(available_scenes()) + ")");
  }
  try
  {
    if (looks_like_path(scene))
    {
      return scenes::load_scene_file(scene);
    }
    if (contains(scene_files(options_.scenes_dir), scene))
    {
      return scenes::load_named_scene(scene, options_.scenes_dir);
    }
    if (contains(scenes::standard_scene_names(), scene))
    {
      return scenes::make_standard_scene(scene);
    }
  }
  catch (const std::exception& e)
  {
    reject("scene '" + scene + "'", e.what());
  }
  reject("scene", "unknown scene '" + scene + "' (known: " + join(available_scenes()) + ")");
}

void WorldService::load(const std::string& name)
{
  Scene scene = find_scene(name);
  if (scene.name.empty())
  {
    scene.name = name;
  }
  check_bodies(scene);
  World world;
  try
  {
    world = make_world(scene);
  }
  catch (const std::invalid_argument& e)
  {
    reject("scene '" + scene.name + "'", e.what());
  }
  Lock lock(mutex_);
  active_ = ActiveEffects{};
  origin_ = WorldClock{};
  commit(std::move(world), scene.name, Change::NewWorld);
}

void WorldService::save_world(const SaveWorld::Request& request, SaveWorld::Response& response)
{
  serve(response, "save", [&] {
    response.path = snapshot_path_or_default(request.path);
    response.frame_count = save_snapshot(response.path);
    response.success = true;
    response.message = "saved frame " + std::to_string(response.frame_count) + " to " + response.path;
  });
}

void WorldService::load_world(const LoadWorld::Request& request, LoadWorld::Response& response)
{
  serve(response, "load", [&] {
    const std::string path = snapshot_path_or_default(request.path);
    load_snapshot(path);
    response.state = state();
    response.success = true;
    response.message = "restored frame " + std::to_string(response.state.frame_count) + " with " +
                       std::to_string(response.state.bodies.size()) + " bodies from " + path;
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
  check_bodies(snapshot.scene);
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
  origin_ = snapshot.clock;
  commit(std::move(world), snapshot.scene.name, Change::NewWorld);
}

void WorldService::check_bodies(const Scene& scene) const
{
  const std::string where = "scene '" + scene.name + "'";
  if (scene.bodies.size() > options_.max_bodies)
  {
    reject(where, std::to_string(scene.bodies.size()) + " bodies, more than the limit of " +
                      std::to_string(options_.max_bodies) + " (parameter ~max_bodies)");
  }
  std::vector<Vec2> centres;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    centres.push_back(scene.bodies[i].body.position());
    labels.push_back(where + " bodies[" + std::to_string(i) + "]" +
                     (scene.bodies[i].name.empty() ? "" : " (" + scene.bodies[i].name + ")"));
  }
  check_distinct_centres(centres, labels);
}

void WorldService::commit(World&& world, const std::string& scene, Change change)
{
  world_ = std::move(world);
  scene_ = scene;
  if (change == Change::NewWorld)
  {
    reset_world_ = world_;
    reset_scene_ = scene_;
    reset_origin_ = origin_;
  }
  if (listener_)
  {
    listener_(state_locked());
  }
  autosave_locked(change);
}

StepReport WorldService::step_locked(int frames, double dt)
{
  World next = world_;
  const bool override_dt = dt > 0.0;
  WorldSettings settings = next.settings();
  if (override_dt)
  {
    settings.dt = dt;
    try
    {
      next.set_settings(settings);
    }
    catch (const std::invalid_argument& e)
    {
      reject("request", e.what());
    }
  }
  const StepReport report = next.step(frames);
  if (override_dt)
  {
    // The dt of a request holds for that request only.
    settings.dt = world_.settings().dt;
    next.set_settings(settings);
  }
  active_ = report.active;
  commit(std::move(next), scene_, Change::Step);
  return report;
}

WorldState WorldService::state_locked() const
{
  WorldState msg = world_state_to_msg(world_, active_, scene_);
  const WorldClock clock = clock_locked();
  msg.frame_count = clock.frames;
  msg.sim_time = clock.time;
  msg.header.stamp = ::ros::Time::now();
  msg.header.frame_id = options_.frame_id;
  return msg;
}

WorldClock WorldService::clock_locked() const
{
  return WorldClock{origin_.frames + world_.frame_count(), origin_.time + world_.time()};
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
  const WorldSnapshot snapshot = take_snapshot(world_, scene_, clock_locked());
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
    ROS_ERROR_THROTTLE(kAutosaveErrorLogPeriod, "autosave failed: %s", e.what());
  }
}

}  // namespace ros_interface
}  // namespace collision2d
