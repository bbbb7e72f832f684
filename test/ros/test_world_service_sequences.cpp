// Requests to the world service drawn at random from fixed seeds, valid and
// not: steps (some with their own dt), body states with and without a hold,
// added and removed bodies, settings edits, new worlds, scene loads, resets,
// saves and loads (of a torn file too), and throws that overflow. After every
// request two promises hold on the whole WorldState:
// - a twin sent only the requests the service accepted is the same: a
//   refused request leaves nothing behind, hidden state included;
// - a service restored from the service's snapshot, then sent the same
//   requests, steps on the same (snapshots resume exactly).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <ros/console.h>
#include <ros/time.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/validation.h"
#include "collision2d/ros/world_service.h"
#include "collision2d/scenes/standard_scenes.h"

#include "snapshot_test_support.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using namespace snapshot_test;  // NOLINT: the temporary folder and the scenes folder

constexpr int kSequences = 120;
constexpr int kRequestsPerSequence = 12;
/// A throw: a speed (m/s) that overflows within a frame of kThrowDt (s).
constexpr double kThrowSpeed = 1e308;
constexpr double kThrowDt = 1.0;
/// Keeps the drawn worlds small; a request may not grow one past it.
constexpr std::size_t kMaxBodies = 24;

using Random = std::mt19937_64;

double uniform(Random& random, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); }

int pick(Random& random, int count) { return std::uniform_int_distribution<int>(0, count - 1)(random); }

/// One in `n` draws.
bool one_in(Random& random, int n) { return pick(random, n) == 0; }

SetWorld::Request draw_world(Random& random)
{
  Scene scene;
  switch (pick(random, 5))
  {
    case 0:
      scene = scenes::pyramid(2 + pick(random, 3));
      break;
    case 1:
      scene = scenes::column(2 + pick(random, 4));
      break;
    case 2:
      scene = scenes::bouncing_disks(1 + pick(random, 4), uniform(random, 0.0, 1.0));
      break;
    case 3:
      scene = scenes::incline(uniform(random, 0.1, 1.0), uniform(random, 0.0, 1.0), uniform(random, 0.0, 0.5));
      break;
    default:
      scene = scenes::newtons_cradle(2 + pick(random, 3));
      break;
  }
  const std::array<Toggle, 3> toggles = {Toggle::Auto, Toggle::On, Toggle::Off};
  WorldSettings& s = scene.settings;
  s.soft_step = one_in(random, 2);
  s.substeps = 1 + pick(random, 4);
  s.sleeping = toggles[pick(random, 3)];
  s.sleep_time = uniform(random, 0.0, 0.3);  // short, so islands fall asleep within a sequence
  s.time_of_impact = toggles[pick(random, 3)];
  s.warm_starting = toggles[pick(random, 3)];
  SetWorld::Request request;
  for (const SceneBody& body : scene.bodies)
  {
    request.bodies.push_back(body_to_msg(body.body, 0, body.material));
  }
  request.settings = world_settings_to_msg(s);
  return request;
}

BodyMsg draw_body(Random& random)
{
  Body body(uniform(random, 0.5, 2.0), uniform(random, 0.1, 0.5), {uniform(random, -3.0, 3.0), uniform(random, 0.5, 6.0)},
            {uniform(random, -2.0, 2.0), 0.0});
  body.set_type(static_cast<BodyType>(pick(random, 3)));
  BodyMsg msg = body_to_msg(body, 0);
  if (one_in(random, 5))
  {
    msg.mass = -1.0;  // refused
  }
  return msg;
}

/// The three services and what the test knows of them.
struct Services
{
  explicit Services(const TempFolder& temp) : folder(temp)
  {
    first = make("first");
    twin = make("twin");
  }

  std::unique_ptr<WorldService> make(const std::string& name) const
  {
    WorldServiceOptions options;
    options.scenes_dir = kScenesDir;
    options.snapshot_path = folder.file(name + ".yaml");
    options.max_bodies = kMaxBodies;
    auto service = std::make_unique<WorldService>(options);
    // Stamps from the clock, so equal worlds have equal states.
    service->set_stamp_source([](const WorldClock& clock) { return ::ros::Time(clock.time); });
    return service;
  }

  /// Sends `request` to the first service and, if it accepted it, to the others.
  template <typename Request, typename Response>
  bool send(void (WorldService::*handler)(const Request&, Response&), const Request& request)
  {
    Response response;
    ((*first).*handler)(request, response);
    if (!response.success)
    {
      return false;
    }
    for (WorldService* other : {twin.get(), restored.get()})
    {
      if (other != nullptr)
      {
        Response again;
        (other->*handler)(request, again);
        EXPECT_TRUE(again.success) << again.message;
      }
    }
    return true;
  }

