// The config's fields by name (through dynamic_reconfigure's generic Config
// message), so each table drives its group: "<group>_<field>".
#include "collision2d/ros/reconfigure.h"

#include <algorithm>
#include <limits>

#include <dynamic_reconfigure/config_tools.h>
#include <ros/console.h>

#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using dynamic_reconfigure::ConfigTools;

const char* const kSolverPrefix = "solver_";
const char* const kWorldPrefix = "world_";
const char* const kWhere = "dynamic_reconfigure";

/// The names a table field takes in the config (two for a vector).
std::vector<std::string> parameter_names(const std::string& prefix, const SettingInfo& info)
{
  const std::string name = prefix + info.name;
  if (info.kind == SettingKind::Vector)
  {
    return {name + "_x", name + "_y"};
  }
  return {name};
}

[[noreturn]] void refuse(const std::string& name, const std::string& value, const std::string& range)
{
  reject(kWhere, name + " = " + value + " is outside " + range);
}

/// Reads each field of a table from the config, checking it against its range.
class ConfigReader
{
public:
  ConfigReader(const Collision2dConfig& config, const char* prefix) : prefix_(prefix) { config.__toMessage__(msg_); }

  void operator()(const SettingInfo& info, double& value) const
  {
    value = get<double>(name(info));
    check(info, name(info), value);
  }
  void operator()(const SettingInfo& info, int& value) const
  {
    value = get<int>(name(info));
    check(info, name(info), value);
  }
  void operator()(const SettingInfo& info, std::size_t& value) const
  {
    const int raw = get<int>(name(info));
    check(info, name(info), raw);
    value = static_cast<std::size_t>(raw);
  }
  void operator()(const SettingInfo& info, bool& value) const { value = get<bool>(name(info)); }
  void operator()(const SettingInfo& info, Toggle& value) const { value = static_cast<Toggle>(choice(info, 2)); }
  void operator()(const SettingInfo& info, SolverMode& value) const
  {
    value = static_cast<SolverMode>(choice(info, 1));
  }
  void operator()(const SettingInfo& info, Vec2& value) const
  {
    const std::vector<std::string> names = parameter_names(prefix_, info);
    value = Vec2{get<double>(names[0]), get<double>(names[1])};
    check(info, names[0], value.x);
    check(info, names[1], value.y);
  }

private:
  std::string name(const SettingInfo& info) const { return prefix_ + info.name; }

  template <typename T>
  T get(const std::string& name) const
  {
    T value{};
    if (!ConfigTools::getParameter(msg_, name, value))
    {
      reject(kWhere, name + " is missing from cfg/Collision2d.cfg");
    }
    return value;
  }

  static void check(const SettingInfo& info, const std::string& name, double value)
  {
    if (!in_range(info.range, value))
    {
      refuse(name, format_number(value), range_text(info.range, info.kind));
    }
  }

  /// The index of an enumerated choice, in [0, last].
  int choice(const SettingInfo& info, int last) const
  {
    const int value = get<int>(name(info));
    if (value < 0 || value > last)
    {
      refuse(name(info), std::to_string(value), "[0, " + std::to_string(last) + "] (" +
                                                    range_text(info.range, info.kind) + ")");
    }
    return value;
  }

  std::string prefix_;
  dynamic_reconfigure::Config msg_;
};

/// Writes each field of a table into the config.
class ConfigWriter
{
public:
  ConfigWriter(const Collision2dConfig& config, const char* prefix) : prefix_(prefix) { config.__toMessage__(msg_); }

  void operator()(const SettingInfo& info, double value) { set(prefix_ + info.name, value); }
  void operator()(const SettingInfo& info, int value) { set(prefix_ + info.name, value); }
  void operator()(const SettingInfo& info, std::size_t value)
  {
    set(prefix_ + info.name, static_cast<int>(std::min<std::size_t>(value, std::numeric_limits<int>::max())));
  }
  void operator()(const SettingInfo& info, bool value) { set(prefix_ + info.name, value); }
  void operator()(const SettingInfo& info, Toggle value) { set(prefix_ + info.name, static_cast<int>(value)); }
  void operator()(const SettingInfo& info, SolverMode value) { set(prefix_ + info.name, static_cast<int>(value)); }
  void operator()(const SettingInfo& info, Vec2 value)
  {
    const std::vector<std::string> names = parameter_names(prefix_, info);
    set(names[0], value.x);
    set(names[1], value.y);
  }

  void store(Collision2dConfig& config) { config.__fromMessage__(msg_); }

private:
  template <typename T>
  void set(const std::string& name, T value)
  {
    for (auto& parameter : ConfigTools::getVectorForType(msg_, value))
    {
      if (parameter.name == name)
      {
        parameter.value = value;
        return;
      }
    }
    reject(kWhere, name + " is missing from cfg/Collision2d.cfg");
  }

