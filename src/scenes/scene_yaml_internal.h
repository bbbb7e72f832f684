// Internal to the scenes library: pieces of the YAML scene reader shared by
// the body/settings parser and the `generate:` expansion.
#pragma once

#include <map>
#include <string>

#include <yaml-cpp/yaml.h>

#include "collision2d/scene.h"
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

/// Appends the bodies of one `generate:` entry ({generator_name: {fields}}).
void expand_generator(const YAML::Node& entry, const std::string& path, const ParseContext& context, Scene& scene);

}  // namespace detail
}  // namespace scenes
}  // namespace collision2d
