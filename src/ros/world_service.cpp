// The node's world: validated changes built on a copy, installed under one
// mutex only when they succeed, and the committed state reads are served from.
#include "collision2d/ros/world_service.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

#include <ros/console.h>
#include <ros/time.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/printable.h"
#include "collision2d/ros/reports.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/validation.h"
#include "service_reply.h"

namespace collision2d
{
namespace ros_interface
{
WorldService::WorldService(WorldServiceOptions options) : options_(std::move(options))
{
  committed_ = std::make_shared<const WorldState>(state_locked());
  committed_settings_ = world_.settings();
}

void WorldService::set_change_listener(ChangeListener listener)
{
  Lock lock(mutex_);
  listener_ = std::move(listener);
}

void WorldService::set_stamp_source(StampSource stamp)
{
  Lock lock(mutex_);
  stamp_ = std::move(stamp);
  auto state = std::make_shared<WorldState>(*committed());
  state->header.stamp = stamp_ ? stamp_(clock_locked()) : ::ros::Time::now();
  std::lock_guard<std::mutex> committed_lock(committed_mutex_);
  committed_ = std::move(state);
}

void WorldService::step(const StepWorld::Request& request, StepWorld::Response& response)
{
  serve(response, "step_world", [&] {
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
    summarize_world(*committed(), request.return_state, response);
    response.success = true;
    response.message = "stepped " + std::to_string(request.frames) + " frames";
  });
}

void WorldService::load_scene(const LoadScene::Request& request, LoadScene::Response& response)
{
  serve(response, "load_scene", [&] {
    load(request.scene);
    const std::shared_ptr<const WorldState> loaded = committed();
    summarize_world(*loaded, request.return_state, response);
    response.success = true;
    response.message = "loaded scene '" + loaded->scene + "' with " + std::to_string(loaded->bodies.size()) + " bodies";
  });
  response.available = available_scenes();
}

void WorldService::set_world(const SetWorld::Request& request, SetWorld::Response& response)
{
  serve(response, "set_world", [&] {
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
    commit(std::move(world), "", Change::NewWorld);
    summarize_world(*committed(), request.return_state, response);
    response.success = true;
    response.message = "world set with " + std::to_string(scene.bodies.size()) + " bodies";
    ROS_INFO_NAMED(kWorldLogger, "%s; %s", response.message.c_str(), settings_summary(world_.settings()).c_str());
  });
}

void WorldService::get_world(GetWorld::Response& response) const
{
  response.state = *committed();
  response.success = true;
  response.message = "";
}

void WorldService::add_body(const AddBody::Request& request, AddBody::Response& response)
{
  serve(response, "add_body", [&] {
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
    ROS_INFO_NAMED(kWorldLogger, "%s", response.message.c_str());
  });
}

void WorldService::remove_body(const RemoveBody::Request& request, RemoveBody::Response& response)
{
  serve(response, "remove_body", [&] {
    Lock lock(mutex_);
    if (!world_.has_body(request.id))
    {
      reject("id " + std::to_string(request.id), "no body with this id in the world");
    }
    World next = world_;
    next.remove_body(request.id);
    held_.erase(request.id);
    commit(std::move(next), scene_, Change::Edit);
    response.success = true;
    response.message = "removed body id " + std::to_string(request.id);
    ROS_INFO_NAMED(kWorldLogger, "%s", response.message.c_str());
  });
}

void WorldService::reset(std_srvs::Trigger::Response& response)
{
  Lock lock(mutex_);
  active_ = ActiveEffects{};
  held_.clear();
  commit(World(reset_world_), reset_scene_, Change::Edit);
  response.success = true;
  response.message = printable_text("reset to " + (reset_scene_.empty() ? std::string("the last world set") :
                                                                          "scene '" + reset_scene_ + "'"));
  ROS_INFO_NAMED(kWorldLogger, "%s (%zu bodies)", response.message.c_str(), world_.body_count());
}

void WorldService::step_frame()
{
  Lock lock(mutex_);
  step_locked(1, 0.0);
}

WorldSettings WorldService::edit_settings(const std::function<WorldSettings(const WorldSettings&)>& change)
{
  Lock lock(mutex_);
  const WorldSettings settings = change(world_.settings());
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
  ROS_INFO_NAMED(kWorldLogger, "world settings changed: %s", settings_summary(settings).c_str());
  return settings;
}

WorldSettings WorldService::settings() const
{
  std::lock_guard<std::mutex> lock(committed_mutex_);
  return committed_settings_;
}

WorldState WorldService::state() const
{
  return *committed();
}

std::shared_ptr<const WorldState> WorldService::committed() const
{
  std::lock_guard<std::mutex> lock(committed_mutex_);
  return committed_;
}

void WorldService::commit(World&& world, const std::string& scene, Change change)
{
  world_ = std::move(world);
  scene_ = scene;
  after_change(change);
}

void WorldService::after_change(Change change)
{
  if (change == Change::NewWorld)
  {
    reset_world_ = world_;
    reset_scene_ = scene_;
    held_.clear();
  }
  auto state = std::make_shared<const WorldState>(state_locked());
  {
    std::lock_guard<std::mutex> lock(committed_mutex_);
    committed_ = state;
    committed_settings_ = world_.settings();
  }
  if (listener_)
  {
    listener_(*state);
  }
  autosave_locked(change);
}

StepReport WorldService::step_locked(int frames, double dt)
{
  // World::step is all-or-nothing (a failed step puts the world back), so the
  // world steps in place: only the dt a request overrides is set back.
  const WorldSettings settings = world_.settings();
  if (dt > 0.0)
  {
    WorldSettings with_dt = settings;
    with_dt.dt = dt;
    try
    {
      world_.set_settings(with_dt);
    }
    catch (const std::invalid_argument& e)
    {
      reject("request", e.what());
    }
  }
  StepReport report;
  try
  {
    report = world_.step(frames);
  }
  catch (...)
  {
    world_.set_settings(settings);
    throw;
  }
  // The dt of a request holds for that request only.
  world_.set_settings(settings);
  active_ = report.active;
  after_change(Change::Step);
  ROS_DEBUG_NAMED(kStepLogger, "stepped %d frames to frame %llu: %zu contacts, max penetration %s m, %zu asleep",
                  frames, static_cast<unsigned long long>(clock_locked().frames), world_.contacts().size(),
                  format_number(report.max_penetration).c_str(), static_cast<std::size_t>(report.sleeping_bodies));
  return report;
}

WorldState WorldService::state_locked() const
{
  WorldState msg = world_state_to_msg(world_, active_, scene_);
  const WorldClock clock = clock_locked();
  msg.frame_count = clock.frames;
  msg.sim_time = clock.time;
  msg.header.stamp = stamp_ ? stamp_(clock) : ::ros::Time::now();
  msg.header.frame_id = options_.frame_id;
  return msg;
}

WorldClock WorldService::clock_locked() const
{
  return WorldClock{world_.frame_count(), world_.time()};
}

}  // namespace ros_interface
}  // namespace collision2d
