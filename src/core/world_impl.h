// Internal to the core: the stages of the World's step, on its state
// (world_state.h) and on how its bodies move (world_motion.h). The stages
// run in the order world_step.cpp lists them; each file below holds one
// topic, and a helper used in one file only is described where it is defined.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/collide.h"
#include "collision2d/world.h"
#include "collide_features.h"
#include "contact_kernel.h"
#include "posed_polygon.h"
#include "world_motion.h"
#include "world_stage_types.h"

namespace collision2d
{
namespace detail
{
/// When a point `apart` from a centre, moving at `slide`, first comes
/// within `radius` of it in [0, h] (s); h if it does not
/// (world_round_points.cpp).
double touch_time(Vec2 apart, Vec2 slide, double radius, double h);

struct WorldImpl : WorldMotion
{
  explicit WorldImpl(const WorldSettings& settings) : WorldMotion(settings) {}

  // world.cpp: bodies by id.
  std::size_t index_of(BodyId id) const;
  void append_body(BodyId id, const Body& body, const Material& material);
  void remove_body(BodyId id);
  void wake(std::size_t index);
  void clear();

  // world_step.cpp: the step, top-down.
  StepReport step(int frames);
  void step_frame(StepReport& report);
  void fx2d_frame(StepContext& ctx, StepReport& report);
  void substep(StepContext& ctx, StepReport& report);
  void kick(const StepContext& ctx);
  void advance(StepContext& ctx, StepReport& report);
  void advance_bodies(std::size_t begin, std::size_t end, const StepContext& ctx, bool swept);
  void advance_body(std::size_t i, const StepContext& ctx, bool swept);
  void solve_velocity_stage(const StepContext& ctx, StepReport& report);
  void finish_report(StepReport& report);
  /// Of the dynamic bodies after the step (J), summed in body order.
  double kinetic_energy();
  /// Throws std::overflow_error naming the first body whose state is not
  /// finite. Each frame checks before it publishes its contacts: a step that
  /// publishes once then keeps its starting contacts in place (save_motion).
  void require_finite_state();
  /// Throws that overflow_error for body i (an index).
  [[noreturn]] void throw_non_finite(std::size_t i) const;
  // world_rollback.cpp: what a refused step puts back.
  /// Keeps aside what a step of `frames` frames changes.
  void save_motion(int frames);
  void restore_motion();
  /// Body i's motion and rest time into the rollback buffers.
  void keep_body(std::size_t i);

  // Sharing a stage among the workers (worker_pool.h; the per-body passes
  // are world_motion.h's): results are the same for any number of them.
  /// Calls f(begin, end) over the contact points split across the workers
  /// at body-pair boundaries, so each manifold's points stay on one worker.
  template <class F>
  void for_point_ranges(F f);
  /// Splits [0, count) into parts, one per worker (one part when count <
  /// min_shared), and folds answer(begin, end) of each part into `start` in
  /// part order: fold(fold(start, first), second)... `answers` is scratch.
  template <class T, class F, class Fold>
  T fold_in_parts(std::size_t count, std::size_t min_shared, std::vector<T>& answers, T start, F answer, Fold fold);
  /// The fold best = std::max(best, value(k)) over k in [0, count) from
  /// `start`, in parts on the workers when count >= min_shared.
  template <class F>
  double max_over(std::size_t count, std::size_t min_shared, double start, F value);
  /// How many bodies sleep now (counted again after a sleep, wake or edit).
  std::size_t asleep_bodies();
  /// The first point at or after k that starts a new body pair (or the end).
  std::size_t pair_boundary(std::size_t k) const;

