// Scene files on disk: YAML and .collision loading, saving, and lookup of
// named scenes in a directory.
#include "collision2d/scenes/scene_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "collision2d/scenario_io.h"

namespace collision2d
{
namespace scenes
{
namespace
{
namespace fs = std::filesystem;

/// Extensions tried by load_named_scene, in order of preference.
const std::vector<std::string>& scene_extensions()
{
  static const std::vector<std::string> kExtensions = {".yaml", ".yml", ".collision"};
  return kExtensions;
}

std::mutex warning_mutex;
std::function<void(const std::string&)> warning_handler;  ///< empty: std::cerr

std::string read_text(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw std::runtime_error(path + ": cannot open scene file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A .collision scenario: one restitution and friction for all bodies, which
/// become every body's material (static = kinetic friction), no gravity.
Scene load_collision_file(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw std::runtime_error(path + ": cannot open scene file");
  }
  const Scenario scenario = parse_scenario(in, path);
  Scene scene;
  scene.settings.gravity = Vec2{0.0, 0.0};
  const Material material{scenario.restitution, scenario.friction, scenario.friction};
  for (std::size_t i = 0; i < scenario.bodies.size(); ++i)
  {
    scene.bodies.push_back(SceneBody{scenario.bodies[i], material, "body_" + std::to_string(i)});
  }
  return scene;
}

}  // namespace

void set_warning_handler(std::function<void(const std::string&)> handler)
{
  std::lock_guard<std::mutex> lock(warning_mutex);
  warning_handler = std::move(handler);
}

void SceneReading::warn(const std::string& message) const
{
  if (warnings != nullptr)
  {
    warnings->push_back(message);
    return;
  }
  std::lock_guard<std::mutex> lock(warning_mutex);
  if (warning_handler)
  {
    warning_handler(message);
  }
  else
  {
    std::cerr << "warning: " << message << "\n";
  }
}

Scene load_scene_file(const std::string& path)
{
  const fs::path file(path);
  const std::string extension = file.extension().string();
  Scene scene;
  if (extension == ".yaml" || extension == ".yml")
  {
    scene = parse_scene_yaml(read_text(path), path);
  }
  else if (extension == ".collision")
  {
    scene = load_collision_file(path);
  }
  else
  {
    throw std::runtime_error(path + ": unknown scene file type (expected .yaml, .yml or .collision)");
  }
  if (scene.name.empty())
  {
    scene.name = file.stem().string();
  }
  return scene;
}

void save_scene_file(const Scene& scene, const std::string& path)
{
  std::ofstream out(path);
  out << scene_to_yaml(scene);
  if (!out)
  {
    throw std::runtime_error(path + ": cannot write scene file");
  }
}

std::vector<std::string> list_scenes(const std::string& dir)
{
  std::error_code error;
  if (!fs::is_directory(dir, error))
  {
    throw std::runtime_error(dir + ": scene directory not found");
  }
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
  {
    const fs::path& file = entry.path();
    const auto& known = scene_extensions();
    if (entry.is_regular_file() && std::find(known.begin(), known.end(), file.extension().string()) != known.end())
    {
      names.push_back(file.stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

Scene load_named_scene(const std::string& name, const std::string& dir)
{
  // A name, not a path: "../x" must not reach outside `dir`.
  const bool plain_name = !name.empty() && fs::path(name).filename().string() == name && name != "..";
  for (const std::string& extension : plain_name ? scene_extensions() : std::vector<std::string>{})
  {
    const fs::path file = fs::path(dir) / (name + extension);
    if (fs::is_regular_file(file))
    {
      return load_scene_file(file.string());
    }
  }
  std::string known;
  for (const std::string& other : list_scenes(dir))
  {
    known += (known.empty() ? "" : ", ") + other;
  }
  throw std::runtime_error("unknown scene '" + name + "' (known: " + known + ")");
}

}  // namespace scenes
}  // namespace collision2d
