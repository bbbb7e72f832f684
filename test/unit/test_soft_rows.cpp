// The soft step's batches of one-point manifolds (soft_rows.h) against the
// point verbs they stand for (contact_kernel.h): on random contacts, every
// lane path this build and CPU have must give the velocities, impulses and
// friction states of warm_start, solve_soft_normal and solve_friction with
// the anchor pull, bit for bit. And a frame of one or two manifolds, which
// skips the colours, between coloured ones: nothing left behind. And a large
// frame packed by several workers: one worker's colours, lanes and bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "contact_kernel.h"
#include "row_lanes_support.h"
#include "soft_rows.h"
#include "worker_pool.h"

namespace collision2d
{
namespace
{
using detail::BodyVelocity;
using detail::ContactPoint;

constexpr double kInvH = 240.0;   // 1/s: 4 substeps of 1/60 s
constexpr double kMaxPush = 3.0;  // m/s
/// Manifolds: three full batches and a last one with three lanes and one of
/// padding, so padding and every lane position are checked.
constexpr std::size_t kManifolds = 15;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Scene
{
  std::vector<BodyVelocity> bodies;
  detail::ContactPoints points;
};

/// The soft step's default spring, for every point (moving or not).
detail::ContactSprings springs()
{
  const detail::Softness spring = detail::make_softness(40.0, 10.0, 1.0 / kInvH);
  return detail::ContactSprings{spring, spring};
}

/// A point's masses from its bodies.
void prepare_soft(ContactPoint& p, const std::vector<BodyVelocity>& bodies)
{
  p.inv_mass_a = bodies[p.a].inv_mass;
  p.inv_mass_b = bodies[p.b].inv_mass;
  p.inv_inertia_a = bodies[p.a].inv_inertia;
  p.inv_inertia_b = bodies[p.b].inv_inertia;
  detail::prepare_masses(p, 0.0);
}

/// Random one-point contacts between disjoint pairs of bodies (2k, 2k + 1):
/// gaps open and closed, friction on and off, sticking, sliding and kinetic.
Scene random_scene(std::uint32_t seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  for (std::size_t i = 0; i < 2 * kManifolds; ++i)
  {
    const bool fixed = i % 2 == 0 && i % 6 == 0;  // some contacts are with the ground
    // Slow enough that most rough points stick and the pull counts.
    BodyVelocity b = detail::body_velocity(Vec2{0.01 * u(rng), 0.01 * u(rng)}, 0.01 * u(rng),
                                           fixed ? 0.0 : 1.0 + u(rng) * 0.5, fixed ? 0.0 : 2.0 + u(rng));
    b.moved = Vec2{1e-3 * u(rng), 1e-3 * u(rng)};
    const double turn = 0.01 * u(rng);
    b.turned_cos = std::cos(turn);
    b.turned_sin = std::sin(turn);
    s.bodies.push_back(b);
  }
  for (std::size_t k = 0; k < kManifolds; ++k)
  {
    ContactPoint p;
    p.a = static_cast<std::uint32_t>(2 * k);
    p.b = static_cast<std::uint32_t>(2 * k + 1);
    const double angle = 3.14159 * u(rng);
    p.normal = Vec2{std::cos(angle), std::sin(angle)};
    p.r_a = Vec2{0.5 * u(rng), 0.5 * u(rng)};
    p.r_b = Vec2{0.5 * u(rng), 0.5 * u(rng)};
    prepare_soft(p, s.bodies);
    p.base_separation = 2e-3 * u(rng);  // some speculative, some overlapping
    p.anchor_drift = 1e-3 * u(rng);
    p.lambda_n = std::max(0.0, u(rng));
    p.lambda_t = 0.01 * u(rng);
    // With an even seed the first batch has no friction at all: a path that
    // takes two batches at once must still solve the second one's.
    const bool smooth = k % 5 == 0 || (seed % 2 == 0 && k < detail::kRowLanes);
    p.mu_s = smooth ? 0.0 : 0.6;
    p.mu_k = smooth ? 0.0 : 0.4;
    p.kinetic = k % 3 == 0;
    p.sliding = k % 4 == 0;
    s.points.push_back(p);
  }
  return s;
}

/// The point verbs, as the soft step's passes call them on a manifold
/// outside the batches.
void solve_by_points(Scene& s, bool warm, bool use_bias)
{
  for (ContactPoint& p : s.points)
  {
    if (warm)
    {
      detail::warm_start(p, s.bodies);
    }
  }
  const detail::ContactSprings frame_springs = springs();
  for (ContactPoint& p : s.points)
  {
    const Vec2 offset = detail::anchor_offset(p, s.bodies);
    const detail::Softness& spring = frame_springs.of(p);
    detail::solve_soft_normal(p, spring, detail::separation_at(p, offset), s.bodies, kInvH, kMaxPush, use_bias);
    if (p.mu_s > 0.0 || p.mu_k > 0.0)
    {
      const double drift = p.kinetic ? 0.0 : p.anchor_drift + detail::slip_at(p, offset);
      const double pull = spring.mass_scale * spring.bias_rate * drift;
      detail::solve_friction(p, s.bodies, use_bias ? std::max(-kMaxPush, std::min(kMaxPush, pull)) : 0.0);
    }
  }
}

/// The same passes on the batches.
void solve_by_rows(Scene& s, bool warm, bool use_bias)
{
  detail::FrameBlock block;
  detail::SoftRows rows;
  detail::WorkerPool workers;
  rows.expect_points(s.points.size());
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    rows.note_manifold(k, s.points[k], nullptr, Vec2{0.0, 1.0});
  }
  rows.pack(s.points, s.bodies, true, springs(), workers, block);
  ASSERT_EQ(rows.colour_count(), 1u) << "disjoint pairs share one colour";
  ASSERT_TRUE(rows.others(0).empty()) << "every manifold is in a batch";
  if (warm)
  {
    rows.warm_start_rows(0, s.bodies);
  }
  rows.solve_rows(0, s.bodies, detail::RowPass{kInvH, kMaxPush, use_bias});
  rows.drop_spare_body(s.bodies);
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    ASSERT_NE(rows.impulses_of(k).normal, nullptr) << k;
    const detail::PointOutcome outcome = rows.point_outcome(k, s.points[k]);
    s.points[k].lambda_n = outcome.normal;
    s.points[k].lambda_t = outcome.tangent;
    s.points[k].sliding = outcome.sliding;
  }
}

