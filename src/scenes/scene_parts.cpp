// Building blocks of the standard scenes (see scene_parts.h).
#include "collision2d/scenes/scene_parts.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace collision2d
{
namespace scenes
{
namespace
{
/// Static bodies never use their mass (inverse mass 0), but Body needs one.
constexpr double kStaticMass = 1.0;  // kg
constexpr double kTwoPi = 6.283185307179586;

void require_count(int count, const char* part)
{
  if (count < 1)
  {
    throw std::invalid_argument(std::string(part) + ": count must be at least 1 (got " + std::to_string(count) + ")");
  }
}

void require_positive(double value, const char* part, const char* field)
{
  if (!(std::isfinite(value) && value > 0.0))
  {
    throw std::invalid_argument(std::string(part) + ": " + field + " must be positive and finite");
  }
}

void add(Scene& scene, const Body& body, const Material& material, const std::string& name)
{
  scene.bodies.push_back(SceneBody{body, material, name});
}

/// SplitMix64: a tiny generator with a fixed, documented output sequence, so a
/// seed gives the same gas on every compiler (std distributions do not).
class SplitMix64
{
public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  /// Uniform in [0, 1).
  double uniform()
  {
    state_ += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
    return static_cast<double>(z >> 11) * kTwoToMinus53;
  }

private:
  std::uint64_t state_;
};

}  // namespace

Material rough_material()
{
  return Material{0.0, 0.6, 0.5};
}

Material elastic_material()
{
  return Material{1.0, 0.0, 0.0};
}

std::vector<Vec2> box_outline(double width, double height)
{
  const double hw = 0.5 * width;
  const double hh = 0.5 * height;
  return {{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}};
}

Body make_box(double mass, double width, double height, Vec2 position, double theta, Vec2 velocity, double omega)
{
  return Body(mass, box_outline(width, height), position, velocity, theta, omega);
}

Body make_static_box(double width, double height, Vec2 position, double theta)
{
  Body body = make_box(kStaticMass, width, height, position, theta);
  body.set_type(BodyType::Static);
  return body;
}

void add_ground(Scene& scene, const GroundParams& p)
{
  require_positive(p.width, "ground", "width");
  require_positive(p.thickness, "ground", "thickness");
  add(scene, make_static_box(p.width, p.thickness, {p.x, p.top - 0.5 * p.thickness}), p.material, "ground");
}

void add_container(Scene& scene, const ContainerParams& p)
{
  require_positive(p.thickness, "container", "thickness");
  require_positive(p.upper.x - p.lower.x, "container", "width (upper.x - lower.x)");
  require_positive(p.upper.y - p.lower.y, "container", "height (upper.y - lower.y)");
  const double t = p.thickness;
  const double w = p.upper.x - p.lower.x;
  const double h = p.upper.y - p.lower.y;
  const double cx = 0.5 * (p.lower.x + p.upper.x);
  const double cy = 0.5 * (p.lower.y + p.upper.y);
  // Floor and roof span the corners; the side walls fit between them, touching
  // but not overlapping, so no static pair starts in contact.
  add(scene, make_static_box(w + 2.0 * t, t, {cx, p.lower.y - 0.5 * t}), p.material, "wall_bottom");
  add(scene, make_static_box(w + 2.0 * t, t, {cx, p.upper.y + 0.5 * t}), p.material, "wall_top");
  add(scene, make_static_box(t, h, {p.lower.x - 0.5 * t, cy}), p.material, "wall_left");
  add(scene, make_static_box(t, h, {p.upper.x + 0.5 * t, cy}), p.material, "wall_right");
}

void add_pyramid(Scene& scene, const PyramidParams& p)
{
  require_count(p.base, "pyramid");
  require_positive(p.box, "pyramid", "box");
  for (int row = 0; row < p.base; ++row)
  {
    const int boxes = p.base - row;
    const double left = p.at.x - 0.5 * (boxes - 1) * p.box;
    for (int col = 0; col < boxes; ++col)
    {
      const Vec2 centre{left + col * p.box, p.at.y + row * p.box};
      add(scene, make_box(p.mass, p.box, p.box, centre), p.material,
          "pyramid_" + std::to_string(row) + "_" + std::to_string(col));
    }
  }
}

void add_column(Scene& scene, const ColumnParams& p)
{
  require_count(p.count, "column");
  require_positive(p.box, "column", "box");
  for (int i = 0; i < p.count; ++i)
  {
    add(scene, make_box(p.mass, p.box, p.box, {p.at.x, p.at.y + i * p.box}), p.material,
        "column_" + std::to_string(i));
  }
}

void add_cradle(Scene& scene, const CradleParams& p)
{
  require_count(p.count, "cradle");
  for (int i = 0; i < p.count; ++i)
  {
    const Vec2 velocity{i == 0 ? p.speed : 0.0, 0.0};
    add(scene, Body(p.mass, p.radius, {p.at.x + 2.0 * i * p.radius, p.at.y}, velocity), p.material,
        "cradle_" + std::to_string(i));
  }
}

void add_disk_row(Scene& scene, const DiskRowParams& p)
{
  require_count(p.count, "disk_row");
  for (int i = 0; i < p.count; ++i)
  {
    add(scene, Body(p.mass, p.radius, p.at + static_cast<double>(i) * p.step, p.velocity), p.material,
        "disk_" + std::to_string(i));
  }
}

void add_gas(Scene& scene, const GasParams& p)
{
  require_count(p.count, "gas");
  require_positive(p.radius, "gas", "radius");
  const double w = p.upper.x - p.lower.x;
  const double h = p.upper.y - p.lower.y;
  require_positive(w, "gas", "width (upper.x - lower.x)");
  require_positive(h, "gas", "height (upper.y - lower.y)");
  // Square cells laid out to the region's aspect ratio, one disk per cell.
  // More columns than disks would stay empty; capping also keeps a very wide
  // region's column count (up to infinity) inside an int.
  const double wanted = std::ceil(std::sqrt(p.count * w / h));
  const int cols = static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(p.count)));
  const int rows = (p.count + cols - 1) / cols;
  const double cell = std::min(w / cols, h / rows);
  const double slack = cell - 2.0 * p.radius;
  if (!(slack > 0.0))
  {
    std::ostringstream message;
    message << "gas: " << p.count << " disks of radius " << p.radius << " m do not fit in the region";
    throw std::invalid_argument(message.str());
  }
  SplitMix64 rng(p.seed);
  const std::size_t first = scene.bodies.size();
  Vec2 mean_velocity;
  for (int i = 0; i < p.count; ++i)
  {
    // Jitter within the cell's slack keeps every pair apart.
    const Vec2 jitter{(rng.uniform() - 0.5) * slack, (rng.uniform() - 0.5) * slack};
    const Vec2 centre = p.lower + Vec2{(i % cols + 0.5) * cell, (i / cols + 0.5) * cell} + jitter;
    const double heading = kTwoPi * rng.uniform();
    const double speed = p.speed * rng.uniform();
    const Vec2 velocity{speed * std::cos(heading), speed * std::sin(heading)};
    mean_velocity += velocity;
    add(scene, Body(p.mass, p.radius, centre, velocity), p.material, "gas_" + std::to_string(i));
  }
  // Zero total momentum: the gas as a whole stays put instead of pressing on
  // one wall, so the walls only confine it.
  mean_velocity = mean_velocity / static_cast<double>(p.count);
  for (std::size_t i = first; i < scene.bodies.size(); ++i)
  {
    Body& body = scene.bodies[i].body;
    body.set_velocity(body.velocity() - mean_velocity);
  }
}

