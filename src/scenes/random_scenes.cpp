#include "collision2d/scenes/random_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace collision2d
{
namespace scenes
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kMinPolygonVertices = 3;
constexpr int kMaxPolygonVertices = 8;
/// Polygon vertices sit on an ellipse at angular gaps drawn from this range
/// (relative units, normalised to a full turn): no gap is so small that an
/// edge degenerates, none reaches half a turn.
constexpr double kMinAngularGap = 1.0;
constexpr double kMaxAngularGap = 1.8;
/// Smallest ellipse axis ratio, so polygons are not slivers.
constexpr double kMinAspect = 0.4;
/// Where on a parent's face a child lands, as a fraction of the face from its
/// midpoint: keeps the contact away from the face's corners.
constexpr double kMaxFaceOffset = 0.3;
/// How far a chain's attachment direction wanders from the chain's axis (rad).
constexpr double kChainWander = 0.5;
/// A placement may overlap bodies other than its parent (more contacts), but
/// only by this fraction of the smaller bounding radius, so piles stay
/// physical rather than bodies sunk into each other; up to kPlacementTries
/// hints are tried before the least overlapping one is kept.
constexpr double kMaxIncidentalOverlap = 0.1;
constexpr int kPlacementTries = 16;
/// Spacing between the two islands of a two-island scene, in units of the
/// largest body size per body: far enough that they never touch.
constexpr double kIslandSpacingPerBody = 4.0;
/// Chances that e is exactly 0 or exactly 1, and that mu is exactly 0.
constexpr double kPerfectlyPlasticProbability = 0.2;
constexpr double kPerfectlyElasticProbability = 0.2;
constexpr double kFrictionlessProbability = 0.3;
constexpr double kMaxFriction = 1.0;

/// Uniform draws mapped from the raw 64-bit engine output by hand, so a seed
/// means the same numbers with every standard library.
class Draw
{
public:
  explicit Draw(std::mt19937_64& engine) : engine_(engine) {}

  /// In [0, 1): the top 53 bits as a double.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  bool chance(double p) { return unit() < p; }
  /// In [lo, hi].
  int integer(int lo, int hi)
  {
    const int value = lo + static_cast<int>(unit() * static_cast<double>(hi - lo + 1));
    return std::min(value, hi);
  }
  Vec2 direction()
  {
    const double angle = uniform(-kPi, kPi);
    return {std::cos(angle), std::sin(angle)};
  }

private:
  std::mt19937_64& engine_;
};

double angle_of(Vec2 v) { return std::atan2(v.y, v.x); }

std::vector<Vec2> rectangle(double half_width, double half_height)
{
  return {{-half_width, -half_height}, {half_width, -half_height}, {half_width, half_height}, {-half_width, half_height}};
}

/// Convex: points on an ellipse in angular order.
std::vector<Vec2> ellipse_polygon(Draw& draw, double size)
{
  const int count = draw.integer(kMinPolygonVertices, kMaxPolygonVertices);
  std::vector<double> gaps(static_cast<std::size_t>(count));
  double total = 0.0;
  for (double& gap : gaps)
  {
    gap = draw.uniform(kMinAngularGap, kMaxAngularGap);
    total += gap;
  }
  const double semi_minor = size * draw.uniform(kMinAspect, 1.0);
  double angle = draw.uniform(-kPi, kPi);
  std::vector<Vec2> vertices;
  for (double gap : gaps)
  {
    vertices.push_back({size * std::cos(angle), semi_minor * std::sin(angle)});
    angle += 2.0 * kPi * gap / total;
  }
  return vertices;
}

Body random_body(Draw& draw, const RandomSceneOptions& options)
{
  const double mass = options.base_mass * std::pow(options.max_mass_ratio, draw.unit());
  const double size = draw.uniform(options.min_size, options.max_size);
  // The direction is drawn before the speed, in its own statement: the
  // operands of * are unsequenced, so one expression drew in each compiler's
  // own order (this is the order GCC on x86-64 chose, the pinned one).
  const Vec2 heading = draw.direction();
  const Vec2 velocity = std::sqrt(draw.unit()) * options.max_speed * heading;
  const double omega = draw.uniform(-options.max_spin, options.max_spin);
  if (!draw.chance(options.polygon_probability))
    return Body(mass, size, Vec2{}, velocity, omega);
  const std::vector<Vec2> outline = draw.chance(options.box_probability)
                                        ? rectangle(size, size * draw.uniform(kMinAspect, 1.0))
                                        : ellipse_polygon(draw, size);
  return Body(mass, outline, Vec2{}, velocity, 0.0, omega);
}

/// Where a child touches `parent` on the side facing `hint`: the outward
/// direction d there and a point s on the parent's outline.
void contact_site(Draw& draw, const Body& parent, Vec2 hint, Vec2& d, Vec2& s)
{
  if (parent.shape() == Shape::Disk)
  {
    d = hint;
    s = parent.position() + parent.radius() * hint;
    return;
  }
  std::size_t face = 0;
  for (std::size_t i = 1; i < parent.vertex_count(); ++i)
    if (dot(parent.world_face_normal(i), hint) > dot(parent.world_face_normal(face), hint))
      face = i;
  d = parent.world_face_normal(face);
  const Vec2 v0 = parent.world_vertex(face);
  const Vec2 v1 = parent.world_vertex((face + 1) % parent.vertex_count());
  s = v0 + (0.5 + draw.uniform(-kMaxFaceOffset, kMaxFaceOffset)) * (v1 - v0);
}

/// Places `child` so that its outermost point toward the parent sits `overlap`
/// inside the parent at s (moving inward from s along -d stays inside the
/// parent: s is a disk's boundary point or the inner part of a face).
void attach(Draw& draw, const RandomSceneOptions& options, const Body& parent, Body& child, Vec2 hint,
            double overlap)
{
  Vec2 d;
  Vec2 s;
  contact_site(draw, parent, hint, d, s);
  const Vec2 tip = s - overlap * d;  // where the child's nearest point goes
  if (child.shape() == Shape::Disk)
  {
    child.set_position(tip + child.radius() * d);
    return;
  }
  const std::vector<Vec2>& local = child.local_vertices();
  const std::size_t n = local.size();
  Vec2 nearest;
  if (draw.chance(options.face_to_face_probability))
  {
    // Turn a random face to point back at the parent: a two-point manifold
    // when the parent is a polygon.
    const std::size_t face = static_cast<std::size_t>(draw.integer(0, static_cast<int>(n) - 1));
    child.set_theta(angle_of(-d) - angle_of(child.local_face_normals()[face]));
    nearest = 0.5 * (child.world_vertex(face) + child.world_vertex((face + 1) % n)) - child.position();
  }
  else
  {
    child.set_theta(draw.uniform(-kPi, kPi));
    nearest = child.world_vertex(0) - child.position();
    for (std::size_t i = 1; i < n; ++i)
      if (dot(child.world_vertex(i) - child.position(), d) < dot(nearest, d))
        nearest = child.world_vertex(i) - child.position();
  }
  child.set_position(tip - nearest);
}

/// Deepest bounding-circle overlap of bodies[child] with bodies [begin, child)
/// other than its parent, relative to the smaller radius.
double incidental_overlap(const std::vector<Body>& bodies, std::size_t begin, std::size_t parent, std::size_t child)
{
  double worst = 0.0;
  for (std::size_t k = begin; k < child; ++k)
  {
    if (k == parent)
      continue;
    const double reach = bodies[k].radius() + bodies[child].radius();
    const double depth = reach - length(bodies[k].position() - bodies[child].position());
    worst = std::max(worst, depth / std::min(bodies[k].radius(), bodies[child].radius()));
  }
  return worst;
}

/// Which earlier body the next one touches, and from which side.
void choose_attachment(Draw& draw, RandomLayout layout, Vec2 axis, std::size_t begin, std::size_t child,
                       std::size_t count, int attempt, std::size_t& parent, Vec2& hint)
{
  switch (layout)
  {
    case RandomLayout::Chain:
    {
      parent = child - 1;
      const double wander = draw.uniform(-kChainWander, kChainWander);
      hint = rotate(axis, std::cos(wander), std::sin(wander));
      return;
    }
    case RandomLayout::Star:
    {
      // Evenly around the centre first; later attempts anywhere around it.
      parent = begin;
      const double step = 2.0 * kPi / static_cast<double>(std::max<std::size_t>(count - 1, 1));
      const double angle = attempt == 0 ? angle_of(axis) + step * static_cast<double>(child - begin - 1)
                                        : draw.uniform(-kPi, kPi);
      hint = {std::cos(angle), std::sin(angle)};
      return;
    }
    case RandomLayout::Pile:
      parent = begin + static_cast<std::size_t>(draw.integer(0, static_cast<int>(child - begin) - 1));
      hint = draw.direction();
      return;
  }
}

/// Lays out bodies [begin, end) as one island whose first body sits at `origin`.
void lay_out_island(Draw& draw, const RandomSceneOptions& options, RandomLayout layout, Vec2 origin,
                     std::vector<Body>& bodies, std::size_t begin, std::size_t end)
{
  bodies[begin].set_position(origin);
  const Vec2 axis = draw.direction();
  for (std::size_t i = begin + 1; i < end; ++i)
  {
    Body best = bodies[i];
    double best_overlap = std::numeric_limits<double>::infinity();
    for (int attempt = 0; attempt < kPlacementTries && best_overlap > kMaxIncidentalOverlap; ++attempt)
    {
      std::size_t parent = begin;
      Vec2 hint;
      choose_attachment(draw, layout, axis, begin, i, end - begin, attempt, parent, hint);
      const double smaller = std::min(bodies[parent].radius(), bodies[i].radius());
      attach(draw, options, bodies[parent], bodies[i], hint, draw.uniform(0.0, options.max_overlap) * smaller);
      const double overlap = incidental_overlap(bodies, begin, parent, i);
      if (overlap < best_overlap)
      {
        best_overlap = overlap;
        best = bodies[i];
      }
    }
    bodies[i] = best;
  }
}

void check_options(const RandomSceneOptions& o)
{
  if (!(o.min_bodies >= 2 && o.max_bodies >= o.min_bodies))
    throw std::invalid_argument("RandomSceneOptions: need 2 <= min_bodies <= max_bodies");
  if (!(o.min_size > 0.0 && o.max_size >= o.min_size))
    throw std::invalid_argument("RandomSceneOptions: need 0 < min_size <= max_size");
  if (!(o.base_mass > 0.0 && o.max_mass_ratio >= 1.0))
    throw std::invalid_argument("RandomSceneOptions: need base_mass > 0 and max_mass_ratio >= 1");
  if (!(o.max_overlap >= 0.0 && o.max_overlap < 1.0))
    throw std::invalid_argument("RandomSceneOptions: need 0 <= max_overlap < 1");
}
}  // namespace