  bool edit_settings(const std::function<WorldSettings(const WorldSettings&)>& change)
  {
    try
    {
      first->edit_settings(change);
    }
    catch (const InvalidRequest&)
    {
      return false;
    }
    twin->edit_settings(change);
    if (restored)
    {
      restored->edit_settings(change);
    }
    return true;
  }

  const TempFolder& folder;
  std::unique_ptr<WorldService> first, twin, restored;
  bool restored_stepped = false;
  std::set<std::uint32_t> held;  ///< a snapshot saves a held body with its own type
};

/// One drawn request; returns its kind and whether the service accepted it.
std::pair<std::string, bool> draw_request(Random& random, Services& s)
{
  const WorldState now = s.first->state();
  // A body of the world, or now and then none (a request naming it is refused).
  const BodyMsg* body = now.bodies.empty() || one_in(random, 8) ?
                            nullptr :
                            &now.bodies[static_cast<std::size_t>(pick(random, static_cast<int>(now.bodies.size())))];
  const std::uint32_t id = body != nullptr ? body->id : 9999;
  switch (pick(random, 10))
  {
    case 0:
    case 1:
    {
      StepWorld::Request step;
      step.frames = one_in(random, 8) ? 0 : 1 + pick(random, 4);  // 0 is refused
      step.dt = one_in(random, 4) ? uniform(random, -0.01, 0.05) : 0.0;
      const bool accepted = s.send(&WorldService::step, step);
      s.restored_stepped = s.restored_stepped || accepted;
      return {"step", accepted};
    }
    case 2:
    {
      SetBodyState::Request set;
      set.id = id;
      set.pose = body != nullptr ? body->pose : geometry_msgs::Pose2D();
      set.pose.x += uniform(random, -0.1, 0.1);
      set.twist.linear.x = uniform(random, -5.0, 5.0);
      set.twist.angular.z = one_in(random, 6) ? std::nan("") : uniform(random, -2.0, 2.0);
      set.hold = one_in(random, 2);
      const bool accepted = s.send(&WorldService::set_body_state, set);
      if (accepted && set.hold && body->type != BodyMsg::KINEMATIC)
      {
        s.held.insert(id);
      }
      if (accepted && !set.hold)
      {
        s.held.erase(id);
      }
      return {"set_body_state", accepted};
    }
    case 3:
    {
      AddBody::Request add;
      add.body = draw_body(random);
      return {"add_body", s.send(&WorldService::add_body, add)};
    }
    case 4:
    {
      RemoveBody::Request remove;
      remove.id = id;
      const bool accepted = s.send(&WorldService::remove_body, remove);
      s.held.erase(id);
      return {"remove_body", accepted};
    }
    case 5:
    {
      const int field = pick(random, 4);
      const double value = uniform(random, -0.01, 0.05);
      const bool accepted = s.edit_settings([field, value](const WorldSettings& old) {
        WorldSettings w = old;
        switch (field)
        {
          case 0:
            w.dt = value;  // <= 0 is refused
            break;
          case 1:
            w.soft_step = !w.soft_step;
            break;
          case 2:
            w.substeps = static_cast<int>(value * 100.0);  // < 1 is refused
            break;
          default:
            w.sleeping = w.sleeping == Toggle::On ? Toggle::Off : Toggle::On;
            break;
        }
        return w;
      });
      return {"edit_settings", accepted};
    }
    case 6:
    {
      if (one_in(random, 3))
      {
        LoadScene::Request load;  // an unknown scene, and one with too many bodies, are refused
        const std::array<const char*, 4> names = {"resting_box", "newtons_cradle", "no_such_scene", "pyramid"};
        load.scene = names[static_cast<std::size_t>(pick(random, 4))];
        const bool accepted = s.send(&WorldService::load_scene, load);
        if (accepted)
        {
          s.held.clear();
        }
        return {"load_scene", accepted};
      }
      SetWorld::Request set = draw_world(random);
      set.keep_settings = one_in(random, 2);
      if (one_in(random, 5))
      {
        set.bodies.back().radius = 0.0;  // refused
      }
      const bool accepted = s.send(&WorldService::set_world, set);
      if (accepted)
      {
        s.held.clear();
      }
      return {"set_world", accepted};
    }
    case 7:
    {
      // Each saves to and loads from its own file; sometimes the first's is torn.
      SaveWorld::Request save;
      EXPECT_TRUE(s.send(&WorldService::save_world, save));
      if (one_in(random, 4))
      {
        std::ofstream(s.first->options().snapshot_path) << "bodies: [";
      }
      const bool accepted = s.send(&WorldService::load_world, LoadWorld::Request());
      if (accepted)
      {
        s.held.clear();
      }
      return {"load_world", accepted};
    }
    case 8:
    {
      // A throw: a dynamic body set flying, and frames of 1 s that overflow
      // unless a contact stops it.
      SetBodyState::Request fly;
      fly.twist.linear.x = kThrowSpeed;
      const auto dynamic = std::find_if(now.bodies.begin(), now.bodies.end(),
                                        [](const BodyMsg& b) { return b.type == BodyMsg::DYNAMIC; });
      if (dynamic == now.bodies.end())
      {
        return {"no dynamic body to throw", true};
      }
      fly.id = dynamic->id;
      fly.pose = dynamic->pose;
      EXPECT_TRUE(s.send(&WorldService::set_body_state, fly));
      s.held.erase(fly.id);
      StepWorld::Request step;
      step.frames = 2;
      step.dt = kThrowDt;
      return {"throw", s.send(&WorldService::step, step)};
    }
    default:
    {
      std_srvs::Trigger::Response first, twin;
      s.first->reset(first);
      s.twin->reset(twin);
      s.restored.reset();  // its reset point is its own snapshot
      s.held.clear();
      return {"reset", true};
    }
  }
}