void add_incline(Scene& scene, const InclineParams& p)
{
  require_positive(p.box, "incline", "box");
  const double c = std::cos(p.angle);
  const double s = std::sin(p.angle);
  // The box sits centred on the slab's top face, both turned by the angle.
  const double lift = 0.5 * p.thickness + 0.5 * p.box;
  add(scene, make_static_box(p.length, p.thickness, Vec2{}, p.angle), p.material, "slab");
  add(scene, make_box(p.mass, p.box, p.box, rotate(Vec2{0.0, lift}, c, s), p.angle), p.material, "box");
}

int rain_columns(const RainParams& p)
{
  return p.columns > 0 ? p.columns : std::max(1, static_cast<int>(std::ceil(std::sqrt(2.0 * p.count))));
}

void add_rain(Scene& scene, const RainParams& p)
{
  require_count(p.count, "rain");
  require_positive(p.size, "rain", "size");
  if (!(p.spacing > p.size))
  {
    throw std::invalid_argument("rain: spacing must exceed size");
  }
  // Sizes cycle through these fractions of `size`; disks and boxes alternate.
  constexpr double kScales[] = {1.0, 0.8, 0.6, 0.9, 0.7};
  constexpr int kScaleCount = 5;
  const int columns = rain_columns(p);
  const double left = -0.5 * (columns - 1) * p.spacing;
  for (int i = 0; i < p.count; ++i)
  {
    const int row = i / columns;
    const int col = i % columns;
    const double scale = kScales[(i / 2) % kScaleCount] * p.size;
    const Vec2 centre{left + col * p.spacing, p.bottom + 0.5 * p.size + row * p.spacing};
    const Vec2 velocity{0.0, -p.speed};
    const bool disk = (i + row) % 2 == 0;
    const double mass = p.density * (disk ? kTwoPi / 8.0 * scale * scale : scale * scale);
    add(scene, disk ? Body(mass, 0.5 * scale, centre, velocity) : make_box(mass, scale, scale, centre, 0.0, velocity),
        p.material, "rain_" + std::to_string(i));
  }
}

}  // namespace scenes
}  // namespace collision2d
