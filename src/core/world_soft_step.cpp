// The soft step (WorldSettings::soft_step), top-down. Contacts are found once
// per frame, for every pair within a speculative margin plus how far its
// bodies can travel in the frame, and prepared with their Newton targets from
// the velocities before the frame (a gap still open is closed under gravity
// first). Each substep integrates gravity, warm starts, solves the contacts as
// damped springs, moves the bodies and relaxes (solves again without the
// push-out, so no correction stays behind as velocity). A contact's gap
// follows from the bodies' pose changes, not from detecting again. At each
// substep's end, restitution drives the contacts the substep pushed to their
// Newton targets (e times the approach speed at the substep's start), iterated
// to the fixed point: a body that meets several others in turn within one
// frame bounces off each as it meets it. After the substeps no body's
// centroid may have passed into a static body (world_static_crossing.cpp).
// Two kinds of contact follow their geometry before each pass instead: a disk
// on the face of a turning kinematic body (world_turning_faces.cpp), and a
// disk and a vertex or another disk whose centres slide past each other
// (world_round_points.cpp).
// Static friction holds position, not only velocity: a sticking point
// remembers how far it has slipped since it stuck (across frames, with its
// impulses) and its friction pulls that back at the contact's rate, so a stack
// cannot creep by round-off-sized slips.
// In the exact mode each pass solves every island as one LCP instead
// (world_exact.cpp): from scratch, a gap allowed to close, an overlap pushed
// out rigidly at the soft rate; the relax adds normal impulses only.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "turn.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A contact's stiffness is capped at this fraction of the substep rate: a
/// spring much stiffer than the substeps can follow would ring.
constexpr double kMaxHertzPerSubstepRate = 0.25;
/// Contacts with a body that cannot move are this much stiffer, so a stack
/// is not pressed into the ground by its own weight.
constexpr double kStaticStiffnessFactor = 2.0;
/// A touching polygon turns at most this much per substep (rad): the frame's
/// contacts follow its pose from lever arms fixed at prepare, which a faster
/// spin would swing through the surface it touches (a disk's do not swing).
constexpr double kMaxTurnPerSubstep = 0.25 * 3.14159265358979323846;

}  // namespace

void WorldImpl::soft_frame(StepContext& ctx, StepReport& report)
{
  ctx.first = true;
  ctx.warm = ctx.warm_available;
  // 1. Collide once: contacts within the margin, impulses from the last
  // frame, each pair's points prepared (masses, softness) as they are added.
  springs_ = contact_springs(ctx);
  detect(ctx, settings_.speculative_margin, report, true);  // world_contacts.cpp
  // 2. Prepare the bodies (velocities, poses, which touch); the rows from
  // the prepared points.
  prepare_soft_bodies(ctx.effects.rotation);
  find_followed_points();                                 // world_turning_faces.cpp, world_round_points.cpp
  if (rows_on())
  {
    soft_rows_.pack(points_, velocity_, ctx.effects.friction, springs_, workers_, frame_block_);  // soft_rows.cpp
  }
  find_bounce_points();                                   // world_soft_restitution.cpp
  // 3. Substeps, and no centroid passed into a static body on the way.
  bool moved_far = false;
  for (int k = 0; k < settings_.substeps; ++k)
  {
    const bool last = k + 1 == settings_.substeps;
    aim_bounces();
    integrate_velocities(ctx, k == 0);
    solve_contacts(ctx, true, report);
    moved_far = integrate_positions(ctx, report, last);
    solve_contacts(ctx, false, report);                   // relax
    restitute(report);
    ++report.substeps;
  }
  if (moved_far)
  {
    stop_static_crossings(ctx, report, true);             // world_static_crossing.cpp
  }
  follow_points(ctx.h, true);                             // as prepared, for the publish
  // 4. The poses and velocities onto the bodies, checked finite before the
  // contacts are published; the impulses kept for next frame: publishing
  // reads each point's back from its row.
  const std::size_t bad = place_bodies(true);
  if (bad != bodies_.size())
  {
    throw_non_finite(bad);                                // world_step.cpp
  }
  if (rows_on())
  {
    soft_rows_.drop_spare_body(velocity_);
  }
  report.contact_count = points_.size() + sleeping_contacts_.size();
  if (ctx.effects.sleeping)
  {
    make_room_to_move_contacts(points_.size());                 // world_sleep.cpp: nothing after the publish allocates
  }
  publish_contacts(true);                                 // slips carried, gaps followed
  cache_h_ = ctx.h;
}

