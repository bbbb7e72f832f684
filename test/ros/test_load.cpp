// Load: kClients concurrent clients make kResolveCalls ResolveContacts calls
// in total on random scenes, each client interleaving StepWorld calls. Every
// call must be answered with success and its own bodies (no crossed
// responses), momentum must hold in every resolve, and the world must have
// stepped exactly the frames requested, one call after another. The p50/p99
// latency of each service is printed and recorded as test properties (a
// report, not an assertion: speed belongs to the benchmarks).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/conversions.h"
#include "collision2d/scenes/random_scenes.h"

namespace collision2d
{
namespace
{
constexpr int kClients = 8;
constexpr int kResolveCalls = 1000;               ///< in total, over all clients
constexpr int kResolvesPerStep = 5;               ///< each client steps after this many resolves
constexpr std::uint32_t kMaxFramesPerStep = 3;    ///< a client's k-th step asks for 1 + k % 3 frames
constexpr double kServiceWait = 30.0;             ///< s, node start-up under a loaded machine
constexpr double kMomentumTolerance = 1e-9;       ///< relative to the momentum scale of the scene
constexpr std::uint64_t kSeedBase = 20240917;
constexpr int kMinSceneBodies = 10;   ///< per request; multi-contact islands
constexpr int kMaxSceneBodies = 100;

scenes::RandomSceneOptions scene_options()
{
  scenes::RandomSceneOptions options;
  options.min_bodies = kMinSceneBodies;
  options.max_bodies = kMaxSceneBodies;
  return options;
}

struct Latencies
{
  std::vector<double> resolve_ms;
  std::vector<double> step_ms;
};

/// What a StepWorld call did: the frame count it left and the frames it asked for.
struct StepRecord
{
  std::uint64_t frame_count_after = 0;
  std::uint32_t frames = 0;
};

struct ClientResult
{
  Latencies latencies;
  std::vector<StepRecord> steps;
  std::uint64_t frames_requested = 0;
  int resolves_done = 0;
};

double elapsed_ms(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

/// Nearest-rank percentile.
double percentile(std::vector<double> values, double p)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(values.size())));
  return values[std::max<std::size_t>(rank, 1) - 1];
}

ResolveContacts::Request request_for(const scenes::RandomScene& scene, std::uint32_t first_id)
{
  ResolveContacts::Request request;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    request.bodies.push_back(ros_interface::body_to_msg(scene.bodies[i], first_id + static_cast<std::uint32_t>(i)));
  }
  request.settings.restitution = scene.restitution;
  request.settings.friction = scene.friction;
  request.settings.iterations = 64;
  request.settings.tolerance = 1e-9;
  request.settings.bias_factor = 0.2;
  request.settings.slop = 1e-3;
  return request;
}

/// The response answers this request: same ids in the same order, and the
/// solve kept the total momentum of the (all dynamic) bodies.
::testing::AssertionResult answers(const ResolveContacts::Request& request, const ResolveContacts::Response& response)
{
  if (!response.success)
  {
    return ::testing::AssertionFailure() << "rejected: " << response.message;
  }
  if (response.bodies.size() != request.bodies.size())
  {
    return ::testing::AssertionFailure() << response.bodies.size() << " bodies for " << request.bodies.size();
  }
  double scale = 0.0;
  for (std::size_t i = 0; i < request.bodies.size(); ++i)
  {
    if (response.bodies[i].id != request.bodies[i].id)
    {
      return ::testing::AssertionFailure() << "body " << i << " has id " << response.bodies[i].id << ", sent "
                                           << request.bodies[i].id << ": another client's answer";
    }
    scale += request.bodies[i].mass * std::hypot(request.bodies[i].twist.linear.x, request.bodies[i].twist.linear.y);
  }
  const auto& before = response.report.momentum_before;
  const auto& after = response.report.momentum_after;
  const double drift = std::hypot(after.x - before.x, after.y - before.y);
  if (drift > kMomentumTolerance * std::max(scale, 1.0))
  {
    return ::testing::AssertionFailure() << "momentum changed by " << drift << " kg m/s";
  }
  return ::testing::AssertionSuccess();
}

class LoadClient
{
public:
  LoadClient(int index, int resolve_calls)
    : index_(index)
    , resolve_calls_(resolve_calls)
    , scenes_(kSeedBase + static_cast<std::uint64_t>(index), scene_options())
    , resolve_(handle_.serviceClient<ResolveContacts>("resolve_contacts", /*persistent=*/true))
    , step_(handle_.serviceClient<StepWorld>("step_world", /*persistent=*/true))
  {
  }

  ClientResult run()
  {
    ClientResult result;
    for (int call = 0; call < resolve_calls_; ++call)
    {
      resolve_once(result);
      if ((call + 1) % kResolvesPerStep == 0)
      {
        step_once(result);
      }
    }
    return result;
  }

private:
  void resolve_once(ClientResult& result)
  {
    // Ids distinct per client and call, so a crossed answer shows.
    const auto first_id =
        static_cast<std::uint32_t>((index_ * resolve_calls_ + result.resolves_done) * kMaxSceneBodies);
    ResolveContacts srv;
    srv.request = request_for(scenes_.next(), first_id);
    const auto start = std::chrono::steady_clock::now();
    const bool called = resolve_.call(srv);
    result.latencies.resolve_ms.push_back(elapsed_ms(start));
    ++result.resolves_done;
    EXPECT_TRUE(called) << "client " << index_ << ": resolve_contacts call " << result.resolves_done << " failed";
    if (called)
    {
      EXPECT_TRUE(answers(srv.request, srv.response)) << "client " << index_;
    }
  }

