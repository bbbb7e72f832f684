// Strict, located reading of YAML maps (see yaml_fields.h).
#include "yaml_fields.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace collision2d
{
namespace scenes
{
namespace detail
{
int line_of(const YAML::Node& node)
{
  return node.Mark().line + 1;
}

void fail(const std::string& source, int line, const std::string& path, const std::string& message)
{
  std::string where = source;
  if (line > 0)
  {
    where += ":" + std::to_string(line);
  }
  throw std::runtime_error(where + ": " + (path.empty() ? "" : path + ": ") + message);
}

std::string child_path(const std::string& parent, const std::string& key)
{
  return parent.empty() ? key : parent + "." + key;
}

std::string item_path(const std::string& parent, std::size_t index)
{
  return parent + "[" + std::to_string(index) + "]";
}

double read_number(const YAML::Node& node, const std::string& path, const std::string& source)
{
  if (!node.IsScalar())
  {
    fail(source, line_of(node), path, "must be a number");
  }
  double value = 0.0;
  if (!YAML::convert<double>::decode(node, value))
  {
    fail(source, line_of(node), path, "must be a number (got '" + node.Scalar() + "')");
  }
  if (!std::isfinite(value))
  {
    fail(source, line_of(node), path, "must be finite");
  }
  return value;
}

Vec2 read_vec2(const YAML::Node& node, const std::string& path, const std::string& source)
{
  if (!node.IsSequence() || node.size() != 2)
  {
    fail(source, line_of(node), path, "must be a pair [x, y]");
  }
  return Vec2{read_number(node[0], item_path(path, 0), source), read_number(node[1], item_path(path, 1), source)};
}

FieldReader::FieldReader(const YAML::Node& map, const std::string& map_path, const std::string& source)
  : map_(map), path_(map_path), source_(source)
{
  if (!map_.IsMap())
  {
    fail(source_, line_of(map_), path_, "must be a map of key: value");
  }
  std::set<std::string> seen;
  for (const auto& entry : map_)
  {
    if (!entry.first.IsScalar())
    {
      fail(source_, line_of(entry.first), path_, "keys must be plain names");
    }
    if (!seen.insert(entry.first.Scalar()).second)
    {
      fail(source_, line_of(entry.first), path(entry.first.Scalar()), "duplicate key");
    }
  }
}

bool FieldReader::has(const std::string& key)
{
  known_.insert(key);
  const YAML::Node& map = map_;
  return static_cast<bool>(map[key]);
}

YAML::Node FieldReader::node(const std::string& key)
{
  known_.insert(key);
  const YAML::Node& map = map_;
  return map[key];
}

void FieldReader::require(const std::string& key)
{
  if (!has(key))
  {
    fail(source_, line(), path(key), "missing (required)");
  }
}

double FieldReader::number(const std::string& key, double fallback)
{
  const YAML::Node value = node(key);
  return value ? read_number(value, path(key), source_) : fallback;
}

double FieldReader::positive(const std::string& key, double fallback)
{
  const double value = number(key, fallback);
  if (!(value > 0.0))
  {
    fail_at(key, "must be positive");
  }
  return value;
}

double FieldReader::non_negative(const std::string& key, double fallback)
{
  const double value = number(key, fallback);
  if (!(value >= 0.0))
  {
    fail_at(key, "must not be negative");
  }
  return value;
}

int FieldReader::integer(const std::string& key, int fallback, int minimum, int maximum)
{
  const YAML::Node value = node(key);
  if (!value)
  {
    return fallback;
  }
  int result = 0;
  if (!value.IsScalar() || !YAML::convert<int>::decode(value, result))
  {
    fail_at(key, "must be an integer");
  }
  if (result < minimum)
  {
    fail_at(key, "must be at least " + std::to_string(minimum));
  }
  if (result > maximum)
  {
    fail_at(key, "must be at most " + std::to_string(maximum));
  }
  return result;
}

std::uint64_t FieldReader::unsigned_integer(const std::string& key, std::uint64_t fallback)
{
  const YAML::Node value = node(key);
  if (!value)
  {
    return fallback;
  }
  // yaml-cpp would wrap "-1" around to a huge unsigned value.
  std::uint64_t result = 0;
  if (!value.IsScalar() || value.Scalar().find('-') != std::string::npos ||
      !YAML::convert<std::uint64_t>::decode(value, result))
  {
    fail_at(key, "must be a non-negative integer");
  }
  return result;
}

Vec2 FieldReader::vec2(const std::string& key, Vec2 fallback)
{
  const YAML::Node value = node(key);
  return value ? read_vec2(value, path(key), source_) : fallback;
}

std::string FieldReader::text(const std::string& key, const std::string& fallback)
{
  const YAML::Node value = node(key);
  if (!value)
  {
    return fallback;
  }
  if (!value.IsScalar())
  {
    fail_at(key, "must be text");
  }
  return value.Scalar();
}

void FieldReader::finish() const
{
  for (const auto& entry : map_)
  {
    const std::string key = entry.first.Scalar();
    if (known_.count(key) == 0)
    {
      std::string allowed;
      for (const std::string& k : known_)
      {
        allowed += (allowed.empty() ? "" : ", ") + k;
      }
      fail(source_, line_of(entry.first), path(key), "unknown key (expected one of: " + allowed + ")");
    }
  }
}

void FieldReader::fail_at(const std::string& key, const std::string& message) const
{
  const YAML::Node& map = map_;
  const YAML::Node value = map[key];
  fail(source_, value ? line_of(value) : line(), path(key), message);
}

}  // namespace detail
}  // namespace scenes
}  // namespace collision2d
