// The world service's snapshots without a master: SaveWorld then LoadWorld
// brings back the saved frame, a loaded snapshot steps on like the saved
// world, failed loads leave the world as it was, and autosave keeps the last
// completed period and every edit.
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

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/settings_conversions.h"
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

class WorldServiceSnapshotTest : public ::testing::Test
{
protected:
  static void SetUpTestCase() { ::ros::Time::init(); }

  WorldServiceOptions options(std::uint32_t autosave_period) const
  {
    WorldServiceOptions out;
    out.scenes_dir = kScenesDir;
    out.snapshot_path = folder_.file("world.snapshot.yaml");
    out.autosave_period = autosave_period;
    return out;
  }

  static void load_demo(WorldService& service)
  {
    LoadScene::Request request;
    request.scene = "bouncing_disks";
    LoadScene::Response response;
    service.load_scene(request, response);
    ASSERT_TRUE(response.success) << response.message;
  }

  static WorldState step(WorldService& service, std::uint32_t frames)
  {
    StepWorld::Request request;
    request.frames = frames;
    request.return_state = true;
    StepWorld::Response response;
    service.step(request, response);
    EXPECT_TRUE(response.success) << response.message;
    return response.state.empty() ? WorldState() : response.state.front();
  }

  /// A restored world has not stepped yet, so no contacts or effects: the
  /// rest of the state must be exactly the saved one.
  static void expect_restored(const WorldState& saved, const WorldState& restored)
  {
    EXPECT_EQ(restored.frame_count, saved.frame_count);
    EXPECT_EQ(restored.sim_time, saved.sim_time);
    EXPECT_EQ(restored.scene, saved.scene);
    EXPECT_EQ(restored.settings, saved.settings);
    ASSERT_EQ(restored.bodies.size(), saved.bodies.size());
    for (std::size_t i = 0; i < saved.bodies.size(); ++i)
    {
      EXPECT_TRUE(restored.bodies[i] == saved.bodies[i]) << "body " << saved.bodies[i].id << " differs";
    }
  }

  TempFolder folder_;
};

TEST_F(WorldServiceSnapshotTest, SaveThenLoadBringsBackTheSavedFrame)
{
  WorldService service(options(0));
  load_demo(service);
  const WorldState saved = step(service, 10);
  SaveWorld::Request save;
  SaveWorld::Response saved_response;
  service.save_world(save, saved_response);
  ASSERT_TRUE(saved_response.success) << saved_response.message;
  EXPECT_EQ(saved_response.frame_count, 10u);
  EXPECT_EQ(saved_response.path, options(0).snapshot_path);

  const WorldState later = step(service, 5);
  ASSERT_EQ(later.frame_count, 15u);
  LoadWorld::Request load;
  load.return_state = true;
  LoadWorld::Response loaded;
  service.load_world(load, loaded);
  ASSERT_TRUE(loaded.success) << loaded.message;
  ASSERT_EQ(loaded.state.size(), 1u);
  expect_restored(saved, loaded.state[0]);
  EXPECT_EQ(loaded.frame_count, saved.frame_count);
  EXPECT_EQ(loaded.sim_time, saved.sim_time);
  EXPECT_EQ(loaded.body_count, saved.bodies.size());

  // The clock runs on from the saved frame, and reset returns to it.
  const WorldState resumed = step(service, 3);
  EXPECT_EQ(resumed.frame_count, 13u);
  EXPECT_NEAR(resumed.sim_time, saved.sim_time + 3 * saved.settings.dt, 1e-12);
  std_srvs::Trigger::Response reset;
  service.reset(reset);
  expect_restored(saved, service.state());
}