  // world_soft_step.cpp: the soft step, top-down.
  void soft_frame(StepContext& ctx, StepReport& report);
  ContactSprings contact_springs(const StepContext& ctx) const;
  /// Pair k's points (added by add_manifold) prepared; whether any can bounce (e > 0).
  bool prepare_pair_points(const ActiveEffects& effects, std::size_t k);
  bool prepare_soft_range(std::size_t begin, std::size_t end);
  void solve_contacts(const StepContext& ctx, bool use_bias, StepReport& report);
  void aim_exact_targets(const StepContext& ctx, bool use_bias);
  // world_soft_solve.cpp: the soft passes.
  /// A warm start (with `warm`) and one soft pass over the frame's manifolds:
  /// by colour on the rows (iterative mode, shared among the workers), else
  /// in point order.
  void soft_pass(const StepContext& ctx, bool use_bias, bool warm);
  void soft_stage(const SoftPass& pass, std::size_t stage, std::size_t part, std::size_t parts);
  /// Whether the soft step solves on its rows (the exact mode keeps the points).
  bool rows_on() const { return settings_.solver_mode != SolverMode::Exact; }
  void warm_start_manifold(std::size_t first);
  void solve_soft_manifold(std::size_t first, const StepContext& ctx, bool use_bias);
  /// A sticking point's slip from its anchor now (m), at its anchor offset; 0 for a sliding one.
  double anchor_drift(const ContactPoint& p, Vec2 offset) const;
  /// The tangential speed (m/s) that pulls `drift` back at the contact's rate.
  double anchor_pull(const ContactPoint& p, double drift, double max_push) const;
  /// After the frame: an active point's slip carried to the next frame, and
  /// whether it now slides (`sliding`: it ended at its friction bound): only
  /// past `slop` from where it stuck. publish_contacts asks on its way
  /// through the points; the outcome goes to the contact, not the point.
  CarriedSlip carry_slip(const ContactPoint& p, bool sliding, Vec2 offset) const;
  // Points the frame follows exactly, kept on the point verbs: disks on the
  // faces of turning kinematic bodies (world_turning_faces.cpp), and
  // contacts between a disk and a vertex or a disk whose centres slide past
  // each other (world_round_points.cpp).
  void find_followed_points();
  void follow_points(double h, bool as_prepared = false);
  __attribute__((noinline, cold)) void list_turning_faces();
  __attribute__((noinline, cold)) void follow_turning_points(double h, bool as_prepared);
  void follow_turning_point(const TurningFacePoint& t, double h, bool as_prepared);
  bool nearest_is_followed_face(const TurningFacePoint& t, DiskFeature& nearest) const;
  DiskFeature nearest_feature_now(std::size_t polygon, std::size_t disk) const;
  void follow_nearest_feature(const TurningFacePoint& t, const DiskFeature& nearest, double slip, double h,
                              bool as_prepared);
  __attribute__((noinline, cold)) void list_round_points();
  bool round_point_followed(const ContactPoint& p, Vec2 slide, double reach) const;
  __attribute__((noinline, cold)) void follow_round_points(double h, bool as_prepared);
  __attribute__((noinline, cold)) void aim_round_bounces(double h);
  RoundPlace round_place(const RoundPoint& r) const;
  void to_nearest_feature(const ContactPoint& p, const RoundPoint& r, RoundPlace& place) const;
  // world_soft_restitution.cpp: restitution, substep by substep (taken back
  // in world_soft_bounce_drop.cpp).
  /// The frame's points that can bounce, after the rows are packed.
  void find_bounce_points();
  /// At a substep's start: each bouncing point's Newton target from the
  /// velocities now.
  void aim_bounces();
  double closing_gravity(const ContactPoint& p) const;
  /// At a substep's end: the points it pushed driven to their targets,
  /// iterated to the fixed point.
  void restitute(StepReport& report);
  double take_bouncing();
  void hold_pushing_points();
  void save_bounce_start();
  double release_points();
  void drive_to_targets(double fastest, StepReport& report);
  void drop_bounces(bool unsettled);
  bool mark_unsettled_groups();
  bool mark_energetic_groups();
  void group_restituted_bodies();
  std::size_t bounce_group_of(const ContactPoint& p);
  void store_bounce_impulses();
  /// Where point k's accumulated normal and tangential impulses live during the substeps.
  ImpulseSlots point_impulses(std::size_t k);
  /// The deepest overlap of the frame's contact points at the poses now,
  /// followed from the pose changes since they were prepared (m).
  double followed_penetration();

