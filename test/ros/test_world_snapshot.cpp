// World snapshots without a master: the file keeps bodies, ids, settings and
// the clock exactly; it still loads as a plain scene; bad files are refused
// with a reason; a writer killed mid-save never leaves a torn file. The world
// service's SaveWorld, LoadWorld and autosave are
// test_world_snapshot_service.cpp, linked into the same binary.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/time.h>

#include "collision2d/ros/world_service.h"
#include "collision2d/ros/world_snapshot.h"
#include "collision2d/scenes/scene_file.h"

#include "snapshot_test_support.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using namespace snapshot_test;  // NOLINT: the temporary folder and file helpers

constexpr int kFramesBeforeSave = 7;

/// Disks and polygons of every type with distinct materials and non-default
/// settings, stepped a few frames, with body 1 removed (an id gap) and the
/// last body removed too (a next id beyond every remaining id).
World busy_world()
{
  WorldSettings settings;
  settings.dt = 1.0 / 120.0;
  settings.substeps = 3;
  settings.gravity = Vec2{0.5, -9.0};
  World world(settings);
  const std::vector<Vec2> box{{-2.0, -0.25}, {2.0, -0.25}, {2.0, 0.25}, {-2.0, 0.25}};
  const std::vector<Vec2> triangle{{0.0, 0.0}, {0.6, 0.1}, {0.2, 0.5}};
  Body ground(1.0, box, Vec2{0.0, -0.25}, Vec2{});
  ground.set_type(BodyType::Static);
  world.add_body(ground, Material{0.1, 0.8, 0.6});
  world.add_body(Body(2.0, 0.3, Vec2{-1.0, 2.0}, Vec2{0.3, 0.0}), Material{0.5, 0.2, 0.1});
  world.add_body(Body(1.5, 0.25, Vec2{0.5, 0.3}, Vec2{-0.2, 0.0}, 0.4), Material{0.9, 0.0, 0.0});
  world.add_body(Body(0.7, triangle, Vec2{1.2, 1.0}, Vec2{0.0, -1.0}, 0.3, 2.0), Material{0.2, 0.5, 0.4});
  world.add_body(Body(3.0, 0.4, Vec2{-1.5, 0.5}, Vec2{}), Material{});
  world.step(kFramesBeforeSave);
  world.remove_body(1);
  world.remove_body(4);
  return world;
}

/// Exactly equal scenes have exactly equal YAML (doubles at max_digits10).
std::string scene_text(const World& world) { return scenes::scene_to_yaml(to_scene(world)); }

BodyId next_id_of(World world) { return world.add_body(Body(1.0, 0.1, Vec2{50.0, 50.0}, Vec2{})); }

/// The snapshot of `world` with its clock set to `clock`.
WorldSnapshot snapshot_at(World world, const std::string& scene_name, const WorldClock& clock)
{
  world.set_clock(clock.time, clock.frames);
  return take_snapshot(world, scene_name);
}

TEST(WorldSnapshotFile, RoundTripKeepsBodiesIdsSettingsAndClock)
{
  const World world = busy_world();
  const WorldClock clock{1234567890123ULL, 0.1 + 0.2};  // a time with no short decimal form
  const WorldSnapshot saved = snapshot_at(world, "busy", clock);
  const WorldSnapshot read = parse_snapshot_yaml(snapshot_to_yaml(saved));
  EXPECT_EQ(read.clock.frames, clock.frames);
  EXPECT_EQ(read.clock.time, clock.time);
  EXPECT_EQ(read.scene.name, "busy");
  EXPECT_EQ(read.ids, (std::vector<BodyId>{0, 2, 3}));
  EXPECT_EQ(read.next_id, 5u);

  World restored = restore_world(read);
  EXPECT_EQ(restored.frame_count(), clock.frames);
  EXPECT_EQ(restored.time(), clock.time);
  EXPECT_EQ(restored.body_ids(), world.body_ids());
  EXPECT_EQ(scene_text(restored), scene_text(world));
  EXPECT_EQ(next_id_of(restored), next_id_of(world)) << "a removed body's id would be reused";

  // Once the bodies rest on the ground, warm-start impulses and sleep come
  // through the text exactly: the restored world steps on bit for bit.
  World original = world;
  original.step(60);
  ASSERT_FALSE(original.contacts().empty());
  restored = restore_world(parse_snapshot_yaml(snapshot_to_yaml(snapshot_at(original, "busy", clock))));
  for (int frame = 0; frame < 20; ++frame)
  {
    original.step();
    restored.step();
    ASSERT_EQ(scene_text(restored), scene_text(original)) << "frame " << frame;
  }
}

