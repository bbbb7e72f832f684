// Human-editable scene files (YAML) and .collision scenarios as Scenes.
//
// YAML layout (every key optional unless noted; unknown keys are errors):
//   name: pyramid
//   gravity: [0, -9.81]                 # m/s^2
//   settings: {dt: 0.0166, substeps: 4, velocity_iterations: 2, slop: 0.001,
//              rotation: auto, friction: on, sleep_time: 0.5, ...}
//              # every WorldSettings field but gravity, by its name
//              # (world_settings.h); toggles are auto | on | off;
//              # a former name warns (SceneReading)
//   materials:
//     rough: {restitution: 0, static_friction: 0.6, kinetic_friction: 0.5}
//   generate:                           # expanded first, in order
//     - ground: {width: 60, material: rough}
//     - pyramid: {base: 20, box: 1.0, at: [0, 0.5], material: rough}
//   bodies:                             # appended after the generated bodies
//     - {name: ball, shape: disk, mass: 1, radius: 0.5, position: [0, 3],
//        velocity: [1, 0], omega: 0, theta: 0, material: rough}
//     - {shape: box, type: static, size: [2, 0.1], position: [0, -1]}
//     - {shape: polygon, mass: 2, vertices: [[0, 0], [1, 0], [0, 1]]}
// Generators: ground, container, pyramid, column, cradle, disk_row, gas,
// incline, with the fields of the matching *Params in scene_parts.h.
// Errors throw std::runtime_error "source:line: key.path: message".
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "collision2d/scene.h"

namespace collision2d
{
namespace scenes
{
/// Limits a scene file may ask for, so a few bytes of YAML cannot make the
/// reader build billions of bodies or a world that never finishes a frame.
constexpr int kMaxSceneBodies = 1000000;
constexpr int kMaxSceneSubsteps = 1000;
constexpr int kMaxSceneIterations = 10000;

/// What a reader reports besides errors: a setting named as an earlier version
/// named it (renamed: read under its new name; retired: ignored) loads with a
/// warning naming its replacement, so old scenes and snapshots keep loading.
struct SceneReading
{
  /// Collects the warnings; null sends each to the warning handler.
  std::vector<std::string>* warnings = nullptr;
  /// Names of earlier versions (former_world_settings() unless a test says otherwise).
  const std::vector<FormerSetting>* former = &former_world_settings();

  void warn(const std::string& message) const;
};

/// Where warnings of readers given no vector go (load_scene_file, snapshots):
/// std::cerr until set; the ROS node sets rosconsole's WARN. Thread-safe.
void set_warning_handler(std::function<void(const std::string&)> handler);

Scene parse_scene_yaml(const std::string& text, const std::string& source_name = "<yaml>");
Scene parse_scene_yaml(const std::string& text, const std::string& source_name, const SceneReading& reading);
/// .yaml/.yml as YAML; .collision via parse_scenario (its restitution and
/// friction become every body's material, gravity zero).
Scene load_scene_file(const std::string& path);

/// YAML that parse_scene_yaml turns back into the same scene exactly (every
/// body listed explicitly, doubles written with max_digits10).
std::string scene_to_yaml(const Scene& scene);
void save_scene_file(const Scene& scene, const std::string& path);

/// Scene names (file stems of *.yaml, *.yml and *.collision) in `dir`, sorted.
std::vector<std::string> list_scenes(const std::string& dir);
/// Loads `dir`/name.{yaml,yml,collision}; throws std::runtime_error
/// "unknown scene 'x' (known: a, b, ...)" when none exists.
Scene load_named_scene(const std::string& name, const std::string& dir);

}  // namespace scenes
}  // namespace collision2d