  // world_effects.cpp
  StepContext select_effects();
  const BodyCensus& census_for_frame();
  /// The bodies counted for select_effects, in parts on the workers.
  BodyCensus take_census();
  void count_body(std::size_t i, BodyCensus& census) const;

  // world_warm_integration.cpp
  void predict_velocities(const StepContext& ctx);
  bool previous_point_matches(std::size_t k) const;
  void restore_velocities();

  // world_contacts.cpp
  bool is_mover(std::size_t i) const;
  /// Contacts at the current poses; pairs within `margin` (m) are kept too.
  /// With `prepare` (the soft step), each pair's points are prepared with
  /// ctx's effects as they are added, while they are in cache, and bounces_
  /// says whether any can bounce.
  void detect(const StepContext& ctx, double margin, StepReport& report, bool prepare = false);
  void find_mover_pairs();
  void merge_pairs();
  /// movers_ and the resting bodies' grid, again if what rests or its boxes
  /// changed; true if they were (the frame's per-body stages then visit every body).
  bool refresh_resting_grid();
  /// movers_ lists the bodies that move now (no sleep, wake or edit since it was made).
  bool movers_current() const
  {
    return resting_built_ && resting_version_ == version_ && resting_stamp_ == sleep_stamp_;
  }
  /// How far any point of the body can travel in one frame (m).
  double frame_reach(const Body& b) const;
  bool collide_pair(std::size_t i, std::size_t j, double tolerance, Manifold& m, bool posed_now) const;
  // world_pose.cpp: the outlines.
  /// Every polygon's outline at its pose now, into posed_vertices_ (workers share it).
  void pose_bodies();
  void pose_range(std::size_t begin, std::size_t end, bool skip_static);
  /// Body i's tight box, read from its outline (pose_bodies) when it has one.
  Aabb posed_box(std::size_t i) const;
  PosedPolygon posed(std::size_t i) const;
  /// The pair stage's buffers for n pairs, in the frame block.
  void place_pair_buffers(std::size_t n);
  /// Narrow phase of pairs_[begin, end) into manifolds_ and collided_ (the workers share it).
  void collide_range(std::size_t begin, std::size_t end);
  /// Soft step: pair k's manifold from its cached contacts when the pair has
  /// moved little since they were detected (world_contact_reuse.cpp);
  /// `cursor` as cached_pair's.
  bool keep_manifold(std::size_t k, std::size_t i, std::size_t j, std::size_t& cursor);
  /// A point's lever arms and where it was detected (world_contact_reuse.cpp):
  /// for a manifold the narrow phase found this frame, from the bodies now;
  /// for a kept one, from its cached contact. Both set the point in place.
  void set_new_origin(std::size_t k, ContactPoint& row) const;
  static void set_kept_origin(const ContactOrigin& origin, ContactPoint& row)
  {
    row.r_a = origin.r_a;
    row.r_b = origin.r_b;
    row.origin_separation = origin.separation;
    row.origin_theta_a = origin.theta_a;
    row.origin_theta_b = origin.theta_b;
    row.origin_known = origin.known;
  }
  /// The point's origin as its published contact carries it: its lever
  /// arms to the detected point, less the soft step's surface_reach.
  static void publish_origin(const ContactPoint& row, ContactOrigin& origin)
  {
    const double reach = surface_reach(row);
    origin.r_a = reach > 0.0 ? row.r_a + reach * row.normal : row.r_a;
    origin.r_b = reach > 0.0 ? row.r_b - reach * row.normal : row.r_b;
    origin.separation = row.origin_separation;
    origin.theta_a = row.origin_theta_a;
    origin.theta_b = row.origin_theta_b;
    origin.known = row.origin_known;
  }
  /// Soft step: how far a rough point's lever arms reach past the detected
  /// point (midway across the gap) to each body's own surface (m): half the
  /// gap where its manifold was detected; 0 for a touching or smooth point
  /// (only friction rows read the difference).
  static double surface_reach(const ContactPoint& row)
  {
    const double gap = row.origin_known ? row.origin_separation : row.separation;
    return gap > 0.0 && has_friction(row) ? 0.5 * gap : 0.0;
  }
  /// Whether pair k's manifold was kept (its points are contacts_ from kept_from_[k]).
  bool kept(std::size_t k) const { return kept_from_[k] != kNotKept; }
  /// How far apart the pair's points are kept (m): margin and reach, or touching.
  double pair_tolerance(std::size_t i, std::size_t j) const;
  /// Each pair's first row (pair_rows_) and cache entry (pair_cache_), as one
  /// pass in pair order finds them (with wakes and late collisions); returns
  /// the rows in all. `cached`: whether hit pairs look up their cached impulses.
  std::size_t place_pair_rows(bool cached);
  /// place_pair_rows in parts on the workers.
  void place_pairs_in_parts(bool cached);
  void place_pairs_part(std::size_t part, std::size_t parts, bool cached);
  void place_pairs_in_order(bool cached);
  /// Pair k's manifold into its rows, impulses matched from the cache;
  /// returns its deepest penetration (m).
  double add_manifold(std::size_t k, double warm_scale, bool friction);
  /// Index of the first cached contact of pair (a, b), or of where it would
  /// be, searched from `cursor`, which it moves.
  std::size_t cached_pair(std::size_t& cursor, BodyId a, BodyId b) const;
  std::size_t first_cached(std::size_t k, std::size_t& cursor) const;
  const WorldContact* find_cached(std::size_t first, BodyId a, BodyId b, std::uint32_t feature) const;
  /// The frame's points become contacts_ (the next frame's warm-start cache),
  /// in place of the last ones, which nothing reads after detection.
  /// After a soft frame each contact takes its point's impulses from the
  /// point's row (the point is only read), an active point's slip is
  /// carried (carry_slip) and the deepest followed gap kept for the report.
  void publish_contacts(bool soft_frame = false);
  void size_contacts(std::size_t n);
  double measure_penetration() const;

