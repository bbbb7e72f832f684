// Rigid 2D bodies: uniform disks and uniform convex polygons.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "collision2d/aabb.h"
#include "collision2d/vec2.h"

namespace collision2d
{
enum class Shape
{
  Disk,
  Polygon
};

/// Dynamic bodies respond to impulses. Static and kinematic bodies have
/// inverse mass and inverse inertia 0: contacts never push them and they add
/// nothing to effective masses. A kinematic body keeps its set velocity; a
/// static one is also expected to have zero velocity.
enum class BodyType
{
  Dynamic,
  Static,
  Kinematic
};

class Body
{
public:
  /// Uniform disk: inertia 1/2 m R^2. Throws std::invalid_argument for a
  /// non-positive or non-finite mass or radius, or non-finite state.
  Body(double mass, double radius, Vec2 position, Vec2 velocity, double omega = 0.0);

  /// Uniform convex polygon. `local_vertices` are counter-clockwise in the body
  /// frame and are recentred on their centroid; the inertia is the polygon's
  /// polar second moment of area times density. Throws std::invalid_argument
  /// for fewer than 3 vertices, non-positive area (clockwise or degenerate),
  /// a non-convex outline, a non-positive mass or non-finite input.
  Body(double mass, const std::vector<Vec2>& local_vertices, Vec2 position, Vec2 velocity, double theta = 0.0,
       double omega = 0.0);

  double mass() const { return mass_; }
  /// Disk radius, or for a polygon the bounding radius about its centroid.
  double radius() const { return radius_; }
  Vec2 position() const { return position_; }
  Vec2 velocity() const { return velocity_; }
  double omega() const { return omega_; }
  double theta() const { return theta_; }
  Shape shape() const { return shape_; }
  BodyType type() const { return type_; }
  std::size_t vertex_count() const { return local_vertices_.size(); }
  /// Centroid-relative vertices, counter-clockwise (empty for a disk).
  const std::vector<Vec2>& local_vertices() const { return local_vertices_; }
  /// Outward unit normal of face i (from vertex i to vertex i+1) in the body frame.
  const std::vector<Vec2>& local_face_normals() const { return local_normals_; }
  Vec2 world_vertex(std::size_t i) const { return position_ + rotate(local_vertices_[i], cos_, sin_); }
  Vec2 world_face_normal(std::size_t i) const;
  /// cos(theta), sin(theta), cached when theta changes.
  double cos_theta() const { return cos_; }
  double sin_theta() const { return sin_; }

  /// 0 for static and kinematic bodies.
  double inv_mass() const { return type_ == BodyType::Dynamic ? inv_mass_ : 0.0; }
  double inertia() const { return inertia_; }
  /// 0 for static and kinematic bodies.
  double inv_inertia() const { return type_ == BodyType::Dynamic ? inv_inertia_ : 0.0; }

  /// Velocity of the material point of this body at world point p.
  Vec2 velocity_at(Vec2 p) const { return velocity_ + cross(omega_, p - position_); }
  double kinetic_energy() const;
  /// m v
  Vec2 momentum() const { return mass_ * velocity_; }
  /// About the world origin: I w + m p x v.
  double angular_momentum() const;
  /// Tight world-space bounding box at the current pose. Inline: a box
  /// returned from another unit came back through the stack in pieces.
  Aabb aabb() const
  {
    if (shape_ == Shape::Disk)
    {
      const Vec2 half{radius_, radius_};
      return {position_ - half, position_ + half};
    }
    Aabb box{world_vertex(0), world_vertex(0)};
    for (std::size_t i = 1; i < local_vertices_.size(); ++i)
    {
      const Vec2 p = world_vertex(i);
      box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y)};
      box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y)};
    }
    return box;
  }

  void set_velocity(Vec2 v) { velocity_ = v; }
  void set_omega(double w) { omega_ = w; }
  void set_position(Vec2 p) { position_ = p; }
  void set_theta(double theta);
  void set_type(BodyType type) { type_ = type; }

private:
  double mass_;
  double inv_mass_;
  double inertia_;
  double inv_inertia_;
  double radius_;
  Vec2 position_;
  Vec2 velocity_;
  double theta_ = 0.0;
  double omega_ = 0.0;
  double cos_ = 1.0;
  double sin_ = 0.0;
  Shape shape_;
  BodyType type_ = BodyType::Dynamic;
  std::vector<Vec2> local_vertices_;
  std::vector<Vec2> local_normals_;
};

/// Whether position, theta, velocity and omega are all finite, in one test:
/// x * 0 is 0 for a finite x and NaN otherwise (the World checks every body
/// each frame).
inline bool has_finite_state(const Body& b)
{
  const double zeros = (b.position().x * 0.0 + b.position().y * 0.0) + (b.velocity().x * 0.0 + b.velocity().y * 0.0) +
                       (b.theta() * 0.0 + b.omega() * 0.0);
  return zeros == 0.0;
}

/// The first of position, theta, velocity, omega that is not finite, or
/// nullptr when the whole state is finite. Body setters do not check (they
/// run in every substep), so every entry point checks with this.
inline const char* non_finite_state_field(const Body& b)
{
  if (has_finite_state(b))
  {
    return nullptr;
  }
  return !is_finite(b.position())   ? "position"
         : !std::isfinite(b.theta()) ? "theta"
         : !is_finite(b.velocity())  ? "velocity"
         : !std::isfinite(b.omega()) ? "omega"
                                     : nullptr;
}

}  // namespace collision2d