TEST_F(WorldServiceSnapshotTest, ALoadedSnapshotStepsOnLikeTheSavedWorld)
{
  WorldService service(options(0));
  load_demo(service);
  step(service, 10);
  SaveWorld::Request save;
  SaveWorld::Response saved;
  service.save_world(save, saved);
  ASSERT_TRUE(saved.success) << saved.message;
  const WorldState uninterrupted = step(service, 30);

  LoadWorld::Request load;
  LoadWorld::Response loaded;
  service.load_world(load, loaded);
  ASSERT_TRUE(loaded.success) << loaded.message;
  const WorldState resumed = step(service, 30);
  EXPECT_EQ(resumed.frame_count, uninterrupted.frame_count);
  EXPECT_EQ(resumed.sim_time, uninterrupted.sim_time) << "the clock too runs on as if never saved";
  ASSERT_EQ(resumed.bodies.size(), uninterrupted.bodies.size());
  for (std::size_t i = 0; i < resumed.bodies.size(); ++i)
  {
    EXPECT_TRUE(resumed.bodies[i] == uninterrupted.bodies[i]) << "body " << resumed.bodies[i].id << " differs";
  }
  EXPECT_TRUE(resumed.contacts == uninterrupted.contacts);
}

TEST_F(WorldServiceSnapshotTest, AWorldWhoseCentresCameToCoincideLoadsAsSaved)
{
  // Requests may not put two bodies on one centre, but stepping can: here a
  // kinematic disk slides through a static one in steps exact in binary
  // (0.5 m/s, 0.5 s frames). What SaveWorld wrote, LoadWorld must restore.
  Body fixed(1.0, 0.5, {1.0, 0.0}, {0.0, 0.0});
  fixed.set_type(BodyType::Static);
  Body sliding(1.0, 0.5, {0.0, 0.0}, {0.5, 0.0});
  sliding.set_type(BodyType::Kinematic);
  const Body falling(1.0, 0.25, {3.0, 2.0}, {0.0, 0.0});
  WorldSettings settings;
  settings.dt = 0.5;
  SetWorld::Request set;
  set.bodies = {body_to_msg(fixed, 0), body_to_msg(sliding, 0), body_to_msg(falling, 0)};
  set.settings = world_settings_to_msg(settings);
  WorldService service(options(0));
  SetWorld::Response set_response;
  service.set_world(set, set_response);
  ASSERT_TRUE(set_response.success) << set_response.message;
  const WorldState saved = step(service, 4);
  ASSERT_EQ(saved.bodies.size(), 3u);
  ASSERT_EQ(saved.bodies[1].pose.x, saved.bodies[0].pose.x) << "the centres must coincide for this test";
  ASSERT_EQ(saved.bodies[1].pose.y, saved.bodies[0].pose.y);

  SaveWorld::Response saved_response;
  service.save_world(SaveWorld::Request(), saved_response);
  ASSERT_TRUE(saved_response.success) << saved_response.message;
  const WorldState uninterrupted = step(service, 3);
  LoadWorld::Response loaded;
  service.load_world(LoadWorld::Request(), loaded);
  ASSERT_TRUE(loaded.success) << loaded.message;
  expect_restored(saved, service.state());
  const WorldState resumed = step(service, 3);
  ASSERT_EQ(resumed.bodies.size(), uninterrupted.bodies.size());
  for (std::size_t i = 0; i < resumed.bodies.size(); ++i)
  {
    EXPECT_TRUE(resumed.bodies[i] == uninterrupted.bodies[i]) << "body " << resumed.bodies[i].id << " differs";
  }
}

TEST_F(WorldServiceSnapshotTest, FailedLoadsLeaveTheWorldAsItWas)
{
  WorldService service(options(0));
  load_demo(service);
  step(service, 4);
  const WorldState before = service.state();

  LoadWorld::Request load;
  LoadWorld::Response response;
  service.load_world(load, response);  // default path, nothing saved yet
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("cannot open snapshot file"), std::string::npos) << response.message;

  load.path = folder_.file("torn.yaml");
  write_text(load.path, read_text(std::string(kScenesDir) + "/bouncing_disks.yaml") + "---\nframe_count: [");
  service.load_world(load, response);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("torn.yaml"), std::string::npos) << response.message;

  WorldService no_default(WorldServiceOptions{});
  SaveWorld::Response save_response;
  no_default.save_world(SaveWorld::Request(), save_response);
  EXPECT_FALSE(save_response.success);
  EXPECT_NE(save_response.message.find("~snapshot_path"), std::string::npos) << save_response.message;

  WorldState after = service.state();
  after.header = before.header;
  EXPECT_TRUE(after == before) << "a failed load changed the world";
}

