// A dynamic body's centroid never passes into a static body it was clear
// of. The substeps' sweeps (world_toi.cpp) stop a body fast enough to skip a
// thin body in one substep; a body crushed into a static one by a heavy or
// fast neighbour the contacts cannot hold can still go deep over a frame's
// substeps. So after the frame's moves (after each substep in the Fx2D
// order) a body that moved far for its size, or that a kinematic face
// pushed (Fx2D), has its centroid core swept along its path against the
// static bodies and stops where it first touches one; the contact then
// pushes it back out the way it came. Its velocity is kept: the next
// frame's contact takes the impact. A centroid already on a static face,
// or pressed into it by less than the body's inner radius (the contacts did
// not hold the body), keeps only the part of its move along the face, and
// its turn: its velocity into the face goes, or the body would stay frozen
// there with a velocity that never moves it. That part is swept again, so
// a corner stops it too.
#include <algorithm>
#include <limits>

#include "outline_gap.h"
#include "world_motion.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Once the core already touches a static body, the centroid itself is
/// swept: a disk this fraction of the inner radius.
constexpr double kCentroidFraction = 1e-3;

/// Faces a centroid on a static face slides along before it stops: the two
/// of a corner, and one more for a gap narrower than the body.
constexpr int kCornerFaces = 3;

/// A move into a face by at most this fraction of its length is along it
/// (round-off of without_inward: the face's unit normal is not exact).
constexpr double kAlongFace = 1e-12;

/// d less its part into a face of outward normal n (unit).
Vec2 without_inward(Vec2 d, Vec2 n) { return d - std::min(0.0, dot(d, n)) * n; }

}  // namespace

PointGap outline_point_gap(const Body& b, Vec2 p)
{
  if (b.shape() == Shape::Disk)
  {
    const Vec2 r = p - b.position();
    const double distance = length(r);
    return {distance - b.radius(), distance > 0.0 ? r * (1.0 / distance) : Vec2{0.0, 1.0}};
  }
  PointGap best{-std::numeric_limits<double>::infinity(), Vec2{0.0, 1.0}};
  for (std::size_t k = 0; k < b.vertex_count(); ++k)
  {
    const Vec2 normal = b.world_face_normal(k);
    const double gap = dot(normal, p - b.world_vertex(k));
    if (gap > best.gap)
    {
      best = {gap, normal};
    }
  }
  return best;
}

double WorldMotion::static_crossing_time(std::size_t i, Vec2 from, Vec2 d, Vec2& face)
{
  if (!is_finite(from) || !is_finite(d))
  {
    return 1.0;  // a pose that overflowed is the finiteness check's
  }
  const double r = kCoreFraction * inner_radius_[i];
  const Aabb path = Aabb{from - Vec2{r, r}, from + Vec2{r, r}}.swept(d);
  crossing_pairs_.clear();
  resting_grid_.query(path, i, crossing_pairs_);
  double earliest = 1.0;
  const auto sweep_against = [&](std::size_t j) {
    const Body& obstacle = bodies_[j];
    if (obstacle.type() == BodyType::Static && obstacle.aabb().overlaps(path))
    {
      earliest = std::min(earliest, centroid_entry_time(i, from, d, obstacle, face));
    }
  };
  for (const BodyPair& pair : crossing_pairs_)
  {
    sweep_against(pair.first == i ? pair.second : pair.first);
  }
  for (const std::size_t j : resting_grid_.large())
  {
    sweep_against(j);
  }
  return earliest;
}

/// When body i's centroid, moved from `from` by d, would first pass into
/// static `obstacle`: the fraction of d its core (or centroid) moves clear;
/// 1 if never; 0 on the obstacle's face (its normal into `face`), as static_crossing_time.
double WorldMotion::centroid_entry_time(std::size_t i, Vec2 from, Vec2 d, const Body& obstacle, Vec2& face) const
{
  const double inner = inner_radius_[i];
  const double t = disk_time_of_impact(i, kCoreFraction * inner, from, d, obstacle, Vec2{0.0, 0.0});
  if (t > 0.0)
  {
    return t;
  }
  // The core touches already: the centroid may come up to the surface, not
  // past it; a centroid deeper inside is the contacts' to push out.
  const double tolerance = kCentroidFraction * inner;
  const PointGap gap = outline_point_gap(obstacle, from);
  if (gap.gap > tolerance)
  {
    const double u = disk_time_of_impact(i, tolerance, from, d, obstacle, Vec2{0.0, 0.0});
    return u > 0.0 ? u : 1.0;
  }
  // A body thinner than `slop` may rest with its centroid that far inside,
  // and contacts that could not hold a body leave it pressed in: up to its
  // inner radius either moves no deeper (a push would carry it through).
  const bool on_surface = gap.gap >= -std::max(inner, settings_.slop);
  if (on_surface && dot(d, gap.normal) < -kAlongFace * length(d))
  {
    face = gap.normal;
    return 0.0;
  }
  return 1.0;
}

void WorldMotion::stop_static_crossings(StepContext& ctx, StepReport& report, bool soft)
{
  if (settings_.time_of_impact == Toggle::Off || resting_.empty())
  {
    return;
  }
  // The soft step moves the frame's poses from prepare; the Fx2D order the
  // bodies themselves from the substep's start.
  const std::vector<Vec2>& start = soft ? prepared_position_ : prev_position_;
  const std::vector<double>& start_theta = soft ? prepared_theta_ : prev_theta_;
  // Inlined by request: called per body, the lambda cost a large falling
  // world a fifth as much again as the sweeps it calls.
  visit_bodies([&](std::size_t i) __attribute__((always_inline)) {
    if (soft ? frame_motion_[i] != FrameMotion::Dynamic : !awake_dynamic(i))
    {
      return;
    }
    const Vec2 end = soft ? frame_position_[i] : bodies_[i].position();
    // A kinematic face pushes again each substep (the Fx2D order), so short
    // pushes into a static body add up: a pushed body is swept however
    // little it moved.
    const bool pushed = !soft && pushing_ && pusher_[i] != kNoBody;
    if (!pushed && !moved_far(i, end - start[i]))
    {
      return;  // checked here: the sweep's own call would save registers first
    }
    const double end_theta = soft ? frame_theta_[i] : bodies_[i].theta();
    Vec2 d = end - start[i];
    Vec2 face;
    double t = static_crossing_time(i, start[i], d, face);
    if (t >= 1.0)
    {
      return;
    }
    // On a face (t exactly 0) only the move and the velocity into it stop;
    // the move along it is swept again, for the next face of a corner (a
    // bar pressing a box down a wall drove it into the ground).
    bool on_face = false;
    for (int faces = 0; t == 0.0 && faces < kCornerFaces; ++faces)
    {
      on_face = true;
      d = without_inward(d, face);
      take_out_approach(i, kNoBody, face, start[i], !soft);  // world_toi.cpp
      t = static_crossing_time(i, start[i], d, face);
    }
    t = std::min(t, 1.0);
    const Vec2 at = start[i] + t * d;
    const double theta = on_face && t == 1.0 ? end_theta : start_theta[i] + t * (end_theta - start_theta[i]);
    if (soft)
    {
      frame_position_[i] = at;
      frame_theta_[i] = theta;
      if (touching_[i])
      {
        follow_pose(i);
      }
    }
    else
    {
      bodies_[i].set_position(at);
      bodies_[i].set_theta(theta);
    }
    ++report.toi_clamps;
    ctx.effects.time_of_impact = true;
  });
}

}  // namespace detail
}  // namespace collision2d