  // world_solve.cpp: the velocity stage on the contact-solver kernel.
  void load_velocities();
  void store_velocities();
  void prepare_points(const ActiveEffects& effects);
  /// prepare_points on points [begin, end) (whole pairs); without
  /// `targets` (the soft step aims each substep) no Newton target is set,
  /// and a point's lever arms reach each body's surface (surface_reach).
  void prepare_point_range(const ActiveEffects& effects, std::size_t begin, std::size_t end, bool targets = true);
  void warm_start();
  void solve_velocities(bool friction);
  double velocity_residual() const;
  /// f(k) for each manifold's first point k, those with a kinematic body
  /// first: the rest, the ground among them, then have the last word on a
  /// body it presses. The rest keep point order, which carries a stack's
  /// correction up from the ground in one pass.
  template <class F>
  void for_manifolds_kinematic_first(F&& f)
  {
    const auto walk = [&](auto&& take) {
      for (std::size_t k = 0; k < points_.size(); k += points_[k].count == 2 ? 2 : 1)
      {
        if (take(points_[k]))
        {
          f(k);
        }
      }
    };
    if (census_.kinematic_bodies == 0)
    {
      walk([](const ContactPoint&) { return true; });  // one walk where there are none
      return;
    }
    walk([](const ContactPoint& p) { return touches_kinematic(p); });
    walk([](const ContactPoint& p) { return !touches_kinematic(p); });
  }
  /// Only a dynamic body has an inverse mass, and a static one is flagged.
  static bool touches_kinematic(const ContactPoint& p)
  {
    return (p.inv_mass_a == 0.0 || p.inv_mass_b == 0.0) && !p.against_static;
  }