TEST(WorldSnapshotFile, AFileWithoutStepStateStillLoadsAndStartsCold)
{
  const WorldSnapshot saved = snapshot_at(busy_world(), "busy", WorldClock{3, 0.3});
  std::string text = snapshot_to_yaml(saved);
  text = text.substr(0, text.find("# Warm starting and sleep"));
  const WorldSnapshot read = parse_snapshot_yaml(text);
  EXPECT_TRUE(read.step.contacts.empty());
  World restored = restore_world(read);
  EXPECT_TRUE(restored.contacts().empty());
  EXPECT_NO_THROW(restored.step());
}

TEST(WorldSnapshotFile, ASnapshotNamingRetiredSettingsLoadsWithWarningsAndStepsOnTheSame)
{
  World original = busy_world();
  original.step(60);
  const std::string text = snapshot_to_yaml(snapshot_at(original, "busy", WorldClock{67, 1.1}));
  // As an earlier version wrote it: the retired warm-start knobs among the settings.
  std::string old_text = text;
  const std::size_t settings = old_text.find("\nsettings:\n");
  ASSERT_NE(settings, std::string::npos) << text;
  old_text.insert(settings + 11, "  warm_start_factor: 1\n  warm_start_every_substep: true\n");
  std::vector<std::string> warnings;
  scenes::set_warning_handler([&](const std::string& message) { warnings.push_back(message); });
  const WorldSnapshot read = parse_snapshot_yaml(old_text, "old.snapshot.yaml");
  scenes::set_warning_handler(nullptr);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].rfind("old.snapshot.yaml: settings.warm_start_factor is retired and ignored", 0), 0u)
      << warnings[0];
  EXPECT_EQ(warnings[1].rfind("old.snapshot.yaml: settings.warm_start_every_substep is retired and ignored", 0), 0u)
      << warnings[1];
  World restored = restore_world(read);
  EXPECT_EQ(snapshot_to_yaml(take_snapshot(restored, "busy")), text);
  for (int frame = 0; frame < 20; ++frame)
  {
    original.step();
    restored.step();
    ASSERT_EQ(scene_text(restored), scene_text(original)) << "frame " << frame;
  }
}

TEST(WorldSnapshotFile, IsStillAPlainSceneFileAndAPlainSceneIsASnapshot)
{
  TempFolder folder;
  const World world = busy_world();
  const std::string snapshot_path = folder.file("world.snapshot.yaml");
  save_snapshot_file(snapshot_at(world, "busy", WorldClock{42, 0.7}), snapshot_path);
  // The scene loader reads the first document and ignores the clock.
  EXPECT_EQ(scenes::scene_to_yaml(scenes::load_scene_file(snapshot_path)),
            scenes::scene_to_yaml(to_scene(world, "busy")));

  const std::string scene_path = folder.file("plain.yaml");
  scenes::save_scene_file(to_scene(world, "plain"), scene_path);
  const WorldSnapshot plain = load_snapshot_file(scene_path);
  EXPECT_EQ(plain.clock.frames, 0u);
  EXPECT_EQ(plain.clock.time, 0.0);
  EXPECT_EQ(plain.ids, (std::vector<BodyId>{0, 1, 2}));
  EXPECT_EQ(plain.next_id, 3u);
}

/// The reason parse_snapshot_yaml gives for a snapshot whose clock document
/// is `clock` ("" if it is accepted).
std::string rejection(const std::string& clock)
{
  const std::string scene = snapshot_to_yaml(snapshot_at(busy_world(), "busy", WorldClock{}));
  const std::string text = scene.substr(0, scene.find("---\n")) + "---\n" + clock;
  try
  {
    parse_snapshot_yaml(text, "bad.yaml");
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}

TEST(WorldSnapshotFile, InconsistentClockDocumentsAreRefusedWithAReason)
{
  const std::string good = "collision2d_snapshot: 1\nframe_count: 5\nsim_time: 0.5\n";
  ASSERT_EQ(rejection(good + "ids: [0, 2, 3]\nnext_id: 5\n"), "");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good + "ids: [0, 2]\nnext_id: 5\n", "2 ids for 3 bodies"},
      {good + "ids: [0, 3, 2]\nnext_id: 5\n", "ids must be strictly ascending"},
      {good + "ids: [0, 2, 3]\nnext_id: 3\n", "next_id = 3 must exceed every id"},
      {good + "ids: [0, 2, 3]\n", "missing 'next_id'"},
      {good + "ids: [0, 2, 3]\nnext_id: 5\nframes: 3\n", "unknown key 'frames'"},
      {"collision2d_snapshot: 2\nframe_count: 5\nsim_time: 0.5\nids: [0, 2, 3]\nnext_id: 5\n", "version"},
      {"collision2d_snapshot: 1\nframe_count: -5\nsim_time: 0.5\nids: [0, 2, 3]\nnext_id: 5\n", "frame_count"},
      {"collision2d_snapshot: 1\nframe_count: 5\nsim_time: .nan\nids: [0, 2, 3]\nnext_id: 5\n", "sim_time"},
      {good + "ids: [0, 2, 3]\nnext_id: 5\n---\nextra: 1\n", "more than two YAML documents"},
      {"[1, 2]\n", "must be a map"},
  };
  for (const auto& [clock, reason] : cases)
  {
    const std::string message = rejection(clock);
    EXPECT_NE(message.find("bad.yaml: snapshot: "), std::string::npos) << clock << " -> '" << message << "'";
    EXPECT_NE(message.find(reason), std::string::npos) << clock << " -> '" << message << "'";
  }
}

