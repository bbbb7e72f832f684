// SolverSettings / WorldConfig <-> ResolveSettings / WorldSettings, field by
// field from the tables (resolve_settings.h, world_settings.h): each message
// field has its setting's name, so a field missing on either side does not compile.
#include "collision2d/ros/settings_conversions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
const char* const kSettings = "settings";
const char* const kWorldModes = "SOLVER_ITERATIVE (0) or SOLVER_EXACT (1)";
const char* const kSolverModes = "ITERATIVE (0) or EXACT (1)";

// The enumerators are the messages' constants.
static_assert(static_cast<int>(Toggle::Auto) == WorldConfig::AUTO && static_cast<int>(Toggle::On) == WorldConfig::ON &&
              static_cast<int>(Toggle::Off) == WorldConfig::OFF);
static_assert(static_cast<int>(SolverMode::Iterative) == WorldConfig::SOLVER_ITERATIVE &&
              static_cast<int>(SolverMode::Exact) == WorldConfig::SOLVER_EXACT &&
              static_cast<int>(SolverMode::Iterative) == SolverSettings::ITERATIVE &&
              static_cast<int>(SolverMode::Exact) == SolverSettings::EXACT);

void from_msg(double& out, double in, const char*, const char*) { out = in; }
void from_msg(int& out, std::int32_t in, const char*, const char*) { out = in; }
void from_msg(std::size_t& out, std::uint32_t in, const char*, const char*) { out = in; }
void from_msg(bool& out, std::uint8_t in, const char*, const char*) { out = in != 0; }

void from_msg(Vec2& out, const geometry_msgs::Vector3& in, const char* name, const char*)
{
  require_finite(in.x, kSettings, std::string(name) + ".x");
  require_finite(in.y, kSettings, std::string(name) + ".y");
  out = Vec2{in.x, in.y};
}

void from_msg(Toggle& out, std::uint8_t in, const char* name, const char*)
{
  if (in > WorldConfig::OFF)
  {
    reject(kSettings, std::string(name) + " = " + std::to_string(in) + " is not AUTO (0), ON (1) or OFF (2)");
  }
  out = static_cast<Toggle>(in);
}

void from_msg(SolverMode& out, std::uint8_t in, const char* name, const char* modes)
{
  if (in > WorldConfig::SOLVER_EXACT)
  {
    reject(kSettings, std::string(name) + " = " + std::to_string(in) + " is not " + modes);
  }
  out = static_cast<SolverMode>(in);
}

double to_msg(double value) { return value; }
std::int32_t to_msg(int value) { return value; }
bool to_msg(bool value) { return value; }
std::uint8_t to_msg(Toggle value) { return static_cast<std::uint8_t>(value); }
std::uint8_t to_msg(SolverMode value) { return static_cast<std::uint8_t>(value); }

std::uint32_t to_msg(std::size_t value)
{
  return static_cast<std::uint32_t>(std::min<std::size_t>(value, std::numeric_limits<std::uint32_t>::max()));
}

geometry_msgs::Vector3 to_msg(Vec2 value)
{
  geometry_msgs::Vector3 out;
  out.x = value.x;
  out.y = value.y;
  return out;
}

/// The request's view of a range: "settings: friction = -1 must be >= 0".
struct RequireInRange
{
  void operator()(const SettingInfo& info, double value) const
  {
    const SettingRange& r = info.range;
    if (std::isfinite(r.max))
    {
      require_in_range(value, r.min, r.max, kSettings, info.name);
    }
    else if (r.min == 0.0 && r.min_exclusive)
    {
      require_positive(value, kSettings, info.name);
    }
    else if (r.min == 0.0)
    {
      require_non_negative(value, kSettings, info.name);
    }
    else
    {
      require_finite(value, kSettings, info.name);
      if (!in_range(r, value))
      {
        reject(kSettings, std::string(info.name) + " = " + format_number(value) + " must be " +
                              describe_range(r, info.kind));
      }
    }
  }
  void operator()(const SettingInfo& info, int value) const
  {
    const SettingRange& r = info.range;
    if (in_range(r, value))
    {
      return;
    }
    const auto bound = [](double b) { return std::to_string(static_cast<long long>(b)); };
    const std::string rule =
        std::isfinite(r.max) ? "in [" + bound(r.min) + ", " + bound(r.max) + "]" : ">= " + bound(r.min);
    reject(kSettings, std::string(info.name) + " = " + std::to_string(value) + " must be " + rule);
  }
  template <typename Choice>
  void operator()(const SettingInfo&, Choice) const
  {
  }
};

}  // namespace

#define COLLISION2D_FROM_MSG(name, type, default_value, range, unit, doc) \
  from_msg(settings.name, msg.name, #name, kModes);
#define COLLISION2D_TO_MSG(name, type, default_value, range, unit, doc) msg.name = to_msg(settings.name);

ResolveSettings resolve_settings_from_msg(const SolverSettings& msg)
{
  const char* const kModes = kSolverModes;
  ResolveSettings settings;
  COLLISION2D_RESOLVE_SETTINGS(COLLISION2D_FROM_MSG)
  visit_resolve_settings(settings, RequireInRange{});
  return settings;
}

SolverSettings resolve_settings_to_msg(const ResolveSettings& settings)
{
  SolverSettings msg;
  COLLISION2D_RESOLVE_SETTINGS(COLLISION2D_TO_MSG)
  return msg;
}

ContactSolver solver_from_msg(const SolverSettings& msg)
{
  const ResolveSettings settings = resolve_settings_from_msg(msg);
  try
  {
    return make_contact_solver(settings);
  }
  catch (const std::invalid_argument& e)
  {
    reject(kSettings, e.what());
  }
}

WorldSettings world_settings_from_msg(const WorldConfig& msg)
{
  const char* const kModes = kWorldModes;
  WorldSettings settings;
  COLLISION2D_WORLD_SETTINGS(COLLISION2D_FROM_MSG)
  try
  {
    // The world's own ranges are the authority; its message names the field.
    World::validate(settings);
  }
  catch (const std::invalid_argument& e)
  {
    reject(kSettings, e.what());
  }
  return settings;
}

WorldConfig world_settings_to_msg(const WorldSettings& settings)
{
  WorldConfig msg;
  COLLISION2D_WORLD_SETTINGS(COLLISION2D_TO_MSG)
  return msg;
}

Effects effects_to_msg(const ActiveEffects& effects)
{
  Effects msg;
  msg.rotation = effects.rotation;
  msg.friction = effects.friction;
  msg.restitution = effects.restitution;
  msg.position_correction = effects.position_correction;
  msg.time_of_impact = effects.time_of_impact;
  msg.warm_starting = effects.warm_starting;
  msg.sleeping = effects.sleeping;
  return msg;
}

}  // namespace ros_interface
}  // namespace collision2d
