// Parameters, advertising and dynamic_reconfigure for the world node.
#include "collision2d/ros/world_node.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/printable.h"
#include "collision2d/ros/reconfigure.h"
#include "collision2d/ros/resolve_contacts.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/validation.h"
#include "collision2d/scenes/scene_file.h"
#include "node_params.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr int kDefaultThreads = 4;
constexpr int kDefaultMaxBodies = 5000;
constexpr int kDefaultMaxFramesPerCall = 10000;
constexpr int kDefaultAutosavePeriod = 0;  ///< frames; 0 = off
/// ~rate below this (Hz) would tick less than once in 1000 s: refused.
constexpr double kMinRate = 1e-3;
/// rosconsole loggers ros.collision2d.<name> (see world_node.h).
constexpr const char* kNodeLogger = "node";
constexpr const char* kRequestsLogger = "requests";

template <typename T>
T positive_param(const ::ros::NodeHandle& handle, const std::string& name, T fallback)
{
  T value = fallback;
  read_param(handle, name, value);
  if (!(value > T{0}))
  {
    ROS_WARN_NAMED(kNodeLogger, "~%s must be > 0; using %s", name.c_str(), std::to_string(fallback).c_str());
    return fallback;
  }
  return value;
}

/// ~rate (Hz): 0 steps only on request; otherwise a finite rate of at
/// least kMinRate. Anything else steps on request, with a WARN.
double rate_param(const ::ros::NodeHandle& handle)
{
  double rate = 0.0;
  read_param(handle, "rate", rate);
  if (rate != 0.0 && !(std::isfinite(rate) && rate >= kMinRate))
  {
    ROS_WARN_NAMED(kNodeLogger, "~rate = %g must be 0 (step on request) or a finite rate >= %g Hz; stepping on request",
                   rate, kMinRate);
    return 0.0;
  }
  return rate;
}

/// $ROS_HOME/collision2d/<node name>.snapshot.yaml ($ROS_HOME defaults to
/// ~/.ros, as for roslaunch's logs): one file per node name, so two worlds
/// never restore each other's snapshot.
std::string default_snapshot_path()
{
  const char* ros_home = std::getenv("ROS_HOME");
  const char* home = std::getenv("HOME");
  const std::filesystem::path base = ros_home != nullptr ? std::filesystem::path(ros_home) :
                                     home != nullptr     ? std::filesystem::path(home) / ".ros" :
                                                           std::filesystem::path(".");
  std::string name = ::ros::this_node::getName();
  std::replace(name.begin(), name.end(), '/', '_');
  name.erase(0, name.find_first_not_of('_'));
  return (base / "collision2d" / (name + ".snapshot.yaml")).string();
}

std::uint32_t autosave_period_param(const ::ros::NodeHandle& handle)
{
  int period = kDefaultAutosavePeriod;
  read_param(handle, "autosave_period", period);
  if (period < 0)
  {
    ROS_WARN_NAMED(kNodeLogger, "~autosave_period must be >= 0 frames; autosave off");
    return 0;
  }
  return static_cast<std::uint32_t>(period);
}

WorldServiceOptions options_from_params(const ::ros::NodeHandle& handle)
{
  WorldServiceOptions options;
  options.max_bodies = static_cast<std::size_t>(positive_param(handle, "max_bodies", kDefaultMaxBodies));
  options.max_frames_per_call =
      static_cast<std::uint32_t>(positive_param(handle, "max_frames_per_call", kDefaultMaxFramesPerCall));
  options.scenes_dir = COLLISION2D_DEFAULT_SCENES_DIR;
  read_param(handle, "scenes_dir", options.scenes_dir);
  options.frame_id = "map";
  read_param(handle, "frame_id", options.frame_id);
  options.snapshot_path = default_snapshot_path();
  read_param(handle, "snapshot_path", options.snapshot_path);
  options.autosave_period = autosave_period_param(handle);
  return options;
}

