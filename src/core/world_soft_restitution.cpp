// The soft step's restitution (world_soft_step.cpp calls it around each
// substep). At a substep's start every point that can bounce takes its Newton
// target from its approach speed then; at the substep's end the points the
// substep pushed are driven to their targets, Gauss-Seidel in point order to
// the fixed point (on one thread). Targets fixed once per frame would stop a
// contact that a body only turns toward after an earlier bounce in the same
// frame, and lose its energy; per substep, each meeting bounces from the speed
// it happened at.
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
}  // namespace

void WorldImpl::find_bounce_points()
{
  bounce_points_.clear();
  if (!bounces_)
  {
    return;  // stacks and other frames without e > 0 skip restitution whole
  }
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    ContactPoint& p = points_[k];
    if (!p.active || p.restitution <= 0.0)
    {
      continue;
    }
    // Packed rows carry the impulses during the substeps; other points their own.
    double* normal = rows_on() ? soft_rows_.normal_impulse_of(k) : nullptr;
    BouncePoint bounce;
    bounce.point = k;
    bounce.normal = normal != nullptr ? normal : &p.lambda_n;
    bounce_points_.push_back(bounce);
  }
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
  const double fastest = take_bouncing();
  if (fastest == 0.0)
  {
    return;  // nothing bounces: the relax already holds every point
  }
  double residual = 0.0;
  for (int pass = 0; pass < kMaxRestitutionPasses; ++pass)
  {
    residual = 0.0;
    for (std::size_t i : bouncing_)
    {
      residual = std::max(residual, apply_restitution(points_[bounce_points_[i].point], velocity_));
    }
    if (residual <= kRestitutionTolerance * fastest)
    {
      break;
    }
  }
  report.velocity_residual = std::max(report.velocity_residual, residual);
  for (std::size_t i : bouncing_)
  {
    *bounce_points_[i].normal = points_[bounce_points_[i].point].lambda_n;
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
  double fastest = 0.0;
  for (std::size_t i = 0; i < bounce_points_.size(); ++i)
  {
    BouncePoint& bounce = bounce_points_[i];
    if (*bounce.normal <= 0.0)
    {
      continue;
    }
    ContactPoint& p = points_[bounce.point];
    p.lambda_n = *bounce.normal;  // from its row, while the rows are packed
    if (bounce.apart)
    {
      release_normal(p, velocity_);
      *bounce.normal = p.lambda_n;
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
