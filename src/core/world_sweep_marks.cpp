// Which bodies a substep sweeps for their time of impact (world_toi.cpp
// sweeps them): those whose move in the substep could carry them past a thin
// body, and how: a dynamic polygon whose spin alone could carry its far
// points that far is swept turning. The Fx2D order checks every body; the
// soft step checks only the bodies a contact touches this frame, unless a
// free body could be fast (a free body keeps its spin).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "world_motion.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A body's reach is divided by this before a free body's speed is held to
/// it (may_turn_fast): far above the round-off of a frame's gravity kicks.
constexpr double kReachRoundOffMargin = 1.0 + 1e-9;
/// Visited bodies below which each substep checks all of them: in a world this
/// small choosing the candidates costs more than it saves (docs/performance.md,
/// the thirty-ninth profile note).
constexpr std::size_t kMinBodiesToChooseSweepCandidates = 16;

}  // namespace

double WorldMotion::sweep_reach_sq(std::size_t i) const
{
  // A kinematic body is swept too: what it strikes is pushed ahead of it
  // (world_kinematic_push.cpp).
  if (!awake_dynamic(i) && bodies_[i].type() != BodyType::Kinematic)
  {
    return -1.0;
  }
  // Two bodies can pass through each other in one substep only when their
  // relative move exceeds the sum of their thinnest half-widths.
  const double reach = settings_.toi_displacement_fraction * (inner_radius_[i] + min_inner_radius_);
  return reach * reach;
}

double WorldMotion::fast_reach_sq(std::size_t i, bool stored) const
{
  // The soft step set its thresholds for the frame (reset_body_motion).
  return stored ? sweep_reach_sq(i) : swept_reach_sq_[i];
}

/// Whether body i spinning at `omega` (rad/s) for h seconds moves its far
/// points past `reach_sq` (its fast_reach_sq): then its sweep turns it.
/// `floor`: the spin_floor, below which no body can.
bool WorldMotion::turn_outruns(std::size_t i, double omega, double h, double floor, double reach_sq) const
{
  // Below the floor no body's turn can outrun its reach, so most bodies stop
  // at the first compare and never read their record. Above it: a polygon's
  // far points lie on its bounding circle; a disk's outline does not change
  // as it turns; a body never swept has a negative reach; a kinematic
  // polygon's turn is face_turn's.
  if (!(std::abs(omega) > floor))
  {
    return false;
  }
  const Body& b = bodies_[i];
  const double far = omega * h * b.radius();
  return reach_sq >= 0.0 && b.type() == BodyType::Dynamic && b.shape() == Shape::Polygon && far * far > reach_sq;
}