TEST(SoftRows, OnePointBatchesGiveThePointVerbsBits)
{
  test::for_each_row_lanes([](const char* label) {
    int checked = 0;
    int sticking = 0;
    for (std::uint32_t seed = 1; seed <= 20; ++seed)
    {
      for (const bool use_bias : {true, false})
      {
        Scene expected = random_scene(seed);
        Scene batched = expected;
        solve_by_points(expected, use_bias, use_bias);
        solve_by_rows(batched, use_bias, use_bias);
        for (std::size_t i = 0; i < expected.bodies.size(); ++i)
        {
          const BodyVelocity& e = expected.bodies[i];
          const BodyVelocity& b = batched.bodies[i];
          EXPECT_TRUE(same_bits(e.v.x, b.v.x) && same_bits(e.v.y, b.v.y) && same_bits(e.omega, b.omega))
              << label << " seed " << seed << " body " << i;
        }
        for (std::size_t k = 0; k < expected.points.size(); ++k)
        {
          const ContactPoint& e = expected.points[k];
          const ContactPoint& b = batched.points[k];
          EXPECT_TRUE(same_bits(e.lambda_n, b.lambda_n) && same_bits(e.lambda_t, b.lambda_t))
              << label << " seed " << seed << " point " << k;
          EXPECT_EQ(e.sliding, b.sliding) << label << " seed " << seed << " point " << k;
          EXPECT_GE(b.lambda_n, 0.0);
          if (b.mu_s > 0.0)
          {
            sticking += b.sliding ? 0 : 1;
            EXPECT_LE(std::abs(b.lambda_t), (b.kinetic ? b.mu_k : b.mu_s) * b.lambda_n) << "inside the cone";
          }
        }
        ++checked;
      }
    }
    std::printf("%s rows: %d random scenes of %zu one-point manifolds matched bit for bit (%d rough points stuck)\n",
                label, checked, kManifolds, sticking);
    EXPECT_GT(sticking, checked) << "the scenes check sticking friction, pull included";
  });
}

