// The soft step's restitution (world_soft_step.cpp calls it around each
// substep). At a substep's start every point that can bounce takes its Newton
// target from its approach speed then; at the substep's end the points the
// substep pushed are driven to their targets, Gauss-Seidel in point order to
// the fixed point (on one thread). Targets fixed once per frame would stop a
// contact that a body only turns toward after an earlier bounce in the same
// frame, and lose its energy; per substep, each meeting bounces from the speed
// it happened at. Where the passes find no fixed point (a body jammed in a
// wedge that a kinematic body closes), the bodies that point joins keep the
// relax's velocities for that substep (drop_bounces).
#include <algorithm>
#include <cmath>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Restitution passes stop when every bouncing contact is this close to its
/// target (m/s), relative to the fastest approach, or after kMaxRestitutionPasses.
constexpr double kRestitutionTolerance = 1e-12;
constexpr int kMaxRestitutionPasses = 64;

/// visit(point index, its impulse slots) for every point restitution
/// drives, lets go of or holds this substep.
template <typename Visit>
void for_each_restituted(const std::vector<std::size_t>& bouncing, const std::vector<std::size_t>& released,
                         const std::vector<HeldPoint>& held, const std::vector<BouncePoint>& bounce_points,
                         Visit&& visit)
{
  for (std::size_t i : bouncing)
  {
    visit(bounce_points[i].point, bounce_points[i].impulses);
  }
  for (std::size_t i : released)
  {
    visit(bounce_points[i].point, bounce_points[i].impulses);
  }
  for (const HeldPoint& h : held)
  {
    visit(h.point, h.impulses);
  }
}
}  // namespace

void WorldImpl::find_bounce_points()
{
  bounce_points_.clear();
  some_cannot_bounce_ = false;
  if (!bounces_)
  {
    return;  // stacks and other frames without e > 0 skip restitution whole
  }
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    ContactPoint& p = points_[k];
    if (!p.active || p.restitution <= 0.0)
    {
      some_cannot_bounce_ = some_cannot_bounce_ || p.active;
      continue;
    }
    BouncePoint bounce;
    bounce.point = k;
    bounce.impulses = point_impulses(k);
    bounce_points_.push_back(bounce);
  }
  // Each substep's bouncing and released points are some of these: room for
  // all of them, so a warmed-up world allocates nothing.
  if (bouncing_.capacity() < bounce_points_.size())
  {
    bouncing_.reserve(bounce_points_.capacity());
  }
  if (released_.capacity() < bounce_points_.size())
  {
    released_.reserve(bounce_points_.capacity());
  }
  if (bounce_start_.capacity() < bounce_points_.size())
  {
    bounce_start_.reserve(bounce_points_.capacity());
  }
}

ImpulseSlots WorldImpl::point_impulses(std::size_t k)
{
  // Packed rows carry the impulses during the substeps; other points their own.
  const ImpulseSlots row = rows_on() ? soft_rows_.impulses_of(k) : ImpulseSlots{};
  return row.normal != nullptr ? row : ImpulseSlots{&points_[k].lambda_n, &points_[k].lambda_t};
}

void WorldImpl::aim_bounces()
{
  for (BouncePoint& bounce : bounce_points_)
  {
    const ContactPoint& p = points_[bounce.point];
    const double vn = dot(relative_velocity(p, velocity_), p.normal);
    const double gap = current_separation(p, velocity_);
    const bool approaching = vn < -settings_.restitution_threshold;
    bounce.apart = !approaching && gap > kTouchingGap;
    bounce.target = 0.0;
    if (approaching)
    {
      // A gap still open closes later in the substep, after gravity has sped
      // the approach up: the speed at contact, as in free fall over the gap.
      const double closing = closing_gravity(p);
      const double at_contact = gap > 0.0 && closing > 0.0 ? std::sqrt(vn * vn + 2.0 * closing * gap) : -vn;
      bounce.target = newton_target(-at_contact, p.restitution, settings_.restitution_threshold);
    }
    else if (vn > settings_.restitution_threshold)
    {
      // Touching but separating: a push it got is undone as far as Newton's
      // rule allows (it may leave approaching at e times its speed).
      bounce.target = -p.restitution * vn;
    }
  }
}

/// How fast gravity closes p's gap (m/s^2, > 0 closing): only bodies that
/// fall feel it.
double WorldImpl::closing_gravity(const ContactPoint& p) const
{
  const Vec2 none{0.0, 0.0};
  const Vec2 relative = (awake_dynamic(p.a) ? settings_.gravity : none) - (awake_dynamic(p.b) ? settings_.gravity : none);
  return dot(relative, p.normal);
}

void WorldImpl::restitute(StepReport& report)
{
  double fastest = take_bouncing();
  if (!released_.empty() && some_cannot_bounce_)  // an elastic gas has none to hold: skip the scan
  {
    hold_pushing_points();
  }
  if (fastest > 0.0 || !released_.empty())  // else nothing below changes a velocity
  {
    save_bounce_start();
  }
  if (!released_.empty())
  {
    fastest = std::max(fastest, release_points());
  }
  if (fastest > 0.0)  // else nothing bounces: the relax already holds every point
  {
    drive_to_targets(fastest, report);
  }
  store_bounce_impulses();
}

