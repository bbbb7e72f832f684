// How the world service answers (private to src/ros): every failure is a
// response with success = false, a printable message and a WARN.
#pragma once

#include <cstdint>
#include <exception>
#include <string>

#include <ros/console.h>

#include "collision2d/ros/messages.h"
#include "collision2d/ros/printable.h"
#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
/// rosconsole loggers (ros.collision2d.<name>): refused requests, world changes, steps.
constexpr const char* kRequestsLogger = "requests";
constexpr const char* kWorldLogger = "world";
constexpr const char* kStepLogger = "step";

/// Every response type has success and message; nothing else is filled on failure.
template <typename Response>
void fail(Response& response, const char* service, const std::string& message)
{
  response = Response();
  response.success = false;
  response.message = printable_text(message);
  ROS_WARN_NAMED(kRequestsLogger, "%s refused: %s", service, response.message.c_str());
}

/// Runs `action`, which fills `response` or throws: InvalidRequest names the
/// body and field, anything else is reported as the service failing.
template <typename Response, typename Action>
void serve(Response& response, const char* service, Action action)
{
  try
  {
    action();
    response.message = printable_text(response.message);
  }
  catch (const InvalidRequest& e)
  {
    fail(response, service, e.what());
  }
  catch (const std::exception& e)
  {
    fail(response, service, std::string(service) + " failed: " + e.what());
  }
}

/// The summary of the world a request left (frames, time, bodies) and, when
/// the client asked for it, the whole state: an answer that fits a terminal.
template <typename Response>
void summarize_world(const WorldState& state, bool return_state, Response& response)
{
  response.frame_count = state.frame_count;
  response.sim_time = state.sim_time;
  response.body_count = static_cast<std::uint32_t>(state.bodies.size());
  if (return_state)
  {
    response.state.push_back(state);
  }
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