/// Notes every point of `s` as a one-point manifold, the first `count`
/// only, and packs them.
void pack_first(detail::SoftRows& rows, Scene& s, std::size_t count, detail::WorkerPool& workers,
                detail::FrameBlock& block)
{
  rows.expect_points(s.points.size());
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    if (k < count)
    {
      rows.note_manifold(k, s.points[k], nullptr, Vec2{0.0, 1.0});
    }
    else
    {
      rows.note_no_manifold(k);
    }
  }
  rows.pack(s.points, s.bodies, true, springs(), workers, block);
  rows.drop_spare_body(s.bodies);
}

TEST(SoftRows, TwoManifoldsGoTopDownWithoutColoursAndLeaveNoneBehind)
{
  Scene s = random_scene(7);
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    s.points[k].point = Vec2{0.0, static_cast<double>(k)};  // the last is the highest
  }
  detail::FrameBlock block;
  detail::SoftRows rows;
  detail::WorkerPool workers;
  // 14 disjoint manifolds: one colour, three full batches and two manifolds
  // left to the point verbs.
  pack_first(rows, s, kManifolds - 1, workers, block);
  ASSERT_EQ(rows.colour_count(), 1u);
  EXPECT_EQ(rows.others(0).size(), 2u);
  // Two: no colours, no rows, the higher first.
  pack_first(rows, s, 2, workers, block);
  EXPECT_EQ(rows.colour_count(), 0u);
  EXPECT_EQ(rows.coloured(), 0u);
  EXPECT_EQ(rows.overflow(), (std::vector<std::size_t>{1, 0}));
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    EXPECT_EQ(rows.impulses_of(k).normal, nullptr) << "point " << k << " has no row";
  }
  // All 15 again: the colour holds its batches only, nothing left from before.
  pack_first(rows, s, kManifolds, workers, block);
  ASSERT_EQ(rows.colour_count(), 1u);
  EXPECT_TRUE(rows.others(0).empty());
  EXPECT_TRUE(rows.overflow().empty());
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    EXPECT_NE(rows.impulses_of(k).normal, nullptr) << "point " << k << " is in a batch";
  }
}

/// One-point contacts between random bodies of a few hundred, which share
/// bodies, so their manifolds need many colours; each at one of `heights`
/// heights (ties keep point order).
Scene crowded_scene(std::uint32_t seed, std::size_t points, int heights)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  constexpr std::uint32_t kBodies = 300;
  Scene s;
  for (std::uint32_t i = 0; i < kBodies; ++i)
  {
    s.bodies.push_back(detail::body_velocity(Vec2{u(rng), u(rng)}, u(rng), i % 50 == 0 ? 0.0 : 1.0, 2.0));
  }
  std::uniform_int_distribution<std::uint32_t> body(0, kBodies - 1);
  std::uniform_int_distribution<int> level(0, heights - 1);
  for (std::size_t k = 0; k < points; ++k)
  {
    ContactPoint p;
    p.a = body(rng);
    p.b = (p.a + 1 + body(rng) % (kBodies - 1)) % kBodies;
    p.normal = Vec2{0.0, 1.0};
    p.r_a = Vec2{0.5 * u(rng), -0.5};
    p.r_b = Vec2{0.5 * u(rng), 0.5};
    prepare_soft(p, s.bodies);
    p.lambda_n = std::max(0.0, u(rng));
    p.mu_s = 0.6;
    p.mu_k = 0.4;
    p.point = Vec2{u(rng), static_cast<double>(level(rng))};
    s.points.push_back(p);
  }
  return s;
}

