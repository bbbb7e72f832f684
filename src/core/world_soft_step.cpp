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
// frame bounces off each as it meets it (bodies whose passes find no fixed
// point keep the relax's velocities instead). After the substeps no body's
// centroid may have passed into a static body (world_static_crossing.cpp).
// Two kinds of contact follow their geometry before each pass instead: a disk
// on the face of a turning kinematic body (world_turning_faces.cpp), and a
// disk and a vertex or another disk whose centres slide past each other
// (world_round_points.cpp; one that can bounce is aimed once a substep).
// Static friction holds position, not only velocity: a sticking point
// remembers how far it has slipped since it stuck (across frames, with its
// impulses) and its friction pulls that back at the contact's rate, so a stack
// cannot creep by round-off-sized slips.
// In the exact mode each pass solves every island as one LCP instead
// (world_exact.cpp): from scratch, a gap allowed to close, an overlap pushed
// out rigidly at the soft rate; the relax adds normal impulses, or, in an
// island a moving kinematic body touches, solves again from the same start.
#include <algorithm>
#include <cmath>
#include <limits>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
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
  prepare_soft_bodies(ctx.effects.rotation);              // world_soft_bodies.cpp
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
    if (!round_points_.empty())
    {
      aim_round_bounces(ctx.h);                           // world_round_points.cpp
    }
    aim_bounces();
    integrate_velocities(ctx, k == 0);                    // world_soft_bodies.cpp
    solve_contacts(ctx, true, report);
    moved_far = integrate_positions(ctx, report, last);   // world_soft_bodies.cpp
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
  const std::size_t bad = place_bodies(true);             // world_soft_bodies.cpp
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
    make_room_to_move_contacts(points_.size());           // world_sleep.cpp: nothing after the publish allocates
  }
  publish_contacts(true);                                 // slips carried, gaps followed
  cache_h_ = ctx.h;
}

/// After prepare, before the rows are packed. Inline: most frames have
/// neither, by the census (counted at each edit, census_for_frame).
inline void WorldImpl::find_followed_points()
{
  turning_faces_.clear();
  round_points_.clear();
  if (census_.turning_face_bodies > 0)
  {
    list_turning_faces();
  }
  if (census_.disks > 0)
  {
    list_round_points();
  }
}

/// Before each pass (substeps of h seconds). `as_prepared`: after the
/// passes, their gaps and slips on the normals and lever arms they were
/// prepared with, which the contacts publish.
inline void WorldImpl::follow_points(double h, bool as_prepared)
{
  if (!turning_faces_.empty())
  {
    follow_turning_points(h, as_prepared);
  }
  if (!round_points_.empty())
  {
    follow_round_points(h, as_prepared);
  }
}

/// The frame's two contact springs (springs_), at most a quarter of the
/// substep rate in frequency, faster against a static body (ContactSprings).
ContactSprings WorldImpl::contact_springs(const StepContext& ctx) const
{
  const double hertz = std::min(settings_.contact_hertz, ContactSprings::kMaxHertzPerSubstepRate * ctx.inv_h);
  const double damping = settings_.contact_damping_ratio;
  return ContactSprings{make_softness(hertz, damping, ctx.h),
                        make_softness(ContactSprings::kStaticHertzFactor * hertz, damping, ctx.h)};
}

bool WorldImpl::prepare_pair_points(const ActiveEffects& effects, std::size_t k)
{
  const std::size_t begin = pair_rows_[k];
  const std::size_t end = pair_rows_[k + 1];
  prepare_point_range(effects, begin, end, false);  // world_solve.cpp: restitution aims per substep
  return prepare_soft_range(begin, end);
}

/// prepare_pair_points' soft terms on points [begin, end) (whole pairs).
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

/// The soft passes, or in exact mode each island's LCP (the passes then
/// take only the islands it could not solve).
void WorldImpl::solve_contacts(const StepContext& ctx, bool use_bias, StepReport& report)
{
  follow_points(ctx.h);                                   // world_turning_faces.cpp, world_round_points.cpp
  const bool exact = settings_.solver_mode == SolverMode::Exact;
  if (use_bias && (exact || !bounce_points_.empty()))
  {
    solve_start_ = velocity_;  // for the exact relax and restitution (capacity kept: no allocation after the first frame)
  }
  if (exact)
  {
    // Each island at once by pivoting, from scratch (no warm start); an
    // island too large for it goes through the soft passes below.
    aim_exact_targets(ctx, use_bias);
    solve_exact_islands(report, use_bias, &exact_targets_, !use_bias);  // world_exact.cpp: the biased pass warm starts
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