  std::string prefix_;
  dynamic_reconfigure::Config msg_;
};

/// Sets in `out` each world_* parameter whose value in `asked` differs from
/// `seen` (or that `seen` lacks).
template <typename Parameter>
void copy_changed_world_fields(const std::vector<Parameter>& asked, const std::vector<Parameter>& seen,
                               std::vector<Parameter>& out)
{
  const std::string prefix = kWorldPrefix;
  for (const Parameter& parameter : asked)
  {
    if (parameter.name.compare(0, prefix.size(), prefix) != 0)
    {
      continue;
    }
    const auto same_name = [&](const Parameter& p) { return p.name == parameter.name; };
    const auto before = std::find_if(seen.begin(), seen.end(), same_name);
    if (before != seen.end() && before->value == parameter.value)
    {
      continue;
    }
    const auto target = std::find_if(out.begin(), out.end(), same_name);
    if (target != out.end())
    {
      target->value = parameter.value;
    }
  }
}

/// The world_* fields of `from` into `to`, as they are (no range check),
/// except those `from` has as `seen` has them.
void copy_world_fields(const Collision2dConfig& from, Collision2dConfig& to,
                       const dynamic_reconfigure::Config& seen = dynamic_reconfigure::Config())
{
  dynamic_reconfigure::Config source;
  dynamic_reconfigure::Config target;
  from.__toMessage__(source);
  to.__toMessage__(target);
  copy_changed_world_fields(source.doubles, seen.doubles, target.doubles);
  copy_changed_world_fields(source.ints, seen.ints, target.ints);
  copy_changed_world_fields(source.bools, seen.bools, target.bools);
  to.__fromMessage__(target);
}

}  // namespace

ResolveSettings resolve_settings_from_config(const Collision2dConfig& config)
{
  ResolveSettings settings;
  visit_resolve_settings(settings, ConfigReader(config, kSolverPrefix));
  return settings;
}

void resolve_settings_to_config(const ResolveSettings& settings, Collision2dConfig& config)
{
  ConfigWriter writer(config, kSolverPrefix);
  visit_resolve_settings(settings, writer);
  writer.store(config);
}

WorldSettings world_settings_from_config(const Collision2dConfig& config)
{
  WorldSettings settings;
  visit_world_settings(settings, ConfigReader(config, kWorldPrefix));
  try
  {
    validate_world_settings(settings);  // the same ranges; the authority all the same
  }
  catch (const std::invalid_argument& e)
  {
    reject(kWhere, e.what());
  }
  return settings;
}

void world_settings_to_config(const WorldSettings& settings, Collision2dConfig& config)
{
  ConfigWriter writer(config, kWorldPrefix);
  visit_world_settings(settings, writer);
  writer.store(config);
}

SolverSettings accept_solver_config(Collision2dConfig& config, const SolverSettings& current)
{
  try
  {
    return resolve_settings_to_msg(resolve_settings_from_config(config));
  }
  catch (const InvalidRequest& e)
  {
    ROS_WARN("%s: refused, the solver settings stay as they were", e.what());
  }
  ResolveSettings kept;
  try
  {
    kept = resolve_settings_from_msg(current);
  }
  catch (const InvalidRequest&)
  {
    // Nothing valid was set before (a bad initial parameter): the table's defaults.
  }
  resolve_settings_to_config(kept, config);
  return resolve_settings_to_msg(kept);
}

WorldSettings merge_world_config(const Collision2dConfig& config, const Collision2dConfig& shown,
                                 const WorldSettings& current)
{
  Collision2dConfig merged = config;
  world_settings_to_config(current, merged);
  dynamic_reconfigure::Config seen;
  shown.__toMessage__(seen);
  copy_world_fields(config, merged, seen);
  return world_settings_from_config(merged);
}

void accept_world_config(Collision2dConfig& config, const Collision2dConfig& shown, const WorldSettingsEditor& edit)
{
  try
  {
    const WorldSettings now =
        edit([&](const WorldSettings& current) { return merge_world_config(config, shown, current); });
    world_settings_to_config(now, config);
  }
  catch (const InvalidRequest& e)
  {
    ROS_WARN("%s: refused, the world's settings stay as they were", e.what());
    copy_world_fields(shown, config);
  }
}

std::vector<std::string> table_parameter_names()
{
  std::vector<std::string> names;
  auto collect = [&names](const char* prefix) {
    return [&names, prefix](const SettingInfo& info, const auto&) {
      for (const std::string& name : parameter_names(prefix, info))
      {
        names.push_back(name);
      }
    };
  };
  const ResolveSettings resolve;
  visit_resolve_settings(resolve, collect(kSolverPrefix));
  const WorldSettings world;
  visit_world_settings(world, collect(kWorldPrefix));
  return names;
}

}  // namespace ros_interface
}  // namespace collision2d