ContactSprings WorldImpl::contact_springs(const StepContext& ctx) const
{
  const double hertz = std::min(settings_.contact_hertz, kMaxHertzPerSubstepRate * ctx.inv_h);
  const double damping = settings_.contact_damping_ratio;
  return ContactSprings{make_softness(hertz, damping, ctx.h),
                        make_softness(kStaticStiffnessFactor * hertz, damping, ctx.h)};
}

bool WorldImpl::prepare_pair_points(const ActiveEffects& effects, std::size_t k)
{
  const std::size_t begin = pair_rows_[k];
  const std::size_t end = pair_rows_[k + 1];
  prepare_point_range(effects, begin, end, false);  // world_solve.cpp: restitution aims per substep
  return prepare_soft_range(begin, end);
}

void WorldImpl::prepare_soft_bodies(bool rotation)
{
  const std::size_t n = bodies_.size();
  if (swept_reach_sq_.size() != n)  // only here are these sized, all together
  {
    velocity_.resize(n);
    stopped_.resize(n);
    touching_.resize(n);
    held_position_.resize(n);
    held_theta_.resize(n);
    prepared_position_.resize(n);
    prepared_theta_.resize(n);
    frame_position_.resize(n);
    frame_theta_.resize(n);
    frame_motion_.resize(n);
    swept_reach_sq_.resize(n);
  }
  // One pass over the body records, which a large world streams from memory.
  sweep_every_body_ = !sweep_candidates_pay();            // world_toi.cpp
  const bool candidates = !sweep_every_body_;
  if (candidates)
  {
    swept_.resize(bodies_.size());
  }
  const FreeSpeedBound bound =
      candidates ? free_speed_bound(settings_.dt / settings_.substeps, rotation) : FreeSpeedBound{};
  std::atomic<bool> any_may_turn_fast{false};
  for_each_body([&](std::size_t i) {
    load_velocity(i);                                     // world_solve.cpp
    reset_body_motion(i);
    if (candidates)
    {
      swept_[i] = 0;  // each substep sets only the candidates' flags
      if (may_turn_fast(i, bound) || may_spin_fast(i, bound))
      {
        any_may_turn_fast.store(true, std::memory_order_relaxed);
      }
    }
  });
  // The frame's active points are those of the pairs that hit (detect()),
  // so the short pair list says which bodies they touch; a substep can make
  // only those fast unless a free body may turn fast on its own.
  sweep_candidates_.clear();
  for (std::size_t k = 0; k < pairs_.size(); ++k)
  {
    if (pair_touches(k))
    {
      note_touching(pairs_[k].first);                     // world_toi.cpp
      note_touching(pairs_[k].second);
    }
  }
  choose_sweep_pass(any_may_turn_fast.load());
}

bool WorldImpl::prepare_soft_range(std::size_t begin, std::size_t end)
{
  bool bounces = false;
  for (std::size_t k = begin; k < end; ++k)
  {
    ContactPoint& p = points_[k];
    if (!p.active)
    {
      continue;
    }
    p.base_separation = p.separation - dot(p.r_b - p.r_a, p.normal);
    bounces = bounces || p.restitution > 0.0;
  }
  // A manifold's normal block is the same all frame (lever arms are fixed).
  // The rows' colouring reads each manifold here, while it is in cache.
  const Vec2 up = -settings_.gravity;
  for (std::size_t k = begin; k < end; k += points_[k].count == 2 ? 2 : 1)
  {
    ContactPoint& p = points_[k];
    const ContactPoint* second = p.count == 2 ? &points_[k + 1] : nullptr;
    if (second != nullptr)
    {
      soft_rows_.note_no_manifold(k + 1);
    }
    if (!p.active)
    {
      soft_rows_.note_no_manifold(k);
      continue;
    }
    if (second != nullptr)
    {
      p.pair_k12 = pair_coupling(p, *second);
      p.pair_block = block_solvable(p.k_n, p.pair_k12, second->k_n);
    }
    soft_rows_.note_manifold(k, p, second, up);
  }
  return bounces;
}