double WorldMotion::spin_floor(double h, bool rotation) const
{
  // Every reach is at least two of the thinnest half-widths' share, every
  // turning outline at most the widest dynamic polygon's: most worlds' spins
  // stay far below this, and their bodies skip the exact test. A kinematic
  // polygon's set spin is mark_turning_faces' to check.
  const double widest = census_.widest_dynamic_polygon;
  if (!rotation || !(widest > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  return settings_.toi_displacement_fraction * 2.0 * min_inner_radius_ / (widest * h);
}

FreeSpeedBound WorldMotion::free_speed_bound(double h, bool rotation) const
{
  // A body no contact touches gains at most one frame of gravity's speed,
  // and keeps its spin; the margin covers the round-off of the substeps'
  // kicks and of the test.
  return FreeSpeedBound{settings_.toi_displacement_fraction / (h * kReachRoundOffMargin),
                        length(settings_.gravity) * settings_.dt, spin_floor(h, rotation), h};
}

bool WorldMotion::may_turn_fast(std::size_t i, const FreeSpeedBound& bound) const
{
  if (swept_reach_sq_[i] < 0.0)  // set for the frame (reset_body_motion)
  {
    return false;
  }
  const double slowest_fast = bound.per_width * (inner_radius_[i] + min_inner_radius_) - bound.frame_kick;
  return !(slowest_fast > 0.0 && length_sq(velocity_[i].v) <= slowest_fast * slowest_fast);
}

bool WorldMotion::may_spin_fast(std::size_t i, const FreeSpeedBound& bound) const
{
  // Nothing changes a free body's spin.
  const double omega = velocity_[i].omega;
  return turn_outruns(i, omega, bound.substep, bound.spin_floor, swept_reach_sq_[i]);
}

void WorldMotion::note_touching(std::size_t i)
{
  // A visited body was reset to untouched, so it is listed once; a resting
  // body outside the frame's pass is never a candidate.
  if (!sweep_every_body_ && !touching_[i] && (body_pass_full_ || !is_resting_[i]) && swept_reach_sq_[i] >= 0.0)
  {
    sweep_candidates_.push_back(i);
  }
  touching_[i] = true;
}

void WorldMotion::choose_sweep_pass(bool any_may_turn_fast)
{
  // With most bodies touched, the plain pass over them is the cheaper.
  sweep_every_body_ = sweep_every_body_ || any_may_turn_fast || 2 * sweep_candidates_.size() > visited_count();
}

bool WorldMotion::sweep_candidates_pay() const
{
  // With toi On every moving body is swept; in a world of a few bodies the
  // plain check of each costs less than choosing them.
  return settings_.time_of_impact == Toggle::Auto && visited_count() >= kMinBodiesToChooseSweepCandidates;
}

bool WorldMotion::mark_swept_bodies(double h, bool stored, bool rotation)
{
  // A resting body's flag stays 0 from the frame that made it rest.
  swept_.resize(bodies_.size());
  const bool any =
      !stored && !sweep_every_body_ ? mark_sweep_candidates(h, rotation) : mark_every_body(h, stored, rotation);
  // A turning kinematic polygon's far points move faster than its centroid.
  return census_.turning_face_bodies > 0 ? mark_turning_faces(h) || any : any;
}

/// mark_swept_bodies over every body by its translation and spin.
bool WorldMotion::mark_every_body(double h, bool stored, bool rotation)
{
  const Toggle mode = settings_.time_of_impact;
  const double least_spin = spin_floor(h, rotation);
  // The soft step reads its own velocities and the thresholds it set for the
  // frame (reset_body_motion): its pass need not read the bodies.
  for_each_body([&](std::size_t i) {
    const double reach_sq = fast_reach_sq(i, stored);
    const Vec2 d = (stored ? bodies_[i].velocity() : velocity_[i].v) * h;  // substep_displacement if swept
    const bool moving = d.x != 0.0 || d.y != 0.0;
    const bool fast = reach_sq >= 0.0 && (mode == Toggle::On ? moving : length_sq(d) > reach_sq);
    const double omega = stored ? bodies_[i].omega() : velocity_[i].omega;
    const bool turns = turn_outruns(i, omega, h, least_spin, reach_sq);
    swept_[i] = turns ? kSweptTurning : fast ? kSweptMoving : kNotSwept;
  });
  if (body_pass_full_)
  {
    return std::any_of(swept_.begin(), swept_.end(), [](unsigned char s) { return s != kNotSwept; });
  }
  return std::any_of(movers_.begin(), movers_.end(), [this](std::size_t i) { return swept_[i] != kNotSwept; });
}

/// mark_swept_bodies over sweep_candidates_ only.
bool WorldMotion::mark_sweep_candidates(double h, bool rotation)
{
  // The other bodies' flags were cleared for the frame (prepare_soft_bodies)
  // and no substep this frame can make them fast (may_turn_fast).
  const double least_spin = spin_floor(h, rotation);
  std::atomic<bool> any{false};
  workers_.parallel_for(sweep_candidates_.size(), kMinSharedBodies, [&](std::size_t begin, std::size_t end) {
    bool part_any = false;
    for (std::size_t k = begin; k < end; ++k)
    {
      const std::size_t i = sweep_candidates_[k];
      const double omega = velocity_[i].omega;
      const bool turns = turn_outruns(i, omega, h, least_spin, swept_reach_sq_[i]);
      swept_[i] = turns ? kSweptTurning : length_sq(velocity_[i].v * h) > swept_reach_sq_[i] ? kSweptMoving : kNotSwept;
      part_any = part_any || swept_[i] != kNotSwept;
    }
    if (part_any)
    {
      any.store(true, std::memory_order_relaxed);
    }
  });
  return any.load();
}

/// Marks the turning kinematic polygons whose points move past their
/// reach in a substep of h seconds; true if any.
bool WorldMotion::mark_turning_faces(double h)
{
  bool any = false;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    const double turn = face_turn(i, h);
    if (turn != 0.0)
    {
      const double move = length(substep_displacement(i, h)) + std::abs(turn) * bodies_[i].radius();
      const bool fast = settings_.time_of_impact == Toggle::On || move * move > sweep_reach_sq(i);
      swept_[i] = fast ? kSweptMoving : kNotSwept;
      any = any || swept_[i] != kNotSwept;
    }
  }
  return any;
}

}  // namespace detail
}  // namespace collision2d
