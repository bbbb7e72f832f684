// Scenes of the world service: finding them by name or path, loading one.
#include "collision2d/ros/world_service.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

#include <ros/console.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/printable.h"
#include "collision2d/ros/validation.h"
#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/standard_scenes.h"
#include "service_reply.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
bool ends_with(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Names are looked up in the scenes folder; anything that reads like a file
/// is loaded as one.
bool looks_like_path(const std::string& scene)
{
  return scene.find('/') != std::string::npos || ends_with(scene, ".yaml") || ends_with(scene, ".yml") ||
         ends_with(scene, ".collision");
}

bool contains(const std::vector<std::string>& names, const std::string& name)
{
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string join(const std::vector<std::string>& names)
{
  std::string out;
  for (const std::string& name : names)
  {
    out += (out.empty() ? "" : ", ") + name;
  }
  return out;
}

std::vector<std::string> scene_files(const std::string& dir)
{
  try
  {
    return scenes::list_scenes(dir);
  }
  catch (const std::exception&)
  {
    return {};  // a missing folder just means no scene files
  }
}

}  // namespace

std::vector<std::string> WorldService::available_scenes() const
{
  std::vector<std::string> names = scene_files(options_.scenes_dir);
  for (const std::string& name : scenes::standard_scene_names())
  {
    if (!contains(names, name))
    {
      names.push_back(name);
    }
  }
  return names;
}

Scene WorldService::find_scene(const std::string& scene) const
{
  if (scene.empty())
  {
    reject("scene", "no name given (known: " + join(available_scenes()) + ")");
  }
  try
  {
    if (looks_like_path(scene))
    {
      return scenes::load_scene_file(scene);
    }
    if (contains(scene_files(options_.scenes_dir), scene))
    {
      return scenes::load_named_scene(scene, options_.scenes_dir);
    }
    if (contains(scenes::standard_scene_names(), scene))
    {
      return scenes::make_standard_scene(scene);
    }
  }
  catch (const std::exception& e)
  {
    reject("scene '" + scene + "'", e.what());
  }
  reject("scene", "unknown scene '" + scene + "' (known: " + join(available_scenes()) + ")");
}

void WorldService::load(const std::string& name)
{
  Scene scene = find_scene(name);
  if (scene.name.empty())
  {
    scene.name = name;
  }
  check_bodies(scene, /*saved_world=*/false);
  World world;
  try
  {
    world = make_world(scene);
  }
  catch (const std::invalid_argument& e)
  {
    reject("scene '" + scene.name + "'", e.what());
  }
  Lock lock(mutex_);
  active_ = ActiveEffects{};
  commit(std::move(world), scene.name, Change::NewWorld);
  ROS_INFO_NAMED(kWorldLogger, "loaded scene '%s': %zu bodies; %s", printable_text(scene.name).c_str(),
                 world_.body_count(), settings_summary(world_.settings()).c_str());
}

void WorldService::check_bodies(const Scene& scene, bool saved_world) const
{
  const std::string where = "scene '" + scene.name + "'";
  if (scene.bodies.size() > options_.max_bodies)
  {
    reject(where, std::to_string(scene.bodies.size()) + " bodies, more than the limit of " +
                      std::to_string(options_.max_bodies) + " (parameter ~max_bodies)");
  }
  if (saved_world)
  {
    return;
  }
  std::vector<Vec2> centres;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    centres.push_back(scene.bodies[i].body.position());
    labels.push_back(where + " bodies[" + std::to_string(i) + "]" +
                     (scene.bodies[i].name.empty() ? "" : " (" + scene.bodies[i].name + ")"));
  }
  check_distinct_centres(centres, labels);
}

}  // namespace ros_interface
}  // namespace collision2d