void WorldImpl::reset_body_motion(std::size_t i)
{
  prepared_position_[i] = bodies_[i].position();
  prepared_theta_[i] = bodies_[i].theta();
  frame_position_[i] = bodies_[i].position();
  frame_theta_[i] = bodies_[i].theta();
  frame_motion_[i] = frame_motion(i);
  stopped_[i] = false;
  touching_[i] = false;
  swept_reach_sq_[i] = sweep_reach_sq(i);
}

void WorldImpl::integrate_velocities(const StepContext& ctx, bool first)
{
  const Vec2 gravity_kick = settings_.gravity * ctx.h;
  const double max_spin = kMaxTurnPerSubstep * ctx.inv_h;
  // After the first substep a body no contact touches has had this kick in
  // the last move pass (integrate_positions), while its velocity was in cache.
  for_each_body([&](std::size_t i) {
    if ((first || touching_[i]) && frame_motion_[i] == FrameMotion::Dynamic)
    {
      velocity_[i].v = velocity_[i].v + gravity_kick;
      if (touching_[i] && !disk_[i])  // a disk's contacts do not swing (follow_pose)
      {
        velocity_[i].omega = std::clamp(velocity_[i].omega, -max_spin, max_spin);
      }
    }
  });
}

void WorldImpl::solve_contacts(const StepContext& ctx, bool use_bias, StepReport& report)
{
  follow_points(ctx.h);                                   // world_turning_faces.cpp, world_round_points.cpp
  if (settings_.solver_mode == SolverMode::Exact)
  {
    // Each island at once by pivoting, from scratch (no warm start); an
    // island too large for it goes through the soft passes below.
    aim_exact_targets(ctx, use_bias);
    solve_exact_islands(report, &exact_targets_, !use_bias);  // world_exact.cpp
  }
  // The warm start goes in once; a later pass goes on from the impulses the
  // one before left (more passes carry a tall stack's weight further down).
  for (int pass = 0; pass < settings_.soft_iterations; ++pass)
  {
    soft_pass(ctx, use_bias, use_bias && pass == 0);     // world_soft_solve.cpp
  }
}

void WorldImpl::aim_exact_targets(const StepContext& ctx, bool use_bias)
{
  // The velocity each point must reach: a gap may close within the substep;
  // an overlap is pushed out at the soft contact's rate (rigidly, so a heavy
  // body's weight leaves no spring's sag), or only held in the relax.
  exact_targets_.resize(points_.size());
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    ContactPoint& p = points_[k];
    p.exact = false;
    const double s = current_separation(p, velocity_);
    // An inactive point keeps a spring that pushes nothing (its target goes unused).
    const Softness spring = p.active ? springs_.of(p) : Softness{};
    const double push = std::min(-spring.mass_scale * spring.bias_rate * s, settings_.contact_push_speed);
    exact_targets_[k] = s > 0.0 ? -s * ctx.inv_h : (use_bias ? push : 0.0);
  }
}

CarriedSlip WorldImpl::carry_slip(const ContactPoint& p, bool sliding, Vec2 offset) const
{
  if (p.kinetic)
  {
    return {sliding, 0.0};
  }
  // A sticking point that met the static bound slides only once it has
  // slipped `slop` from where it stuck: a box settling on a slope at one
  // or two substeps rocks on its corners for a frame or two, and a bound
  // met then would latch the kinetic cone, which cannot hold the box.
  const double drift = p.anchor_drift + slip_at(p, offset);
  const bool slides = sliding && std::abs(drift) >= settings_.slop;
  return {slides, slides ? 0.0 : drift};
}

