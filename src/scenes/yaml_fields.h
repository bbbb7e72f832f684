// Internal to the scenes library: strict, located reading of YAML maps.
// Every error names the source, the line and the key path
// ("scenes/x.yaml:12: bodies[3].mass: must be positive"), and keys nobody
// asked for are reported, so a typo never passes silently.
#pragma once

#include <cstdint>
#include <set>
#include <limits>
#include <string>

#include <yaml-cpp/yaml.h>

#include "collision2d/vec2.h"

namespace collision2d
{
namespace scenes
{
namespace detail
{
/// 1-based line of a node (yaml-cpp marks are 0-based).
int line_of(const YAML::Node& node);
[[noreturn]] void fail(const std::string& source, int line, const std::string& path, const std::string& message);
std::string child_path(const std::string& parent, const std::string& key);
std::string item_path(const std::string& parent, std::size_t index);

/// Reads the fields of one YAML map. Each getter records the key as known;
/// finish() then rejects any key that no getter asked for.
class FieldReader
{
public:
  /// Throws when `map` is not a map or repeats a key.
  FieldReader(const YAML::Node& map, const std::string& map_path, const std::string& source);

  bool has(const std::string& key);
  /// The child node (undefined when absent); marks the key as known.
  YAML::Node node(const std::string& key);

  double number(const std::string& key, double fallback);
  double positive(const std::string& key, double fallback);
  double non_negative(const std::string& key, double fallback);
  /// An integer in [minimum, maximum].
  int integer(const std::string& key, int fallback, int minimum,
              int maximum = std::numeric_limits<int>::max());
  std::uint64_t unsigned_integer(const std::string& key, std::uint64_t fallback);
  Vec2 vec2(const std::string& key, Vec2 fallback);
  std::string text(const std::string& key, const std::string& fallback);
  /// Throws naming `key` when it is absent.
  void require(const std::string& key);

  /// Rejects unknown keys, listing the ones accepted here.
  void finish() const;

  std::string path(const std::string& key) const { return child_path(path_, key); }
  const std::string& source() const { return source_; }
  int line() const { return line_of(map_); }
  /// Throws for `key`, at its line when present.
  [[noreturn]] void fail_at(const std::string& key, const std::string& message) const;

private:
  YAML::Node map_;
  std::string path_;
  std::string source_;
  std::set<std::string> known_;
};

/// Reads a scalar as a finite double; `path` and `source` locate errors.
double read_number(const YAML::Node& node, const std::string& path, const std::string& source);
/// Reads [x, y].
Vec2 read_vec2(const YAML::Node& node, const std::string& path, const std::string& source);

}  // namespace detail
}  // namespace scenes
}  // namespace collision2d
