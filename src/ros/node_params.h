// Reading a node's private parameters (private to src/ros). NodeHandle::param
// keeps the default without a word when a parameter has the wrong type
// (`_rate:=fast`, `_max_bodies:=many`); read_param says so on /rosout.
// (roscpp reads a number into an integer rounded, `_threads:=2.5` as 3.)
#pragma once

#include <string>

#include <ros/console.h>
#include <ros/node_handle.h>

#include "collision2d/ros/printable.h"
#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
inline std::string param_text(double value) { return format_number(value); }
inline std::string param_text(int value) { return std::to_string(value); }
inline std::string param_text(bool value) { return value ? "true" : "false"; }
inline std::string param_text(const std::string& value) { return "'" + printable_text(value) + "'"; }

inline const char* param_kind(double) { return "a number"; }
inline const char* param_kind(int) { return "an integer"; }
inline const char* param_kind(bool) { return "true or false"; }
inline const char* param_kind(const std::string&) { return "a string"; }

/// ~name into `value`, which holds the default; a parameter of another type
/// keeps the default with a WARN naming the parameter and what it must be.
template <typename T>
void read_param(const ::ros::NodeHandle& handle, const std::string& name, T& value)
{
  T read = value;
  if (handle.hasParam(name) && !handle.getParam(name, read))
  {
    ROS_WARN_NAMED("node", "~%s must be %s; using %s", name.c_str(), param_kind(value), param_text(value).c_str());
    return;
  }
  value = read;
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