/// Packs every `active_every`-th point of `s` as a one-point manifold on
/// `workers` workers, then solves each colour's batches once.
struct Packed
{
  Scene scene;
  detail::FrameBlock block;  ///< holds the rows
  detail::SoftRows rows;
  std::vector<std::ptrdiff_t> lanes;  ///< each point's impulse slot from the lowest, -1 without a row
};

void pack_crowded(Packed& out, const Scene& s, std::size_t active_every, int workers)
{
  out.scene = s;
  detail::WorkerPool pool;
  pool.resize(workers);
  out.rows.expect_points(s.points.size());
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    if (k % active_every == 0)
    {
      out.rows.note_manifold(k, s.points[k], nullptr, Vec2{0.0, 1.0});
    }
    else
    {
      out.rows.note_no_manifold(k);
    }
  }
  out.rows.pack(out.scene.points, out.scene.bodies, true, springs(), pool, out.block);
  const double* lowest = nullptr;
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    const double* at = out.rows.impulses_of(k).normal;
    lowest = at != nullptr && (lowest == nullptr || at < lowest) ? at : lowest;
  }
  for (std::size_t k = 0; k < s.points.size(); ++k)
  {
    const double* at = out.rows.impulses_of(k).normal;
    out.lanes.push_back(at == nullptr ? -1 : at - lowest);
  }
  for (std::size_t c = 0; c < out.rows.colour_count(); ++c)
  {
    out.rows.solve_rows(c, out.scene.bodies, detail::RowPass{kInvH, kMaxPush, true});
  }
  out.rows.drop_spare_body(out.scene.bodies);
}

TEST(SoftRows, PackingInPartsGivesOneWorkersColoursLanesAndBits)
{
  // Ordering and placing the rows are shared among the workers from a few
  // thousand points on; the colours, each colour's point-verb list, every
  // lane and the solved velocities must be one worker's. Cases: many heights,
  // all heights equal (every digit pass skipped), parts too small for a
  // radix sort of their own (sorted by comparison, then merged), and few
  // manifolds among many points (ordered by a comparison sort).
  struct Case
  {
    std::size_t points;
    std::size_t active_every;
    int heights;
  };
  for (const Case& c : {Case{6000, 1, 4000}, Case{6000, 1, 1}, Case{6000, 2, 7}, Case{6000, 10, 50}, Case{6000, 40, 50}})
  {
    const Scene s = crowded_scene(11, c.points, c.heights);
    Packed one;
    pack_crowded(one, s, c.active_every, 1);
    ASSERT_GT(one.rows.colour_count(), 4u) << "the manifolds share bodies";
    for (const int workers : {2, 3, 4})
    {
      Packed shared;
      pack_crowded(shared, s, c.active_every, workers);
      const std::string label = std::to_string(c.points / c.active_every) + " manifolds, " +
                                std::to_string(c.heights) + " heights, " + std::to_string(workers) + " workers";
      ASSERT_EQ(shared.rows.colour_count(), one.rows.colour_count()) << label;
      EXPECT_EQ(shared.rows.coloured(), one.rows.coloured()) << label;
      EXPECT_EQ(shared.rows.overflow(), one.rows.overflow()) << label;
      for (std::size_t colour = 0; colour < one.rows.colour_count(); ++colour)
      {
        EXPECT_EQ(shared.rows.others(colour), one.rows.others(colour)) << label << " colour " << colour;
      }
      EXPECT_EQ(shared.lanes, one.lanes) << label;
      for (std::size_t i = 0; i < s.bodies.size(); ++i)
      {
        const BodyVelocity& e = one.scene.bodies[i];
        const BodyVelocity& b = shared.scene.bodies[i];
        EXPECT_TRUE(same_bits(e.v.x, b.v.x) && same_bits(e.v.y, b.v.y) && same_bits(e.omega, b.omega))
            << label << " body " << i;
      }
    }
  }
}

}  // namespace
}  // namespace collision2d
