// World snapshots: a scene document plus a clock-and-ids document, written
// atomically (temporary file, fsync, rename).
#include "collision2d/ros/world_snapshot.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "collision2d/ros/step_state_yaml.h"
#include "collision2d/ros/validation.h"
#include "collision2d/scenes/scene_file.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
namespace fs = std::filesystem;

constexpr int kSnapshotVersion = 1;
const char* const kVersionKey = "collision2d_snapshot";
constexpr mode_t kSnapshotMode = 0644;  ///< rw-r--r--

[[noreturn]] void malformed(const std::string& source, const std::string& problem)
{
  throw std::runtime_error(source + ": snapshot: " + problem);
}

std::string clock_to_yaml(const WorldSnapshot& snapshot)
{
  std::ostringstream out;
  out << "---\n# The world's clock and body ids (collision2d world snapshot).\n";
  out << kVersionKey << ": " << kSnapshotVersion << "\n";
  out << "frame_count: " << snapshot.clock.frames << "\n";
  out << "sim_time: " << format_number(snapshot.clock.time) << "\n";
  out << "ids: [";
  for (std::size_t i = 0; i < snapshot.ids.size(); ++i)
  {
    out << (i == 0 ? "" : ", ") << snapshot.ids[i];
  }
  out << "]\nnext_id: " << snapshot.next_id << "\n";
  write_step_state(out, snapshot.step);
  return out.str();
}

template <typename T>
T read_field(const YAML::Node& doc, const char* key, const std::string& source)
{
  const YAML::Node node = doc[key];
  if (!node)
  {
    malformed(source, std::string("missing '") + key + "'");
  }
  try
  {
    return node.as<T>();
  }
  catch (const YAML::Exception&)
  {
    malformed(source, std::string("'") + key + "' is not a valid value");
  }
}

void check_keys(const YAML::Node& doc, const std::string& source)
{
  static const std::vector<std::string> kKeys = {kVersionKey,          "frame_count",         "sim_time",
                                                 "ids",                "next_id",             kStepStateKeys[0],
                                                 kStepStateKeys[1],    kStepStateKeys[2],     kStepStateKeys[3]};
  for (const auto& entry : doc)
  {
    const std::string key = entry.first.as<std::string>();
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
    {
      malformed(source, "unknown key '" + key + "'");
    }
  }
}

void check_ids(const WorldSnapshot& snapshot, const std::string& source)
{
  if (snapshot.ids.size() != snapshot.scene.bodies.size())
  {
    malformed(source, std::to_string(snapshot.ids.size()) + " ids for " +
                          std::to_string(snapshot.scene.bodies.size()) + " bodies");
  }
  for (std::size_t i = 1; i < snapshot.ids.size(); ++i)
  {
    if (snapshot.ids[i] <= snapshot.ids[i - 1])
    {
      malformed(source, "ids must be strictly ascending (ids[" + std::to_string(i) + "] = " +
                            std::to_string(snapshot.ids[i]) + ")");
    }
  }
  const std::uint64_t first_free = snapshot.ids.empty() ? 0 : std::uint64_t{snapshot.ids.back()} + 1;
  if (snapshot.next_id < first_free)
  {
    malformed(source, "next_id = " + std::to_string(snapshot.next_id) + " must exceed every id");
  }
}

void read_clock(const YAML::Node& doc, const std::string& source, WorldSnapshot& snapshot)
{
  if (!doc.IsMap())
  {
    malformed(source, "the second document must be a map");
  }
  check_keys(doc, source);
  if (read_field<int>(doc, kVersionKey, source) != kSnapshotVersion)
  {
    malformed(source, std::string("unsupported ") + kVersionKey + " version");
  }
  snapshot.clock.frames = read_field<std::uint64_t>(doc, "frame_count", source);
  snapshot.clock.time = read_field<double>(doc, "sim_time", source);
  if (!std::isfinite(snapshot.clock.time) || snapshot.clock.time < 0.0)
  {
    malformed(source, "sim_time must be finite and >= 0");
  }
  snapshot.ids = read_field<std::vector<BodyId>>(doc, "ids", source);
  snapshot.next_id = read_field<BodyId>(doc, "next_id", source);
  check_ids(snapshot, source);
  snapshot.step = read_step_state(doc, source);
}