TEST(WorldSnapshotFile, RestoreTakesIdsDirectlyHoweverManyWereSkipped)
{
  // Restoring sets each id and the next one directly (no id is walked
  // through), so four billion removed bodies cost nothing.
  WorldSnapshot snapshot;
  snapshot.scene.bodies.push_back(SceneBody{Body(1.0, 0.5, Vec2{0.0, 0.0}, Vec2{0.0, 0.0}), Material{}, ""});
  snapshot.ids = {3999999990u};
  snapshot.next_id = 4000000000u;
  World world = restore_world(snapshot);
  EXPECT_EQ(world.body_ids(), std::vector<BodyId>{3999999990u});
  EXPECT_EQ(world.next_id(), 4000000000u);
  EXPECT_EQ(world.add_body(Body(1.0, 0.5, Vec2{5.0, 0.0}, Vec2{0.0, 0.0})), 4000000000u);
}

TEST(WorldSnapshotFile, SavingCreatesFoldersReplacesWholeAndLeavesNoTemporaries)
{
  TempFolder folder;
  const std::string path = folder.file("deep/er/world.snapshot.yaml");
  save_snapshot_file(snapshot_at(busy_world(), "first", WorldClock{1, 0.1}), path);
  save_snapshot_file(snapshot_at(World(), "second", WorldClock{2, 0.2}), path);
  const WorldSnapshot read = load_snapshot_file(path);
  EXPECT_EQ(read.scene.name, "second");
  EXPECT_TRUE(read.scene.bodies.empty());
  EXPECT_EQ(std::distance(fs::directory_iterator(fs::path(path).parent_path()), fs::directory_iterator()), 1);

  // A folder in the way: the save fails naming the path and cleans up.
  const std::string blocked = folder.file("blocked");
  fs::create_directories(fs::path(blocked) / "inside");
  try
  {
    save_snapshot_file(snapshot_at(World(), "x", WorldClock{}), blocked);
    FAIL() << "saved over a folder";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(blocked), std::string::npos) << e.what();
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()), 2) << "temporary left";
}

/// A child process saves two different large snapshots in turns as fast as
/// it can and is killed with SIGKILL at an arbitrary moment; the file must
/// then hold one of the two whole. A writer that wrote the file in place
/// would leave it torn at most of these moments.
TEST(WorldSnapshotFile, AWriterKilledMidSaveNeverLeavesATornFile)
{
  constexpr int kKills = 6;
  constexpr int kBodies = 1000;  // ~170 kB per snapshot: a save takes milliseconds
  constexpr int kFirstSaveWaitS = 20;
  TempFolder folder;
  const std::string path = folder.file("world.snapshot.yaml");
  World big;
  for (int i = 0; i < kBodies; ++i)
  {
    big.add_body(Body(1.0, 0.4, Vec2{1.0 * i, 0.0}, Vec2{0.1 * i, 0.0}));
  }
  const std::vector<WorldSnapshot> versions = {snapshot_at(big, "even", WorldClock{2, 0.2}),
                                               snapshot_at(big, "odd", WorldClock{3, 0.3})};
  for (int kill = 0; kill < kKills; ++kill)
  {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
      for (unsigned i = 0;; ++i)
      {
        save_snapshot_file(versions[i % 2], path);
      }
    }
    // Kill only after a first whole save, at a different moment each time.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kFirstSaveWaitS);
    while (!fs::exists(path) && std::chrono::steady_clock::now() < deadline)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(3 + 7 * kill));
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(fs::exists(path)) << "no save finished within " << kFirstSaveWaitS << " s";
    const WorldSnapshot read = load_snapshot_file(path);
    ASSERT_EQ(read.scene.bodies.size(), static_cast<std::size_t>(kBodies));
    EXPECT_EQ(read.clock.frames, read.scene.name == "even" ? 2u : 3u) << "clock of one save, scene of another";
  }
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