/// Thousands of requests: their INFO and WARN lines would drown the output.
struct QuietLogs
{
  QuietLogs() { set(::ros::console::levels::Error); }
  ~QuietLogs() { set(::ros::console::levels::Info); }
  static void set(::ros::console::Level level)
  {
    if (::ros::console::set_logger_level(ROSCONSOLE_DEFAULT_NAME, level))
    {
      ::ros::console::notifyLoggerLevelsChanged();
    }
  }
};

/// Equal states; contacts and effects only when `contacts` (a restored
/// world has none until it steps).
void expect_same(const WorldState& a, const WorldState& b, bool contacts, const std::string& what)
{
  WorldState x = a;
  WorldState y = b;
  if (!contacts)
  {
    x.contacts = y.contacts;
    x.active = y.active;
  }
  EXPECT_TRUE(x == y) << what << " (frames " << a.frame_count << " / " << b.frame_count << ")";
}

TEST(WorldServiceSequences, RefusalsLeaveNothingBehindAndSnapshotsResume)
{
  ::ros::Time::init();
  QuietLogs quiet;
  std::map<std::string, std::array<int, 2>> tally;  // kind -> {refused, accepted}
  for (int seed = 0; seed < kSequences; ++seed)
  {
    Random random(static_cast<std::uint64_t>(seed));
    TempFolder folder;
    Services s(folder);
    ASSERT_TRUE(s.send(&WorldService::set_world, draw_world(random)));
    std::string log = "seed " + std::to_string(seed) + ":";
    for (int k = 0; k < kRequestsPerSequence; ++k)
    {
      const auto [kind, accepted] = draw_request(random, s);
      ++tally[kind][accepted ? 1 : 0];
      log += " " + kind + (accepted ? "" : " (refused)");
      expect_same(s.first->state(), s.twin->state(), true, "the twin differs after " + log);
      if (s.restored)
      {
        expect_same(s.first->state(), s.restored->state(), s.restored_stepped, "the restored differs after " + log);
      }
      else if (s.held.empty() && one_in(random, 3))
      {
        s.first->save_snapshot(folder.file("snapshot.yaml"));
        s.restored = s.make("restored");
        s.restored->load_snapshot(folder.file("snapshot.yaml"));
        s.restored_stepped = false;
        expect_same(s.first->state(), s.restored->state(), false, "the restored differs at once after " + log);
      }
      if (::testing::Test::HasFailure())
      {
        return;
      }
    }
  }
  // Both answers of every kind that can be refused must have been drawn, or
  // the draws no longer test what this file says.
  for (const auto& [kind, counts] : tally)
  {
    std::printf("%-24s refused %3d, accepted %3d\n", kind.c_str(), counts[0], counts[1]);
    if (kind != "reset" && kind != "no dynamic body to throw")
    {
      EXPECT_GT(counts[0], 0) << kind << " never refused";
    }
    EXPECT_GT(counts[1], 0) << kind << " never accepted";
  }
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