/// roscpp service callbacks return false only when no response should be
/// sent; every collision2d failure is a response with success = false.
template <typename Service, typename Handler>
::ros::ServiceServer advertise(::ros::NodeHandle& handle, const std::string& name, Handler handler)
{
  using Request = typename Service::Request;
  using Response = typename Service::Response;
  return handle.advertiseService<Request, Response>(name, [handler](Request& request, Response& response) {
    handler(request, response);
    return true;
  });
}

}  // namespace

WorldNode::WorldNode(const ::ros::NodeHandle& node_handle, const ::ros::NodeHandle& private_handle)
  : node_handle_(node_handle)
  , private_handle_(private_handle)
  , threads_(positive_param(private_handle, "threads", kDefaultThreads))
  , rate_(rate_param(private_handle))
  , outputs_(node_handle_, world_output_options_from_params(private_handle))
  , world_(options_from_params(private_handle))
{
  // Scene and snapshot files naming a setting's former name say so on /rosout.
  scenes::set_warning_handler([](const std::string& message) { ROS_WARN("%s", message.c_str()); });
  world_.set_stamp_source([this](const WorldClock& clock) { return outputs_.stamp(clock); });
  world_.set_change_listener([this](const WorldState& state) { outputs_.publish(state); });

  if (!restore_snapshot())
  {
    load_initial_scene();
  }
  advertise_services();
  start_reconfigure();
  start_timer();
  log_start_summary();
}

void WorldNode::log_start_summary() const
{
  const WorldState state = world_.state();
  const WorldOutputOptions& outputs = outputs_.options();
  std::string services;
  for (const ::ros::ServiceServer& service : services_)
  {
    services += (services.empty() ? "" : ", ") + service.getService();
  }
  ROS_INFO_NAMED(kNodeLogger, "world node %s: scene '%s' with %zu bodies at frame %llu; %s; rate %s Hz (%s)",
                 ::ros::this_node::getName().c_str(), printable_text(state.scene).c_str(), state.bodies.size(),
                 static_cast<unsigned long long>(state.frame_count), settings_summary(world_.settings()).c_str(),
                 format_number(rate_).c_str(), rate_ > 0.0 ? "free-running" : "steps on request");
  ROS_INFO_NAMED(kNodeLogger, "frame '%s'; tf %s; /clock %s; world_state on %s; services: %s",
                 world_.options().frame_id.c_str(),
                 outputs.publish_tf ? ("on, child frames " + outputs.body_frame_prefix + "<id>").c_str() : "off",
                 outputs.publish_clock ? "on (header.stamp is sim time)" : "off (header.stamp is ros::Time::now())",
                 node_handle_.resolveName("world_state").c_str(), services.c_str());
}

bool WorldNode::restore_snapshot()
{
  bool restore = world_.options().autosave_period > 0;
  read_param(private_handle_, "restore_on_start", restore);
  const std::string& path = world_.options().snapshot_path;
  std::error_code ignored;
  if (!restore || !std::filesystem::exists(path, ignored))
  {
    return false;
  }
  try
  {
    world_.load_snapshot(path);
    ROS_INFO_NAMED(kNodeLogger, "restored the world at frame %lu from %s", static_cast<unsigned long>(world_.state().frame_count),
             path.c_str());
    return true;
  }
  catch (const std::exception& e)
  {
    ROS_ERROR_NAMED(kNodeLogger, "snapshot not restored, loading ~scene instead: %s", e.what());
    return false;
  }
}

void WorldNode::load_initial_scene()
{
  std::string scene;
  read_param(private_handle_, "scene", scene);
  if (scene.empty())
  {
    return;
  }
  try
  {
    world_.load(scene);
  }
  catch (const std::exception& e)
  {
    ROS_ERROR_NAMED(kNodeLogger, "initial scene not loaded, starting with an empty world: %s", e.what());
  }
}

void WorldNode::spin()
{
  ::ros::AsyncSpinner spinner(threads_);
  spinner.start();
  ::ros::waitForShutdown();
}