TEST_F(WorldServiceSnapshotTest, AutosaveKeepsTheLastCompletedPeriodAndEveryEdit)
{
  constexpr std::uint32_t kPeriod = 5;
  WorldService service(options(kPeriod));
  load_demo(service);
  const std::string path = options(kPeriod).snapshot_path;
  EXPECT_EQ(load_snapshot_file(path).clock.frames, 0u) << "a new world is saved at once";

  WorldState at_five;
  for (std::uint32_t frame = 1; frame <= 7; ++frame)
  {
    const WorldState state = step(service, 1);
    if (frame == kPeriod)
    {
      at_five = state;
    }
  }
  EXPECT_EQ(load_snapshot_file(path).clock.frames, 5u);
  WorldService reader(options(0));
  reader.load_snapshot(path);
  expect_restored(at_five, reader.state());
  step(service, 12);  // 7 -> 19 passes 10 and 15: saved at the end of the call
  EXPECT_EQ(load_snapshot_file(path).clock.frames, 19u);

  RemoveBody::Request remove;
  remove.id = 0;
  RemoveBody::Response removed;
  service.remove_body(remove, removed);
  ASSERT_TRUE(removed.success) << removed.message;
  const WorldState edited = service.state();
  EXPECT_EQ(load_snapshot_file(path).ids.front(), 1u) << "an edit is saved at once";

  // A new node on the same file (a respawn) restores the last save.
  WorldService respawned(options(kPeriod));
  respawned.load_snapshot("");
  expect_restored(edited, respawned.state());
  step(respawned, 1);
  EXPECT_EQ(load_snapshot_file(path).clock.frames, 20u) << "the period counts on from the restored frame";
}

TEST_F(WorldServiceSnapshotTest, ABodyHeldBySomeoneIsSavedAsItIsWhenReleased)
{
  // A hold makes a body kinematic only while a client drags it; a snapshot
  // taken then (saved by hand, or by autosave at the hold itself) must not
  // keep it kinematic for good once restored.
  WorldService service(options(1));
  load_demo(service);
  step(service, 5);
  const BodyMsg dragged = service.state().bodies.back();
  ASSERT_EQ(dragged.type, BodyMsg::DYNAMIC);
  SetBodyState::Request hold;
  hold.id = dragged.id;
  hold.pose = dragged.pose;
  hold.pose.y += 1.0;
  hold.hold = true;
  SetBodyState::Response held;
  service.set_body_state(hold, held);
  ASSERT_TRUE(held.success) << held.message;
  const std::string autosaved = folder_.file("autosaved.yaml");
  std::filesystem::copy_file(options(1).snapshot_path, autosaved);  // the edit's autosave
  SaveWorld::Request by_hand;
  by_hand.path = folder_.file("by_hand.yaml");
  SaveWorld::Response saved;
  service.save_world(by_hand, saved);
  ASSERT_TRUE(saved.success) << saved.message;
  for (const std::string& path : {autosaved, by_hand.path})
  {
    WorldService restored(options(0));
    restored.load_snapshot(path);
    for (const BodyMsg& b : restored.state().bodies)
    {
      if (b.id == dragged.id)
      {
        EXPECT_EQ(b.type, BodyMsg::DYNAMIC) << path;
        EXPECT_EQ(b.pose.y, hold.pose.y) << path << ": the pose it was dragged to";
      }
    }
  }
  LoadWorld::Request load;
  load.path = by_hand.path;
  LoadWorld::Response loaded;
  service.load_world(load, loaded);
  ASSERT_TRUE(loaded.success) << loaded.message;
  hold.hold = false;
  SetBodyState::Response released;
  service.set_body_state(hold, released);
  ASSERT_TRUE(released.success) << released.message;
  EXPECT_EQ(service.state().bodies.back().type, BodyMsg::DYNAMIC);
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
