// Time of impact inside a substep: a dynamic body that moves far enough in one
// substep to skip over a thin body (world_sweep_marks.cpp marks it) is swept
// against the bodies a broad phase over swept boxes finds, and travels only
// up to its earliest exact time of impact. There it touches its obstacle;
// detection counts that touching pair as a contact (touch tolerance) and the
// velocity solve takes the impact.
// The sweep is translation-only with each body's current orientation, as
// time_of_impact() defines it, except for a kinematic polygon's set spin and
// a dynamic polygon whose spin alone outruns its reach: those outlines turn
// in their sweep. The rest of a clamped body's substep move (and turn, if
// its sweep turned it) is dropped, its velocity is not. A pair that already
// touches (or that the soft step's solver holds) is swept again with each
// fast body shrunk to a small disk at its centroid: a spin can carry an
// outline's far side through a thin body the sweep saw touching, but never
// the centroid, which moves on a line. A centroid's disk that touches the
// other body already is not stopped (that stop would come again each
// substep, freezing the pair): the pair's approach along the normal there
// leaves both velocities instead.
// The static bodies are swept once more after the frame's moves
// (world_static_crossing.cpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "collision2d/time_of_impact.h"
#include "collision2d/touch_tolerance.h"
#include "outline_gap.h"
#include "world_motion.h"