[[noreturn]] void io_error(const std::string& path, const std::string& what)
{
  throw std::runtime_error(path + ": " + what + ": " + std::strerror(errno));
}

void write_all(int fd, const std::string& text, const std::string& path)
{
  std::size_t done = 0;
  while (done < text.size())
  {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n < 0)
    {
      io_error(path, "cannot write");
    }
    done += static_cast<std::size_t>(n);
  }
}

/// The temporary file is complete and on disk before the rename makes it the
/// snapshot; the folder is synced so the rename survives a power cut too.
void write_atomically(const std::string& text, const std::string& path)
{
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ignored;
  fs::create_directories(folder, ignored);
  std::string temp = path + ".tmp.XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0)
  {
    io_error(temp, "cannot create");
  }
  try
  {
    // mkstemp makes the file private; a snapshot is as readable as any scene file.
    if (::fchmod(fd, kSnapshotMode) != 0)
    {
      io_error(temp, "cannot chmod");
    }
    write_all(fd, text, temp);
    if (::fsync(fd) != 0)
    {
      io_error(temp, "cannot sync");
    }
  }
  catch (...)
  {
    ::close(fd);
    ::unlink(temp.c_str());
    throw;
  }
  ::close(fd);
  if (::rename(temp.c_str(), path.c_str()) != 0)
  {
    const int saved = errno;
    ::unlink(temp.c_str());
    errno = saved;
    io_error(path, "cannot rename " + temp + " to it");
  }
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0)
  {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace

WorldSnapshot take_snapshot(const World& world, const std::string& scene_name)
{
  WorldSnapshot snapshot;
  snapshot.scene = to_scene(world, scene_name);
  snapshot.ids = world.body_ids();
  snapshot.clock = WorldClock{world.frame_count(), world.time()};
  // Ids of removed bodies stay unused after a restore too.
  snapshot.next_id = world.next_id();
  snapshot.step = world.step_state();
  snapshot.saved_world = true;
  return snapshot;
}

World restore_world(const WorldSnapshot& snapshot)
{
  World world(snapshot.scene.settings);
  for (std::size_t i = 0; i < snapshot.scene.bodies.size(); ++i)
  {
    world.add_body(snapshot.ids[i], snapshot.scene.bodies[i].body, snapshot.scene.bodies[i].material);
  }
  world.set_next_id(snapshot.next_id);
  // The world counts on from the saved clock, so its time after n more
  // frames is the same sum of frame lengths as the saved world's.
  world.set_clock(snapshot.clock.time, snapshot.clock.frames);
  // An older snapshot (or a plain scene) has no step state: it starts cold.
  if (!snapshot.step.rest_time.empty() || snapshot.step.contact_substep > 0.0)
  {
    world.set_step_state(snapshot.step);
  }
  return world;
}

std::string snapshot_to_yaml(const WorldSnapshot& snapshot)
{
  return scenes::scene_to_yaml(snapshot.scene) + clock_to_yaml(snapshot);
}

WorldSnapshot parse_snapshot_yaml(const std::string& text, const std::string& source_name)
{
  WorldSnapshot snapshot;
  snapshot.scene = scenes::parse_scene_yaml(text, source_name);
  std::vector<YAML::Node> documents;
  try
  {
    documents = YAML::LoadAll(text);
  }
  catch (const YAML::Exception& e)
  {
    malformed(source_name, e.what());
  }
  if (documents.size() > 2)
  {
    malformed(source_name, "more than two YAML documents");
  }
  if (documents.size() < 2)
  {
    // A plain scene file: a world as loading the scene makes it.
    for (std::size_t i = 0; i < snapshot.scene.bodies.size(); ++i)
    {
      snapshot.ids.push_back(static_cast<BodyId>(i));
    }
    snapshot.next_id = static_cast<BodyId>(snapshot.ids.size());
    return snapshot;
  }
  read_clock(documents[1], source_name, snapshot);
  snapshot.saved_world = true;
  return snapshot;
}

void save_snapshot_file(const WorldSnapshot& snapshot, const std::string& path)
{
  write_atomically(snapshot_to_yaml(snapshot), path);
}

WorldSnapshot load_snapshot_file(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw std::runtime_error(path + ": cannot open snapshot file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_snapshot_yaml(text.str(), path);
}

}  // namespace ros_interface
}  // namespace collision2d
