// Golden trajectories: a hash of every body's state, every reported contact
// impulse and the step report after a run of shipped scenes, at the defaults
// and under setting sets that exercise each branch of the step. A refactor
// must keep every hash bit for bit; a commit that changes behaviour on
// purpose re-pins the hashes it changes and says why.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <ostream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/random_scenes.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"
#include "row_lanes_support.h"
#include "soft_rows.h"

namespace collision2d
{
namespace
{
/// FNV-1a over the raw bytes of doubles: any change of any bit shows.
class Hash
{
public:
  void add(double value)
  {
    unsigned char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    for (unsigned char byte : bytes)
    {
      state_ = (state_ ^ byte) * kPrime;
    }
  }
  void add(Vec2 v)
  {
    add(v.x);
    add(v.y);
  }
  std::uint64_t value() const { return state_; }

private:
  static constexpr std::uint64_t kPrime = 1099511628211ULL;
  std::uint64_t state_ = 14695981039346656037ULL;
};

/// Which of the World's two step pipelines a run pins.
enum class Pipeline
{
  Fx2d,
  Soft
};

/// Steps the scene frame by frame and hashes the state after every frame, so
/// a difference that later heals still shows.
std::uint64_t run_hash(const Scene& scene, Pipeline pipeline, const std::function<void(WorldSettings&)>& tweak,
                       int frames)
{
  Scene s = scene;
  s.settings.soft_step = pipeline == Pipeline::Soft;
  tweak(s.settings);
  World world = make_world(s);
  Hash hash;
  for (int f = 0; f < frames; ++f)
  {
    const StepReport report = world.step();
    for (BodyId id : world.body_ids())
    {
      const Body& b = world.body(id);
      hash.add(b.position());
      hash.add(b.theta());
      hash.add(b.velocity());
      hash.add(b.omega());
      hash.add(world.is_sleeping(id) ? 1.0 : 0.0);
    }
    for (const WorldContact& c : world.contacts())
    {
      hash.add(static_cast<double>(c.a));
      hash.add(static_cast<double>(c.b));
      hash.add(c.contact.point);
      hash.add(c.contact.penetration);
      hash.add(c.impulse.normal);
      hash.add(c.impulse.tangent);
      hash.add(c.sliding ? 1.0 : 0.0);
    }
    hash.add(report.max_penetration);
    hash.add(report.velocity_residual);
    hash.add(static_cast<double>(report.exact_islands));
    hash.add(static_cast<double>(report.exact_fallbacks));
  }
  return hash.value();
}

struct Golden
{
  const char* name;
  Pipeline pipeline;
  std::function<Scene()> scene;
  std::function<void(WorldSettings&)> tweak;
  int frames;
  std::uint64_t expected;
};

void defaults(WorldSettings&) {}

const Golden kGolden[] = {
    {"pyramid_defaults", Pipeline::Fx2d, [] { return scenes::pyramid(10); }, defaults, 120, 0xa04f2bb62b7d82a5ULL},
    {"pyramid_8x4", Pipeline::Fx2d, [] { return scenes::pyramid(10); },
     [](WorldSettings& s) {
       s.substeps = 8;
       s.velocity_iterations = 4;
     },
     60, 0x1a9a15c3f0dcfe8aULL},
    {"pyramid_position_block", Pipeline::Fx2d, [] { return scenes::pyramid(10); },
     [](WorldSettings& s) {
       s.position_block = true;
       s.position_iterations = 2;
     },
     60, 0xfb1d050cde778ccdULL},
    {"pyramid_warm_before_integration", Pipeline::Fx2d, [] { return scenes::pyramid(10); },
     [](WorldSettings& s) {
       s.warm_start_before_integration = true;
     },
     60, 0xb42a024f68818025ULL},
    {"pyramid_exact", Pipeline::Fx2d, [] { return scenes::pyramid(5); },
     [](WorldSettings& s) { s.solver_mode = SolverMode::Exact; }, 60, 0x4cdd0760d6e94bdeULL},
    {"pyramid_sleeping", Pipeline::Fx2d, [] { return scenes::pyramid(10); },
     [](WorldSettings& s) {
       s.sleeping = Toggle::On;
       s.sleep_time = 0.1;
     },
     150, 0x825a6730d85f8f72ULL},
    {"pyramid_soft_step", Pipeline::Soft, [] { return scenes::pyramid(10); }, defaults, 120, 0x37a636e800d366acULL},
    {"pyramid_soft_step_sleeping", Pipeline::Soft, [] { return scenes::pyramid(10); },
     [](WorldSettings& s) {
       s.sleeping = Toggle::On;
       s.sleep_time = 0.1;
     },
     150, 0xe14cdd5978d23393ULL},
    {"pyramid_exact_soft_step", Pipeline::Soft, [] { return scenes::pyramid(5); },
     [](WorldSettings& s) { s.solver_mode = SolverMode::Exact; }, 60, 0x5ff538c286a156bbULL},
    {"heavy_on_light_exact_soft_step", Pipeline::Soft, [] { return scenes::heavy_on_light(1e6); },
     [](WorldSettings& s) { s.solver_mode = SolverMode::Exact; }, 120, 0xbd408e67022ce4dbULL},
    {"column_soft_step", Pipeline::Soft, [] { return scenes::column(20); }, defaults, 120, 0xbe29083fdd8d27f6ULL},
    {"gas_soft_step", Pipeline::Soft, [] { return scenes::elastic_gas(200); }, defaults, 120, 0x2d530fc84ff0fbf1ULL},
    {"cradle_soft_step", Pipeline::Soft, [] { return scenes::newtons_cradle(5); }, defaults, 120, 0x0097b9090a8da9cfULL},
    {"incline_soft_step", Pipeline::Soft, [] { return scenes::incline(); }, defaults, 120, 0x1dd76887a0bff7bcULL},
    {"incline_sliding_soft_step", Pipeline::Soft, [] { return scenes::incline(0.6, 0.5, 0.3); }, defaults, 120, 0xc50cffb3d4109831ULL},
    {"bouncing_soft_step", Pipeline::Soft, [] { return scenes::bouncing_disks(); }, defaults, 180, 0x4358f0c34771397cULL},
    {"bullet_soft_step", Pipeline::Soft, [] { return scenes::bullet_wall(); }, defaults, 30, 0x467559917c196034ULL},
    {"demo_soft_step", Pipeline::Soft, [] { return scenes::demo(); }, defaults, 120, 0xfe805a463a7f652eULL},
    {"column_defaults", Pipeline::Fx2d, [] { return scenes::column(20); }, defaults, 120, 0xac173e8a2b9d9916ULL},
    {"gas_defaults", Pipeline::Fx2d, [] { return scenes::elastic_gas(200); }, defaults, 120, 0x95df6558a7b1d529ULL},
    {"gas_no_toggles", Pipeline::Fx2d, [] { return scenes::elastic_gas(100); },
     [](WorldSettings& s) {
       s.rotation = Toggle::On;
       s.friction = Toggle::On;
       s.warm_starting = Toggle::Off;
     },
     60, 0xf5c12fbe1f0becccULL},
    {"cradle_defaults", Pipeline::Fx2d, [] { return scenes::newtons_cradle(5); }, defaults, 120, 0xf9c820f5c2aa202bULL},
    {"incline_defaults", Pipeline::Fx2d, [] { return scenes::incline(); }, defaults, 120, 0x7b8876f6d22680abULL},
    {"incline_sliding", Pipeline::Fx2d, [] { return scenes::incline(0.6, 0.5, 0.3); }, defaults, 120, 0x726a4ca7660d503bULL},
    {"bouncing_defaults", Pipeline::Fx2d, [] { return scenes::bouncing_disks(); }, defaults, 180, 0xc00e709942ea150bULL},
    {"bullet_defaults", Pipeline::Fx2d, [] { return scenes::bullet_wall(); }, defaults, 30, 0x284a3ca8f63749c5ULL},
    {"demo_defaults", Pipeline::Fx2d, [] { return scenes::demo(); }, defaults, 120, 0x3fbdeace0c8fcfc5ULL},
    {"heavy_on_light_exact", Pipeline::Fx2d, [] { return scenes::heavy_on_light(1e6); },
     [](WorldSettings& s) { s.solver_mode = SolverMode::Exact; }, 120, 0x1fe96c18f10d53b6ULL},
    {"heavy_on_light_exact_velocity_only", Pipeline::Fx2d, [] { return scenes::heavy_on_light(1e3); },
     [](WorldSettings& s) {
       s.solver_mode = SolverMode::Exact;
       s.exact_position_correction = false;
     },
     60, 0xf15b95fb7dcb07b0ULL},
};

/// gtest names a failing case by its scene and settings, not its bytes.
void PrintTo(const Golden& golden, std::ostream* os) { *os << golden.name; }

class WorldGolden : public ::testing::TestWithParam<Golden>
{
};

TEST_P(WorldGolden, TrajectoryHashIsPinned)
{
  const Golden& g = GetParam();
  const std::uint64_t hash = run_hash(g.scene(), g.pipeline, g.tweak, g.frames);
  // Printed so a commit that changes behaviour on purpose can re-pin.
  std::printf("golden %s 0x%016llxULL\n", g.name, static_cast<unsigned long long>(hash));
  EXPECT_EQ(hash, g.expected) << g.name;
}

/// ContactSolver's entry points on the soak's random islands: resolve and
/// step in both modes, hashed over every body and the report.
std::uint64_t contact_solver_hash(SolverMode mode, bool step)
{
  scenes::RandomSceneGenerator generator(2024);
  Hash hash;
  for (int n = 0; n < 200; ++n)
  {
    scenes::RandomScene scene = generator.next();
    ContactSolver solver(scene.restitution, scene.friction);
    solver.set_mode(mode);
    const SolveReport report = step ? solver.step(scene.bodies) : solver.resolve(scene.bodies);
    for (const Body& b : scene.bodies)
    {
      hash.add(b.position());
      hash.add(b.theta());
      hash.add(b.velocity());
      hash.add(b.omega());
    }
    hash.add(static_cast<double>(report.iterations));
    hash.add(report.max_residual);
    hash.add(report.total_normal_impulse);
    hash.add(report.time_of_impact);
  }
  return hash.value();
}

TEST(ContactSolverGolden, ResolveAndStepHashesArePinned)
{
  const struct
  {
    const char* name;
    SolverMode mode;
    bool step;
    std::uint64_t expected;
  } kRuns[] = {
      {"resolve_iterative", SolverMode::Iterative, false, 0xa4f20264a6a51055ULL},
      {"resolve_exact", SolverMode::Exact, false, 0x2a2bb98bfed60545ULL},
      {"step_iterative", SolverMode::Iterative, true, 0xf351a46b1397672dULL},
      {"step_exact", SolverMode::Exact, true, 0xc875ed56f2f432bdULL},
  };
  for (const auto& run : kRuns)
  {
    const std::uint64_t hash = contact_solver_hash(run.mode, run.step);
    std::printf("golden %s 0x%016llxULL\n", run.name, static_cast<unsigned long long>(hash));
    EXPECT_EQ(hash, run.expected) << run.name;
  }
}

TEST(WorldGoldenRuns, AreRepeatable)
{
  // The hash is a function of the inputs only: two runs in one process agree.
  const Golden& g = kGolden[0];
  EXPECT_EQ(run_hash(g.scene(), g.pipeline, g.tweak, 30), run_hash(g.scene(), g.pipeline, g.tweak, 30));
}

TEST(WorldGoldenRuns, WorkersDoNotChangeTrajectories)
{
  // The narrow phase is split across the workers, each writing only its own
  // pairs' results: every bit of every run must match the one-worker pin.
  for (const char* name : {"pyramid_soft_step", "pyramid_defaults", "gas_soft_step", "demo_soft_step",
                           "pyramid_soft_step_sleeping"})
  {
    const Golden* golden = nullptr;
    for (const Golden& g : kGolden)
    {
      golden = std::string(g.name) == name ? &g : golden;
    }
    ASSERT_NE(golden, nullptr) << name;
    for (int workers : {2, 4})
    {
      const auto tweak = [&](WorldSettings& s) {
        golden->tweak(s);
        s.workers = workers;
      };
      EXPECT_EQ(run_hash(golden->scene(), golden->pipeline, tweak, golden->frames), golden->expected)
          << name << " with " << workers << " workers";
    }
  }
}

TEST(WorldGoldenRuns, SharedSoftPassesDoNotChangeTrajectories)
{
  // Scenes large enough that the workers share every colour of the soft
  // passes, the narrow phase, the contact rows and the per-point and
  // per-body stages (the gas also sweeps fast disks; the sleeping pyramid
  // carries its contacts once asleep): every bit must match one worker's run.
  const auto sleeping = [] {
    Scene scene = scenes::pyramid(30);
    scene.settings.sleeping = Toggle::On;
    scene.settings.sleep_time = 0.1;
    return scene;
  };
  // Without gravity every contact sorts level, so the ground's contacts fall
  // in every worker's share of a colour: the rows read the ground there but
  // must not write it back. Two workers writing one body race even when they
  // write the same value, which no hash shows: a ThreadSanitizer build of
  // this test reported it before the rows skipped such bodies.
  const auto flat_layers = [] {
    constexpr int kPerLayer = 190;
    constexpr int kBoxes = 3 * kPerLayer;
    const Scene pyramid = scenes::pyramid(70);
    Scene scene = pyramid;
    scene.settings.gravity = Vec2{0.0, 0.0};
    scene.bodies.clear();
    int placed = 0;
    for (SceneBody b : pyramid.bodies)
    {
      if (b.body.type() == BodyType::Dynamic)
      {
        if (placed == kBoxes)
        {
          continue;
        }
        b.body.set_position(Vec2{-0.5 * kPerLayer + placed % kPerLayer, 0.5 + placed / kPerLayer});
        ++placed;
      }
      scene.bodies.push_back(b);
    }
    return scene;
  };
  const std::pair<std::function<Scene()>, int> kRuns[] = {{[] { return scenes::pyramid(40); }, 20},
                                                          {[] { return scenes::pyramid(70); }, 20},
                                                          {[] { return scenes::elastic_gas(3000); }, 20},
                                                          {sleeping, 60},
                                                          {flat_layers, 10}};
  const auto with = [](int workers) { return [workers](WorldSettings& s) { s.workers = workers; }; };
  for (const auto& [scene, frames] : kRuns)
  {
    const std::uint64_t one = run_hash(scene(), Pipeline::Soft, with(1), frames);
    EXPECT_EQ(run_hash(scene(), Pipeline::Soft, with(2), frames), one);
    EXPECT_EQ(run_hash(scene(), Pipeline::Soft, with(4), frames), one);
  }
  // The Fx2D step shares detection, prepare and the velocity copies too.
  const std::uint64_t one = run_hash(scenes::pyramid(70), Pipeline::Fx2d, with(1), 10);
  EXPECT_EQ(run_hash(scenes::pyramid(70), Pipeline::Fx2d, with(2), 10), one);
}

TEST(WorldGoldenRuns, WideRowsMatchTheScalarPath)
{
  // The scalar rows are the reference the soft-step pins were made with;
  // every lane path this build and CPU have (two lanes on SSE2 or NEON, four
  // on AVX2, eight on AVX-512) must give every bit of them. The widest is
  // the default, which TrajectoryHashIsPinned runs.
  detail::reset_row_lanes();
  const detail::RowLanes widest = detail::row_lanes();
  test::for_each_row_lanes([widest](const char* label) {
    if (detail::row_lanes() == widest)
    {
      std::printf("%s rows: the default path, checked by TrajectoryHashIsPinned\n", label);
      return;
    }
    std::printf("%s rows: checked\n", label);
    for (const Golden& g : kGolden)
    {
      if (g.pipeline == Pipeline::Soft)
      {
        EXPECT_EQ(run_hash(g.scene(), g.pipeline, g.tweak, g.frames), g.expected)
            << g.name << " (" << label << " rows)";
      }
    }
  });
}

INSTANTIATE_TEST_SUITE_P(Scenes, WorldGolden, ::testing::ValuesIn(kGolden),
                         [](const ::testing::TestParamInfo<Golden>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace collision2d