RandomSceneGenerator::RandomSceneGenerator(std::uint64_t seed, RandomSceneOptions options)
  : engine_(seed), options_(options)
{
  check_options(options_);
}

RandomScene RandomSceneGenerator::next()
{
  Draw draw(engine_);
  RandomScene scene;
  scene.layout = static_cast<RandomLayout>(draw.integer(0, 2));
  if (draw.chance(kPerfectlyPlasticProbability))
    scene.restitution = 0.0;
  else if (draw.chance(kPerfectlyElasticProbability))
    scene.restitution = 1.0;
  else
    scene.restitution = draw.unit();
  scene.friction = draw.chance(kFrictionlessProbability) ? 0.0 : draw.uniform(0.0, kMaxFriction);

  const int count = draw.integer(options_.min_bodies, options_.max_bodies);
  for (int i = 0; i < count; ++i)
    scene.bodies.push_back(random_body(draw, options_));

  const std::size_t n = scene.bodies.size();
  const bool two_islands = n >= 4 && draw.chance(options_.second_island_probability);
  const std::size_t split = two_islands ? n / 2 : n;
  const double spacing = kIslandSpacingPerBody * options_.max_size * static_cast<double>(n);
  lay_out_island(draw, options_, scene.layout, Vec2{}, scene.bodies, 0, split);
  if (two_islands)
    lay_out_island(draw, options_, scene.layout, Vec2{spacing, 0.0}, scene.bodies, split, n);

  if (draw.chance(options_.static_probability))
  {
    scene.bodies.front().set_type(BodyType::Static);
    scene.bodies.front().set_velocity(Vec2{});
    scene.bodies.front().set_omega(0.0);
  }
  return scene;
}

}  // namespace scenes
}  // namespace collision2d