  // world_position.cpp: penetration resolution (Fx2D step 3).
  void correct_positions(const StepContext& ctx, StepReport& report);
  void correct_pass(double softness, bool hold, bool resting_only);
  Vec2 integration_move(std::size_t i, Vec2 r) const;
  void hold_static_friction(const ContactPoint& first, const ContactPoint& second);
  void hold_all_static_friction(bool friction);
  double current_depth(const ContactPoint& p) const;
  void correct_point(const ContactPoint& p, double depth, double softness);
  bool correct_pair(const ContactPoint& first, const ContactPoint& second, double depth1, double depth2,
                    double softness);
  void displace(std::size_t i, double lambda, Vec2 n, Vec2 r, double inv_mass, double inv_inertia);

  // world_exact.cpp
  /// With `targets`, row k aims at (*targets)[k] instead of its Newton target;
  /// with `relax`, the substep's second pass: normal impulses added, or, in an
  /// island a moving kinematic body touches, all solved again from `solve_start_`.
  /// With `seed`, the passes that follow warm start: an island solved near
  /// but not exactly leaves its impulses as their warm start.
  void solve_exact_islands(StepReport& report, bool seed, const std::vector<double>* targets = nullptr,
                           bool relax = false);
  void solve_position_islands(double softness, StepReport& report);

  // world_rest.cpp: a frame at rest repeats the last one, which is replayed.
  /// Every dynamic body asleep and no kinematic body moving.
  bool at_rest() const;
  /// Adds the remembered rest frame when nothing changed since it; false otherwise.
  bool replay_rest_frame(StepReport& report);
  /// After a frame: remembers it when it started and ended at rest.
  void note_frame(bool started_at_rest, const StepReport& frame);
  /// A whole step of replayed frames: nothing to keep aside, check or
  /// measure again (the closing figures are those of the rest state).
  bool replay_rest_step(int frames, StepReport& report);
  /// After a step: its closing figures, when it ends at the remembered rest.
  void note_finish(const StepReport& report);
  /// A frame's report folded into the step's.
  static void add_frame(StepReport& total, const StepReport& frame);
  /// Any edit through the World API: a remembered rest frame no longer holds.
  void changed() { ++version_; }

  // world_sleep.cpp: islands fall asleep; world_sleeping_contacts.cpp: their
  // contacts kept aside, out of the step, until they wake.
  void update_sleep();
  /// Gives every list that waking islands or putting them to sleep moves
  /// contacts through (and their scratch) room for `contacts` contacts and
  /// those asleep, so those moves cannot run out of memory: before a publish
  /// over the step's starting contacts (update_sleep comes after it), and
  /// before an edit that wakes islands.
  void make_room_to_move_contacts(std::size_t contacts);
  void update_rest_times();
  /// Labels the bodies that fell asleep this frame by island and puts their
  /// contacts aside.
  void label_new_sleepers();
  /// Moves the contacts of bodies asleep now from contacts_ to sleeping_contacts_.
  void put_contacts_aside();
  /// Wakes every body of island `label`; its contacts go back into `into`
  /// (kept in (a, b) order), where detection or warm starting finds them.
  void wake_island(IslandLabel label, std::vector<WorldContact>& into);
  /// Sleeping switched off: every body awake, every contact back in contacts_.
  void wake_everyone();
  /// Detection: wakes the islands that a mover's contact reaches; true if any woke.
  bool wake_reached_islands();
  /// Before the step first changes the contacts kept aside: keeps them (and,
  /// with `starting_contacts`, the step's starting contacts, which the
  /// change may reach) for a rollback.
  void keep_sleeping_for_rollback(bool starting_contacts);
  /// After an edit of contacts_ and asleep_ as a whole (set_step_state):
  /// sleeping contacts aside again, islands labelled from them.
  void sort_out_sleeping();
  /// sleeping_contacts_' deepest penetration, after they changed.
  void measure_sleeping_penetration();
  /// Every contact in (a, b) order: contacts_ merged with sleeping_contacts_.
  const std::vector<WorldContact>& all_contacts() const;
};

}  // namespace detail
}  // namespace collision2d

#include "world_parallel.h"