/// Gauss-Seidel over the bouncing and held points to the fixed point;
/// `fastest` (m/s) scales the tolerance.
void WorldImpl::drive_to_targets(double fastest, StepReport& report)
{
  double residual = 0.0;
  for (int pass = 0; pass < kMaxRestitutionPasses; ++pass)
  {
    residual = 0.0;
    for (std::size_t i : bouncing_)
    {
      residual = std::max(residual, apply_restitution(points_[bounce_points_[i].point], velocity_));
    }
    for (const HeldPoint& held : held_)
    {
      residual = std::max(residual, apply_restitution(points_[held.point], velocity_));
    }
    if (residual <= kRestitutionTolerance * fastest)
    {
      break;
    }
  }
  report.velocity_residual = std::max(report.velocity_residual, residual);
  drop_bounces(residual > kRestitutionTolerance * fastest);  // world_soft_bounce_drop.cpp
}

/// The impulses of the bouncing, released and held points before
/// restitution changes any (drop_bounces).
void WorldImpl::save_bounce_start()
{
  bounce_start_.clear();
  for_each_restituted(bouncing_, released_, held_, bounce_points_, [this](std::size_t k, ImpulseSlots) {
    const ContactPoint& p = points_[k];
    bounce_start_.push_back(SavedImpulses{k, p.lambda_n, p.lambda_t, relative_velocity(p, velocity_)});
  });
}

/// Lets go of the released_ points. A released impulse may have balanced
/// others on its bodies (a heavy disk pressing a light box into a wall it
/// was not approaching at the substep's start), so the points of those
/// bodies that push and cannot bounce are held at their speeds now while
/// it comes off; alone, the wall's impulse threw the box at 800 m/s.
/// Returns how far the release moved them from those speeds (m/s).
double WorldImpl::release_points()
{
  for (std::size_t i : released_)
  {
    release_point(points_[bounce_points_[i].point], velocity_);
  }
  double moved = 0.0;
  for (const HeldPoint& held : held_)
  {
    const ContactPoint& p = points_[held.point];
    moved = std::max(moved, std::abs(dot(relative_velocity(p, velocity_), p.normal) - p.target));
  }
  return moved;
}

/// The restituted impulses into their slots; the held points' own targets back.
void WorldImpl::store_bounce_impulses()
{
  for_each_restituted(bouncing_, released_, held_, bounce_points_, [this](std::size_t k, ImpulseSlots slots) {
    store_impulses(points_[k], slots);
  });
  for (const HeldPoint& held : held_)
  {
    points_[held.point].target = held.saved_target;
  }
}

/// held_: the pushing points that cannot bounce on the dynamic bodies of the
/// released_ and bouncing_ points, each aimed at its normal speed now. A
/// bouncing point's bodies count too: a light disk squeezed between a box
/// against a wall and a body it parts from, let go of, was thrown with the
/// box at 1900 m/s by the wall's push.
void WorldImpl::hold_pushing_points()
{
  holding_body_.assign(bodies_.size(), 0);
  const auto mark = [this](std::size_t i) {
    const ContactPoint& p = points_[bounce_points_[i].point];
    holding_body_[p.a] = holding_body_[p.a] || awake_dynamic(p.a);
    holding_body_[p.b] = holding_body_[p.b] || awake_dynamic(p.b);
  };
  for (std::size_t i : released_)
  {
    mark(i);
  }
  for (std::size_t i : bouncing_)
  {
    mark(i);
  }
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    ContactPoint& p = points_[k];
    // Points that can bounce are the bounce points' own (bouncing or let go).
    if (!p.active || p.restitution > 0.0 || !(holding_body_[p.a] || holding_body_[p.b]))
    {
      continue;
    }
    const ImpulseSlots impulses = point_impulses(k);
    if (*impulses.normal > 0.0)
    {
      held_.push_back(HeldPoint{k, impulses, p.target});
      load_impulses(p, impulses);
      p.target = dot(relative_velocity(p, velocity_), p.normal);
    }
  }
}

/// The points restitute drives, into bouncing_; returns their fastest |target| (m/s).
double WorldImpl::take_bouncing()
{
  // A point bounces if the substep pushed it: it ends the substep holding an
  // impulse (the substep's warm start and passes sum to it). Each ends at e
  // times its speed at the substep's start, reversed, or lets go; so with
  // e = 1 the substep keeps the kinetic energy exactly, however many bodies
  // met in it. One apart and not approaching at the start was pushed only
  // because another impact sent a body its way: it lets go now and meets
  // that body in a later substep, at the speed it then has. One the relax
  // slowed before it touched bounces a gap short of contact: gravity over
  // that gap comes off its rebound, as the free fall it skips.
  bouncing_.clear();
  released_.clear();
  held_.clear();
  double fastest = 0.0;
  for (std::size_t i = 0; i < bounce_points_.size(); ++i)
  {
    BouncePoint& bounce = bounce_points_[i];
    if (*bounce.impulses.normal <= 0.0)
    {
      continue;
    }
    ContactPoint& p = points_[bounce.point];
    load_impulses(p, bounce.impulses);  // from their rows, while the rows are packed
    if (bounce.apart)
    {
      released_.push_back(i);  // release_points
      continue;
    }
    p.target = bounce.target;
    if (bounce.target > 0.0)
    {
      const double gap = current_separation(p, velocity_);
      const double closing = closing_gravity(p);
      const double climb = gap > 0.0 && closing > 0.0 ? 2.0 * closing * gap : 0.0;  // m^2/s^2
      p.target = std::sqrt(std::max(0.0, bounce.target * bounce.target - climb));
    }
    bouncing_.push_back(i);
    fastest = std::max(fastest, std::abs(p.target));
  }
  return fastest;
}

}  // namespace detail
}  // namespace collision2d
