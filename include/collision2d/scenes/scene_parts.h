// Building blocks that append bodies to a Scene: the standard scene builders
// are made of them, and the YAML `generate:` entries expand through them, so a
// scene file and its builder produce the same bodies in the same order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/vec2.h"

namespace collision2d
{
namespace scenes
{
/// Standard gravity (m/s^2), y up.
constexpr double kGravity = -9.81;

/// Stacking material: no bounce, enough friction to hold a pyramid.
Material rough_material();
/// Perfectly elastic and frictionless.
Material elastic_material();

/// Counter-clockwise outline of a w x h rectangle centred on the origin (m).
std::vector<Vec2> box_outline(double width, double height);
/// A uniform rectangle; static bodies get BodyType::Static.
Body make_box(double mass, double width, double height, Vec2 position, double theta = 0.0,
              Vec2 velocity = Vec2{}, double omega = 0.0);
Body make_static_box(double width, double height, Vec2 position, double theta = 0.0);

/// A static slab whose top face is the line y = top.
struct GroundParams
{
  double width = 60.0;      ///< m
  double thickness = 1.0;   ///< m
  double top = 0.0;         ///< y of the top face (m)
  double x = 0.0;           ///< x of the centre (m)
  Material material = rough_material();
};
void add_ground(Scene& scene, const GroundParams& params);

/// Four static walls enclosing the rectangle [lower, upper].
struct ContainerParams
{
  Vec2 lower{0.0, 0.0};     ///< inner lower-left corner (m)
  Vec2 upper{10.0, 10.0};   ///< inner upper-right corner (m)
  double thickness = 1.0;   ///< m
  Material material = elastic_material();
};
void add_container(Scene& scene, const ContainerParams& params);

/// Rows of touching boxes, each row one shorter and centred on the one below.
struct PyramidParams
{
  int base = 20;            ///< boxes in the bottom row
  double box = 1.0;         ///< edge length (m)
  double mass = 1.0;        ///< per box (kg)
  Vec2 at{0.0, 0.5};        ///< centre of the bottom row (m)
  Material material = rough_material();
};
void add_pyramid(Scene& scene, const PyramidParams& params);

/// A vertical stack of touching boxes.
struct ColumnParams
{
  int count = 20;
  double box = 1.0;         ///< edge length (m)
  double mass = 1.0;        ///< per box (kg)
  Vec2 at{0.0, 0.5};        ///< centre of the bottom box (m)
  Material material = rough_material();
};
void add_column(Scene& scene, const ColumnParams& params);

/// Touching equal disks in a row along +x; the leftmost moves toward the rest.
struct CradleParams
{
  int count = 5;
  double radius = 0.5;      ///< m
  double mass = 1.0;        ///< kg
  double speed = 1.0;       ///< of the first disk along +x (m/s)
  Vec2 at{0.0, 0.0};        ///< centre of the first disk (m)
  Material material = elastic_material();
};
void add_cradle(Scene& scene, const CradleParams& params);

/// Disks at at + i * step, all with the same velocity.
struct DiskRowParams
{
  int count = 5;
  double radius = 0.25;     ///< m
  double mass = 1.0;        ///< kg
  Vec2 at{0.0, 2.0};        ///< centre of the first disk (m)
  Vec2 step{1.0, 0.5};      ///< offset between neighbours (m)
  Vec2 velocity{0.0, 0.0};  ///< m/s
  Material material = elastic_material();
};
void add_disk_row(Scene& scene, const DiskRowParams& params);

/// Disks on a jittered grid filling [lower, upper] (never overlapping), with
/// random velocities of zero mean; deterministic for a given seed on every
/// platform. Throws std::invalid_argument when the disks do not fit.
struct GasParams
{
  int count = 1000;
  std::uint64_t seed = 7;
  double radius = 0.1;      ///< m
  double mass = 1.0;        ///< kg
  double speed = 2.0;       ///< largest speed before the mean is removed (m/s)
  Vec2 lower{0.0, 0.0};     ///< m
  Vec2 upper{16.0, 16.0};   ///< m
  Material material = elastic_material();
};
void add_gas(Scene& scene, const GasParams& params);

/// A static slab tilted by `angle` about the origin with a box resting on it,
/// centred on the slab and turned with it.
struct InclineParams
{
  double angle = 0.4;       ///< rad, counter-clockwise (the slope rises to +x)
  double length = 20.0;     ///< slab length (m)
  double thickness = 1.0;   ///< slab thickness (m)
  double box = 1.0;         ///< box edge (m)
  double mass = 1.0;        ///< box mass (kg)
  Material material{0.0, 0.5, 0.3};  ///< of both slab and box
};
void add_incline(Scene& scene, const InclineParams& params);

/// A rain: `count` bodies on a grid above the line y = bottom, disks and boxes
/// in turn with sizes varying by a fixed pattern (no randomness, so every
/// engine gets the same bodies), falling at `speed` onto whatever lies below.
struct RainParams
{
  int count = 1000;
  double size = 0.5;        ///< largest disk diameter and box edge (m)
  double spacing = 1.0;     ///< grid pitch, > size (m)
  int columns = 0;          ///< bodies per row; 0: about twice as wide as high
  double bottom = 1.0;      ///< y of the lowest row's centres less half a size (m)
  double speed = 2.0;       ///< downward speed at the start (m/s)
  double density = 1.0;     ///< kg/m^2
  Material material = rough_material();
};
void add_rain(Scene& scene, const RainParams& params);
/// The columns add_rain uses for these parameters.
int rain_columns(const RainParams& params);

}  // namespace scenes
}  // namespace collision2d
