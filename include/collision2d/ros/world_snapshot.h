// World snapshots: what the world node saves (SaveWorld, ~autosave_period)
// and restores (LoadWorld, a respawn with ~restore_on_start).
//
// A snapshot file is a scene file (scene_to_yaml, exactly as save_scene_file
// writes it) followed by a second YAML document with what a scene does not
// hold: the frame count, the sim time, the body ids and the next id, and the
// step state (step_state_yaml.h: the contacts with their impulses, their
// substep, and sleep).
//
//   name: "demo"
//   settings: {...}
//   bodies: [...]
//   ---
//   collision2d_snapshot: 1
//   frame_count: 120
//   sim_time: 2.0000000000000004
//   ids: [0, 1, 3]
//   next_id: 5
//   contact_substep: ... (and asleep, rest_time, contacts: the step state)
//
// parse_scene_yaml (and so load_scene_file and LoadScene) reads only the first
// document, so a snapshot still loads as a plain scene; a plain scene file
// loads as a snapshot at frame 0 with ids 0..n-1.
//
// Doubles are written with max_digits10, so a restored world steps on bit for
// bit like the saved one. An older file without the step state restores
// bodies, ids and clock exactly but starts its first frame cold (as after
// SetWorld).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace ros_interface
{
/// Frames and time stepped since the scene was loaded.
struct WorldClock
{
  std::uint64_t frames = 0;
  double time = 0.0;  ///< s
};

struct WorldSnapshot
{
  Scene scene;               ///< bodies in ascending id, materials, settings, name
  std::vector<BodyId> ids;   ///< id of scene.bodies[i], ascending
  BodyId next_id = 0;        ///< the id the world gives its next body
  WorldClock clock;
  StepState step;            ///< warm-start contacts and sleep; empty in older files
  /// Taken from a world or read from a snapshot document (not a plain scene):
  /// a state the world may have stepped to.
  bool saved_world = false;
};

/// The world's bodies, ids, settings, clock and step state.
WorldSnapshot take_snapshot(const World& world, const std::string& scene_name);
/// A world holding the snapshot's bodies under their ids, at the snapshot's
/// clock, whose next body gets snapshot.next_id. Throws std::invalid_argument
/// for a bad body or setting.
World restore_world(const WorldSnapshot& snapshot);

std::string snapshot_to_yaml(const WorldSnapshot& snapshot);
/// Throws std::runtime_error "source: ..." for a malformed scene or snapshot
/// document (ids not ascending, count not matching the bodies, ...).
WorldSnapshot parse_snapshot_yaml(const std::string& text, const std::string& source_name = "<snapshot>");

/// Writes to a temporary file in the same folder, flushes it to disk and
/// renames it over `path`, so `path` always holds a whole snapshot, the old
/// or the new, even if the process dies mid-write. Creates missing folders.
/// Throws std::runtime_error naming the path.
void save_snapshot_file(const WorldSnapshot& snapshot, const std::string& path);
/// Throws std::runtime_error naming the path.
WorldSnapshot load_snapshot_file(const std::string& path);

}  // namespace ros_interface
}  // namespace collision2d