namespace collision2d
{
namespace detail
{
namespace
{
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// A centroid core that would touch within this fraction of its radius
/// touches already: stopped there, it would stop again each substep.
constexpr double kCoreTouchFraction = 1e-3;

}  // namespace

void WorldMotion::refresh_body_shapes()
{
  inner_radius_.resize(bodies_.size());
  disk_.resize(bodies_.size());
  min_inner_radius_ = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    inner_radius_[i] = inner_radius(bodies_[i]);
    disk_[i] = bodies_[i].shape() == Shape::Disk;
    min_inner_radius_ = std::min(min_inner_radius_, inner_radius_[i]);
  }
  if (bodies_.empty())
  {
    min_inner_radius_ = 0.0;
  }
}

void WorldMotion::append_body_shape(const Body& body)
{
  inner_radius_.push_back(inner_radius(body));
  disk_.push_back(body.shape() == Shape::Disk);
  min_inner_radius_ = inner_radius_.size() == 1 ? inner_radius_.back() : std::min(min_inner_radius_, inner_radius_.back());
}

Vec2 WorldMotion::substep_displacement(std::size_t i, double h) const
{
  const Body& b = bodies_[i];
  return b.type() == BodyType::Static || asleep_[i] ? Vec2{0.0, 0.0} : b.velocity() * h;
}

/// How far body i's outline turns in a sweep of h seconds (rad): a
/// kinematic polygon's spin (face_turn) or a dynamic polygon's marked
/// kSweptTurning, 0 for any other body.
double WorldMotion::substep_turn(std::size_t i, double h) const
{
  // A dynamic polygon's sweep keeps its orientation unless its spin alone
  // could carry its far points past a thin body; a disk's outline has none.
  return swept_[i] == kSweptTurning ? bodies_[i].omega() * h : face_turn(i, h);
}

double WorldMotion::face_turn(std::size_t i, double h) const
{
  // A kinematic polygon follows its set spin, whatever the rotation toggle.
  const Body& b = bodies_[i];
  const bool turning = census_.turning_face_bodies > 0 && b.type() == BodyType::Kinematic &&
                       b.shape() == Shape::Polygon && !asleep_[i];
  return turning ? b.omega() * h : 0.0;
}

/// Body i's box for the sweep's broad phase: a turning outline's is its
/// bounding circle's.
Aabb WorldMotion::sweep_box(std::size_t i, double h) const
{
  // A turning outline stays inside its bounding circle.
  const Vec2 d = substep_displacement(i, h);
  if (substep_turn(i, h) == 0.0)
  {
    return bodies_[i].aabb().swept(d);
  }
  const Vec2 half{bodies_[i].radius(), bodies_[i].radius()};
  const Vec2 at = bodies_[i].position();
  return Aabb{at - half, at + half}.swept(d);
}

bool WorldMotion::sweep(double h, StepReport& report, bool stored, bool rotation)
{
  clamping_ = false;
  pushing_ = false;
  if (settings_.time_of_impact == Toggle::Off || !mark_swept_bodies(h, stored, rotation))
  {
    return false;
  }
  // Only a world with a moving kinematic body keeps the books of pushes.
  pushing_ = census_.moving_kinematic_bodies > 0 || census_.turning_face_bodies > 0;
  // The pairs' sweeps read every body's velocity and outline: the soft
  // step's velocities and poses so far go onto the bodies.
  place_bodies(!stored);
  const std::size_t n = bodies_.size();
  toi_.assign(n, 1.0);
  boxes_.resize(n);
  // Only a world where an outline can turn pays sweep_box's test of each body.
  const bool outlines_turn = census_.turning_face_bodies > 0 || spin_floor(h, rotation) < kInfinity;
  for (std::size_t i = 0; i < n; ++i)
  {
    boxes_[i] = outlines_turn ? sweep_box(i, h) : bodies_[i].aabb().swept(substep_displacement(i, h));
    report.swept_bodies += swept_[i] ? 1 : 0;
  }
  sweep_phase_.find_pairs(boxes_, pairs_);
  if (pushing_)
  {
    pusher_.assign(n, kNoBody);
    pushed_at_.resize(n);
    touching_faces_.clear();
  }
  for (const BodyPair& pair : pairs_)
  {
    const std::size_t i = pair.first;
    const std::size_t j = pair.second;
    if ((!swept_[i] && !swept_[j]) || (pushing_ && !dynamic_pair(i, j)))
    {
      continue;
    }
    // A soft-step pair with a contact this frame is the solver's: it holds
    // their approach to the gap, turning included, where a translation-only
    // sweep would stop a turning body short of a touch that never comes. A
    // spin that outruns the reach turns past what the frame's contact can
    // follow: that pair is swept turning.
    const bool held = !stored && swept_[i] != kSweptTurning && swept_[j] != kSweptTurning && has_frame_contact(i, j);
    const Vec2 di = substep_displacement(i, h);
    const Vec2 dj = substep_displacement(j, h);
    double t = held ? 0.0 : time_of_impact(bodies_[i], di, substep_turn(i, h), bodies_[j], dj, substep_turn(j, h));
    if (pushing_ && (t <= 0.0 || t >= 1.0))
    {
      note_touching_face(i, j);                           // world_kinematic_push.cpp
    }
    // t = 0: already touching or overlapping, which detection (or the
    // solver) handles, as long as no centroid passes into the other body.
    // In the Fx2D order a body touching a turning face is lifted onto it
    // instead (the face overruns a straight path however slowly it turns);
    // in the soft step the pair's contact holds it.
    const bool turning = stored && pushing_ && (face_turn(i, h) != 0.0 || face_turn(j, h) != 0.0);
    if (t <= 0.0 && !turning)
    {
      std::size_t on_face = kNoBody;
      t = core_time_of_impact(i, j, di, dj, stored, on_face);
      if (on_face != kNoBody)
      {
        release_core(on_face, on_face == i ? j : i, stored);
      }
    }
    if (t <= 0.0 || t >= 1.0)
    {
      continue;
    }
    for (std::size_t k : {i, j})
    {
      if (bodies_[k].type() == BodyType::Dynamic && t < toi_[k])
      {
        toi_[k] = t;
        if (pushing_)
        {
          note_pusher(k, k == i ? j : i);                 // world_kinematic_push.cpp
        }
      }
    }
  }
  if (pushing_)
  {
    press_touching_faces(h, !stored);                     // world_kinematic_push.cpp
    find_pushes(h);
    apply_pushes(h, stored);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const bool stopped = toi_[i] < 1.0;
    report.toi_clamps += stopped ? 1 : 0;
    clamping_ = clamping_ || stopped;
  }
  return true;
}

double WorldMotion::disk_time_of_impact(std::size_t i, double radius, Vec2 from, Vec2 d, const Body& other,
                                      Vec2 d_other) const
{
  return time_of_impact(Body(bodies_[i].mass(), radius, from, Vec2{0.0, 0.0}), d, other, d_other);
}

/// Soft step: whether the frame's contact points (in pair order) hold pair (i, j).
bool WorldMotion::has_frame_contact(std::size_t i, std::size_t j) const
{
  const std::uint32_t a = static_cast<std::uint32_t>(std::min(i, j));
  const std::uint32_t b = static_cast<std::uint32_t>(std::max(i, j));
  const auto before = [](const ContactPoint& p, std::pair<std::uint32_t, std::uint32_t> key) {
    return p.a < key.first || (p.a == key.first && p.b < key.second);
  };
  const auto found = std::lower_bound(points_.begin(), points_.end(), std::make_pair(a, b), before);
  return found != points_.end() && found->a == a && found->b == b;
}

/// Earliest time of impact in (0, 1) of a fast body's centroid core
/// against the other body of pair (i, j) moved by di and dj, else 1. A
/// core that touches the other body already and closes on it is not
/// counted: it is `on_face` (i or j, else kNoBody), for release_core.
double WorldMotion::core_time_of_impact(std::size_t i, std::size_t j, Vec2 di, Vec2 dj, bool stored,
                                      std::size_t& on_face) const
{
  // Only a body fast against the other (as Auto judges fast) can carry its
  // centroid that far: resting pairs swept with time_of_impact On skip this.
  const double relative_sq = length_sq(di - dj);
  double earliest = 1.0;
  for (const auto& [k, other, dk, d_other] : {std::tuple{i, j, di, dj}, std::tuple{j, i, dj, di}})
  {
    const double reach_sq = fast_reach_sq(k, stored);
    // A pose already overflowed is left to the step's finiteness check,
    // which names the body (a Body cannot be made at it).
    if (!swept_[k] || bodies_[k].type() != BodyType::Dynamic || relative_sq <= reach_sq ||
        !is_finite(bodies_[k].position()))
    {
      continue;
    }
    const double core = kCoreFraction * inner_radius_[k];
    const double t = disk_time_of_impact(k, core, bodies_[k].position(), dk, bodies_[other], d_other);
    if (t <= 0.0)
    {
      continue;  // a core already inside stays the detection's
    }
    if (t * std::sqrt(relative_sq) <= kCoreTouchFraction * core)
    {
      on_face = k;
      continue;
    }
    earliest = std::min(earliest, t);
  }
  return earliest;
}

/// Body k's core touches body `other` and closes on it: their approach
/// along the normal there leaves both velocities (take_out_approach),
/// instead of a stop at time 0 that would come again each substep.
void WorldMotion::release_core(std::size_t k, std::size_t other, bool stored)
{
  const PointGap at = outline_point_gap(bodies_[other], bodies_[k].position());  // outline_gap.h
  take_out_approach(k, other, at.normal, bodies_[k].position() - at.gap * at.normal, stored);
}

void WorldMotion::take_out_approach(std::size_t k, std::size_t other, Vec2 n, Vec2 point, bool stored)
{
  // The soft step's velocities live in velocity_; the bodies get a copy, which
  // the sweep reads for the pairs after this one.
  const auto velocity = [&](std::size_t i) { return stored ? bodies_[i].velocity() : velocity_[i].v; };
  const auto set = [&](std::size_t i, Vec2 v) {
    bodies_[i].set_velocity(v);
    if (!stored)
    {
      velocity_[i].v = v;
    }
  };
  Vec2 v_surface{0.0, 0.0};
  double inv_other = 0.0;
  if (other != kNoBody)
  {
    const Body& b = bodies_[other];
    v_surface = b.velocity() + b.omega() * perp(point - b.position());
    inv_other = asleep_[other] ? 0.0 : b.inv_mass();  // a sleeping body stays as it is
  }
  const double closing = dot(velocity(k) - v_surface, n);
  const double inv_k = bodies_[k].inv_mass();
  if (!(closing < 0.0) || inv_k == 0.0)
  {
    return;
  }
  // Each side's share of the closing speed, by inverse mass: all of it
  // for k against a body that keeps its velocity.
  const double share_k = inv_k / (inv_k + inv_other);
  set(k, velocity(k) - (closing * share_k) * n);
  if (inv_other > 0.0)
  {
    set(other, velocity(other) + (closing * (1.0 - share_k)) * n);
  }
}

void WorldMotion::grow_stopped_boxes()
{
  // A body stopped at its time of impact touches its obstacle only up to
  // round-off: its box grows by its share of the touch tolerance, or the
  // broad phase could drop the pair that pair_tolerance keeps.
  for (std::size_t k = 0; k < looked_.size(); ++k)
  {
    const std::size_t i = looked_[k];
    if (clamped(i))
    {
      mover_boxes_[k] = mover_boxes_[k].inflated(kRelativeTouchTolerance * 2.0 * bodies_[i].radius());
    }
  }
}

bool WorldMotion::clamped(std::size_t i) const
{
  return clamping_ && toi_[i] < 1.0;
}

}  // namespace detail
}  // namespace collision2d