bool WorldImpl::integrate_positions(StepContext& ctx, StepReport& report, bool last)
{
  // As advance() (world_step.cpp): fast bodies swept for time of impact
  // (world_toi.cpp, on one thread: it pairs bodies), then every body moved
  // with its velocity, shared among the workers. A body stopped at its time
  // of impact stays there for the rest of the frame, velocity kept: no
  // contact stops it before the next frame's collide finds the touching pair.
  const bool swept = sweep(ctx.h, report, false, ctx.effects.rotation);  // world_toi.cpp
  ctx.effects.time_of_impact = ctx.effects.time_of_impact || swept;
  poses_pending_ = true;
  const Vec2 gravity_kick = settings_.gravity * ctx.h;
  const bool kick_free = !last;
  std::atomic<bool> far{false};
  // The poses stay in frame_position_ and frame_theta_ and go onto the
  // bodies once per frame (place_bodies), as do the velocities: a substep
  // reads and writes no body record, which a large world streams from memory.
  // Inlined by request: the crossing check made the compiler call it per body.
  for_each_body([&](std::size_t i) __attribute__((always_inline)) {
    move_in_frame(i, ctx, swept);
    follow_body(i, ctx);
    if (kick_free && !touching_[i] && frame_motion_[i] == FrameMotion::Dynamic)
    {
      // Nothing reads its velocity before the next substep's kick would.
      velocity_[i].v = velocity_[i].v + gravity_kick;
    }
    // Checked while the poses are in cache: stop_static_crossings is rarely needed.
    if (last && moved_far_in_frame(i))
    {
      far.store(true, std::memory_order_relaxed);
    }
  });
  return far.load();
}

void WorldImpl::move_in_frame(std::size_t i, const StepContext& ctx, bool swept)
{
  // move_body's arithmetic on the frame's poses, the velocities the solver left.
  const FrameMotion motion = frame_motion_[i];
  if (motion == FrameMotion::Still)
  {
    return;
  }
  const BodyVelocity& state = velocity_[i];
  const double travel = swept ? toi_[i] * ctx.h : ctx.h;
  frame_position_[i] = frame_position_[i] + state.v * travel;
  if (turns(ctx, motion, state.omega))
  {
    frame_theta_[i] = frame_theta_[i] + state.omega * turn_time(i, ctx, swept);
  }
}

std::size_t WorldImpl::place_bodies(bool velocities)
{
  const bool poses = poses_pending_;
  poses_pending_ = false;
  std::atomic<std::size_t> first_bad{bodies_.size()};
  if (!poses && !velocities)
  {
    return first_bad.load();
  }
  for_each_body([&](std::size_t i) {
    Body& b = bodies_[i];
    if (velocities)
    {
      store_velocity(i);                                  // world_solve.cpp
    }
    if (poses)
    {
      if (frame_motion_[i] != FrameMotion::Still)
      {
        b.set_position(frame_position_[i]);
      }
      const double theta = frame_theta_[i];
      if (theta != b.theta() || std::signbit(theta) != std::signbit(b.theta()))
      {
        b.set_theta(theta);
      }
    }
    // Checked here while the record is in cache: a pass over the bodies fewer.
    note_non_finite(i, first_bad);
  });
  return first_bad.load();
}

void WorldImpl::follow_body(std::size_t i, const StepContext& ctx)
{
  Vec2& position = frame_position_[i];
  if (stopped_[i])
  {
    position = held_position_[i];
    frame_theta_[i] = held_theta_[i];
    return;
  }
  if (clamped(i))
  {
    stopped_[i] = true;
    held_position_[i] = position;
    held_theta_[i] = frame_theta_[i];
  }
  else if (!touching_[i] && frame_motion_[i] == FrameMotion::Dynamic)
  {
    // In free flight the substep's mean velocity is the end one less half
    // its gravity kick: a thrown body follows its parabola exactly.
    position = position - (0.5 * ctx.h * ctx.h) * settings_.gravity;
  }
  if (touching_[i])  // only contact points read a body's motion since prepare
  {
    follow_pose(i);
  }
}

double WorldImpl::followed_penetration()
{
  // An inactive point's -infinity leaves the deepest as it is.
  return max_over(points_.size(), kMinSharedPoints, 0.0, [this](std::size_t k) {
    const ContactPoint& p = points_[k];
    return p.active ? -current_separation(p, velocity_) : -std::numeric_limits<double>::infinity();
  });
}

}  // namespace detail
}  // namespace collision2d