  void step_once(ClientResult& result)
  {
    StepWorld srv;
    srv.request.frames = 1 + static_cast<std::uint32_t>(result.steps.size()) % kMaxFramesPerStep;
    const auto start = std::chrono::steady_clock::now();
    const bool called = step_.call(srv);
    result.latencies.step_ms.push_back(elapsed_ms(start));
    result.frames_requested += srv.request.frames;
    EXPECT_TRUE(called) << "client " << index_ << ": step_world call failed";
    EXPECT_TRUE(srv.response.success) << srv.response.message;
    result.steps.push_back(StepRecord{srv.response.frame_count, srv.request.frames});
  }

  ros::NodeHandle handle_;
  int index_;
  int resolve_calls_;
  scenes::RandomSceneGenerator scenes_;
  ros::ServiceClient resolve_;
  ros::ServiceClient step_;
};

std::uint64_t world_frame_count()
{
  GetWorld srv;
  EXPECT_TRUE(ros::service::call("get_world", srv));
  return srv.response.state.frame_count;
}

std::string format_ms(double ms)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << ms;
  return out.str();
}

void report(const std::string& service, const std::vector<double>& ms)
{
  const double p50 = percentile(ms, 50.0);
  const double p99 = percentile(ms, 99.0);
  std::cout << "[load] " << service << ": " << ms.size() << " calls, p50 " << format_ms(p50) << " ms, p99 "
            << format_ms(p99) << " ms, max " << format_ms(ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()))
            << " ms" << std::endl;
  ::testing::Test::RecordProperty(service + "_calls", std::to_string(ms.size()));
  ::testing::Test::RecordProperty(service + "_p50_ms", format_ms(p50));
  ::testing::Test::RecordProperty(service + "_p99_ms", format_ms(p99));
}

/// Steps serialize on the world: sorted by the frame count they left, each
/// call starts where the one before it ended, from `start` to `end`.
void expect_serialized(std::vector<StepRecord> steps, std::uint64_t start, std::uint64_t end)
{
  std::sort(steps.begin(), steps.end(),
            [](const StepRecord& a, const StepRecord& b) { return a.frame_count_after < b.frame_count_after; });
  std::uint64_t frame = start;
  for (const StepRecord& step : steps)
  {
    EXPECT_EQ(step.frame_count_after - step.frames, frame) << "a step overlapped another or was lost";
    frame = step.frame_count_after;
  }
  EXPECT_EQ(frame, end);
}

TEST(Load, ConcurrentClientsAreAllAnsweredAndStepsAddUp)
{
  const std::uint64_t frames_before = world_frame_count();
  std::vector<ClientResult> results(kClients);
  std::vector<std::thread> threads;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kClients; ++i)
  {
    // kResolveCalls split as evenly as it goes.
    const int calls = kResolveCalls / kClients + (i < kResolveCalls % kClients ? 1 : 0);
    threads.emplace_back([i, calls, &results] { results[i] = LoadClient(i, calls).run(); });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  const double wall_s = elapsed_ms(start) / 1000.0;

  Latencies all;
  std::vector<StepRecord> steps;
  std::uint64_t frames_requested = 0;
  int resolves = 0;
  for (const ClientResult& result : results)
  {
    all.resolve_ms.insert(all.resolve_ms.end(), result.latencies.resolve_ms.begin(), result.latencies.resolve_ms.end());
    all.step_ms.insert(all.step_ms.end(), result.latencies.step_ms.begin(), result.latencies.step_ms.end());
    steps.insert(steps.end(), result.steps.begin(), result.steps.end());
    frames_requested += result.frames_requested;
    resolves += result.resolves_done;
  }
  EXPECT_EQ(resolves, kResolveCalls);
  const std::uint64_t frames_after = world_frame_count();
  EXPECT_EQ(frames_after, frames_before + frames_requested);
  expect_serialized(steps, frames_before, frames_after);

  report("resolve_contacts", all.resolve_ms);
  report("step_world", all.step_ms);
  std::cout << "[load] " << kClients << " clients, " << resolves << " resolve_contacts and " << all.step_ms.size()
            << " step_world calls (" << frames_requested << " frames) in " << std::fixed << std::setprecision(2)
            << wall_s << " s" << std::endl;
  ::testing::Test::RecordProperty("wall_s", format_ms(wall_s));
  ::testing::Test::RecordProperty("frames_requested", std::to_string(frames_requested));
}

}  // namespace
}  // namespace collision2d

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_load");
  ros::NodeHandle handle;
  for (const char* service : {"resolve_contacts", "step_world", "get_world"})
  {
    if (!ros::service::waitForService(service, ros::Duration(collision2d::kServiceWait)))
    {
      ADD_FAILURE() << service << " never came up";
    }
  }
  return RUN_ALL_TESTS();
}