void WorldNode::advertise_services()
{
  ::ros::NodeHandle& nh = node_handle_;
  services_.push_back(advertise<ResolveContacts>(nh, "resolve_contacts", [this](auto& request, auto& response) {
    resolve_contacts(request, solver_settings(), world_.options().max_bodies, response);
  }));
  services_.push_back(advertise<StepWorld>(
      nh, "step_world", [this](auto& request, auto& response) { world_.step(request, response); }));
  services_.push_back(advertise<GetWorld>(
      nh, "get_world", [this](auto&, auto& response) { world_.get_world(response); }));
  services_.push_back(advertise<AddBody>(
      nh, "add_body", [this](auto& request, auto& response) { world_.add_body(request, response); }));
  services_.push_back(advertise<SetBodyState>(
      nh, "set_body_state", [this](auto& request, auto& response) { world_.set_body_state(request, response); }));
  services_.push_back(advertise<RemoveBody>(
      nh, "remove_body", [this](auto& request, auto& response) { world_.remove_body(request, response); }));
  // Replacing the world brings the new world's settings, which
  // dynamic_reconfigure then shows.
  services_.push_back(advertise<LoadScene>(nh, "load_scene", [this](auto& request, auto& response) {
    world_.load_scene(request, response);
    show_world_settings();
  }));
  services_.push_back(advertise<SetWorld>(nh, "set_world", [this](auto& request, auto& response) {
    world_.set_world(request, response);
    show_world_settings();
  }));
  services_.push_back(advertise<std_srvs::Trigger>(nh, "reset_world", [this](auto&, auto& response) {
    world_.reset(response);
    show_world_settings();
  }));
  services_.push_back(advertise<SaveWorld>(
      nh, "save_world", [this](auto& request, auto& response) { world_.save_world(request, response); }));
  services_.push_back(advertise<LoadWorld>(nh, "load_world", [this](auto& request, auto& response) {
    world_.load_world(request, response);
    show_world_settings();
  }));
}

void WorldNode::start_reconfigure()
{
  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<Collision2dConfig>>(reconfigure_mutex_, private_handle_);
  // The first callback carries the parameters (config/collision2d.yaml): it
  // sets the solver settings, but the world keeps its scene's settings.
  reconfigure_->setCallback([this](Collision2dConfig& config, std::uint32_t level) { on_reconfigure(config, level); });
  reconfigure_started_ = true;
  show_world_settings();
}

void WorldNode::start_timer()
{
  if (rate_ <= 0.0)
  {
    return;  // steps only on request
  }
  timer_ = node_handle_.createWallTimer(::ros::WallDuration(1.0 / rate_), [this](const ::ros::WallTimerEvent&) {
    try
    {
      world_.step_frame();
    }
    catch (const std::exception& e)
    {
      ROS_ERROR_THROTTLE_NAMED(1.0, "step", "free-running step failed: %s", e.what());
    }
  });
}

void WorldNode::on_reconfigure(Collision2dConfig& config, std::uint32_t level)
{
  // A refused value is put back in `config`, which the server then publishes.
  if (level & kSolverLevel)
  {
    const SolverSettings settings = accept_solver_config(config, solver_settings());
    std::lock_guard<std::mutex> lock(solver_mutex_);
    solver_settings_ = settings;
  }
  if (reconfigure_started_ && (level & kWorldLevel))
  {
    accept_world_config(config, config_, [this](const auto& change) { return world_.edit_settings(change); });
  }
  config_ = config;
}

void WorldNode::show_world_settings()
{
  if (!reconfigure_)
  {
    return;
  }
  boost::recursive_mutex::scoped_lock lock(reconfigure_mutex_);
  world_settings_to_config(world_.settings(), config_);
  reconfigure_->updateConfig(config_);
}

SolverSettings WorldNode::solver_settings() const
{
  std::lock_guard<std::mutex> lock(solver_mutex_);
  return solver_settings_;
}

}  // namespace ros_interface
}  // namespace collision2d
