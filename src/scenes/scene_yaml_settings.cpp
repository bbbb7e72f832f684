// The `settings:` map of a scene file, read and written field by field from
// the table in world_settings.h, so no setting can be dropped on either side.
#include <ostream>
#include <string>

#include "collision2d/scenes/scene_file.h"
#include "scene_yaml_internal.h"

namespace collision2d
{
namespace scenes
{
namespace detail
{
namespace
{
/// Fields a scene file keeps at its top level rather than under `settings:`
/// (every scene since the first names its gravity there).
bool at_top_level(const SettingInfo& info) { return std::string(info.name) == "gravity"; }

/// Extra cap a file may ask for, beyond the setting's own range: a few bytes
/// of YAML must not make a world that never finishes a frame.
int file_cap(const SettingInfo& info)
{
  return std::string(info.name) == "substeps" ? kMaxSceneSubsteps : kMaxSceneIterations;
}

template <typename Choice>
Choice read_choice(FieldReader& f, const std::string& key, const SettingInfo& info, Choice fallback)
{
  const std::string text = f.text(key, "");
  Choice value = fallback;
  if (!text.empty() && !from_text(text, value))
  {
    std::string choices = range_text(info.range, info.kind);
    for (std::size_t at = choices.find(" | "); at != std::string::npos; at = choices.find(" | "))
    {
      choices.replace(at, 3, choices.find(" | ", at + 1) == std::string::npos ? " or " : ", ");
    }
    f.fail_at(key, "must be " + choices + " (got '" + text + "')");
  }
  return value;
}

/// Reads each field under its own name, or under a former name the file uses.
class SettingsReader
{
public:
  SettingsReader(FieldReader& fields, const SceneReading& reading) : f_(fields), reading_(reading) {}

  void operator()(const SettingInfo& info, double& value)
  {
    const std::string key = key_of(info);
    if (info.range.min == 0.0 && info.range.min_exclusive && info.range.max == kUnbounded)
    {
      value = f_.positive(key, value);
      return;
    }
    if (info.range.min == 0.0 && info.range.max == kUnbounded)
    {
      value = f_.non_negative(key, value);
      return;
    }
    value = f_.number(key, value);
    if (!in_range(info.range, value))
    {
      f_.fail_at(key, "must be " + describe_range(info.range, info.kind));
    }
  }
  void operator()(const SettingInfo& info, int& value)
  {
    value = f_.integer(key_of(info), value, static_cast<int>(info.range.min), file_cap(info));
  }
  void operator()(const SettingInfo& info, std::size_t& value)
  {
    value = static_cast<std::size_t>(f_.unsigned_integer(key_of(info), value));
  }
  void operator()(const SettingInfo& info, bool& value) { value = read_choice(f_, key_of(info), info, value); }
  void operator()(const SettingInfo& info, Toggle& value) { value = read_choice(f_, key_of(info), info, value); }
  void operator()(const SettingInfo& info, SolverMode& value) { value = read_choice(f_, key_of(info), info, value); }
  void operator()(const SettingInfo& info, Vec2& value)
  {
    if (!at_top_level(info))
    {
      value = f_.vec2(key_of(info), value);
    }
  }

private:
  /// The field's own key, or the former name standing in for it (with a warning).
  std::string key_of(const SettingInfo& info)
  {
    for (const FormerSetting& former : *reading_.former)
    {
      if (former.replacement == std::string(info.name) && f_.has(former.name) && !f_.has(info.name))
      {
        return former.name;
      }
    }
    return info.name;
  }

  FieldReader& f_;
  const SceneReading& reading_;
};

/// One warning per former name the file uses; retired ones are read and dropped.
void warn_former_names(FieldReader& f, const SceneReading& reading)
{
  for (const FormerSetting& former : *reading.former)
  {
    if (!f.has(former.name))
    {
      continue;
    }
    const std::string where = f.source() + ": " + f.path(former.name);
    const std::string replacement = former.replacement;
    std::string message;
    if (replacement.empty())
    {
      f.node(former.name);  // known, so finish() accepts it
      message = where + " is retired and ignored";
    }
    else if (f.has(replacement))
    {
      f.node(former.name);
      message = where + " is the former name of " + replacement + ", which the file also sets: ignored";
    }
    else
    {
      message = where + " is the former name of " + replacement + ": read as " + replacement;
    }
    reading.warn(message + (former.note[0] != '\0' ? std::string(" (") + former.note + ")" : std::string()));
  }
}

/// The writer's text of one value.
class SettingsWriter
{
public:
  explicit SettingsWriter(std::ostream& out) : out_(out) {}

  void operator()(const SettingInfo& info, double value) { line(info) << number_text(value) << "\n"; }
  void operator()(const SettingInfo& info, int value) { line(info) << value << "\n"; }
  void operator()(const SettingInfo& info, std::size_t value) { line(info) << value << "\n"; }
  void operator()(const SettingInfo& info, bool value) { line(info) << to_text(value) << "\n"; }
  void operator()(const SettingInfo& info, Toggle value) { line(info) << to_text(value) << "\n"; }
  void operator()(const SettingInfo& info, SolverMode value) { line(info) << to_text(value) << "\n"; }
  void operator()(const SettingInfo& info, Vec2 value)
  {
    if (!at_top_level(info))
    {
      line(info) << "[" << number_text(value.x) << ", " << number_text(value.y) << "]\n";
    }
  }

private:
  std::ostream& line(const SettingInfo& info) { return out_ << "  " << info.name << ": "; }

  std::ostream& out_;
};

}  // namespace

WorldSettings read_settings(const YAML::Node& node, const std::string& source, const SceneReading& reading,
                            WorldSettings settings)
{
  FieldReader f(node, "settings", source);
  warn_former_names(f, reading);
  SettingsReader reader(f, reading);
  visit_world_settings(settings, reader);
  f.finish();
  return settings;
}

void write_settings(std::ostream& out, const WorldSettings& settings)
{
  out << "gravity: [" << number_text(settings.gravity.x) << ", " << number_text(settings.gravity.y) << "]\n";
  out << "settings:\n";
  visit_world_settings(settings, SettingsWriter(out));
}

}  // namespace detail
}  // namespace scenes
}  // namespace collision2d
