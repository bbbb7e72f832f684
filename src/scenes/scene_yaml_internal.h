// Internal to the scenes library: pieces of the YAML scene reader shared by
// the body/settings parser and the `generate:` expansion.
#pragma once

#include <map>
#include <ostream>
#include <string>

#include <yaml-cpp/yaml.h>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_file.h"
#include "yaml_fields.h"

namespace collision2d
{
namespace scenes
{
namespace detail
{
struct ParseContext
{
  std::string source;
  std::map<std::string, Material> materials;  ///< the file's `materials:` table
};

/// `key` of `fields`: a name from the materials table or an inline map;
/// `fallback` when absent.
Material read_material(FieldReader& fields, const std::string& key, const Material& fallback,
                       const ParseContext& context);
/// An inline material map at `path`.
Material read_material_map(const YAML::Node& node, const std::string& path, const std::string& source);

/// The `settings:` map over `settings` (fields it leaves out keep their value).
WorldSettings read_settings(const YAML::Node& node, const std::string& source, const SceneReading& reading,
                            WorldSettings settings);
/// The top-level `gravity:` line and the `settings:` map with every other field.
void write_settings(std::ostream& out, const WorldSettings& settings);

/// Appends the bodies of one `generate:` entry ({generator_name: {fields}}).
void expand_generator(const YAML::Node& entry, const std::string& path, const ParseContext& context, Scene& scene);

}  // namespace detail
}  // namespace scenes
}  // namespace collision2d
