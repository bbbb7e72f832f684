// Model selection: which effects a frame models. Under Toggle::Auto an effect
// is on only when the scene can show it; On and Off override.
#include <algorithm>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
bool resolve(Toggle toggle, bool needed)
{
  return toggle == Toggle::Auto ? needed : toggle == Toggle::On;
}

double restitution_of(const Material& m) { return m.restitution; }
double friction_of(const Material& m) { return std::max(m.static_friction, m.kinetic_friction); }

}  // namespace

void BodyCensus::add(const BodyCensus& other)
{
  dynamic += other.dynamic;
  rough += other.rough;
  dynamic_rough += other.dynamic_rough;
  bouncy += other.bouncy;
  dynamic_bouncy += other.dynamic_bouncy;
  dynamic_polygons += other.dynamic_polygons;
  widest_dynamic_polygon = std::max(widest_dynamic_polygon, other.widest_dynamic_polygon);
  spinning_disks += other.spinning_disks;
  disks += other.disks;
  turning_face_bodies += other.turning_face_bodies;
  moving_kinematic_bodies += other.moving_kinematic_bodies;
  kinematic_bodies += other.kinematic_bodies;
}

/// take_census, kept while no edit changes the bodies (census_).
const BodyCensus& WorldImpl::census_for_frame()
{
  // Types, shapes and materials change only by an edit, so their counts hold
  // until one. Where rotation's Auto choice turns on a disk's spin (no
  // friction, no dynamic polygon), a spinning disk can stop in any frame (it
  // falls asleep), so spins are counted again each frame; with none, rotation
  // is off and nothing but an edit starts one.
  const bool counted = census_known_ && census_version_ == version_;
  const bool spin_decides = settings_.rotation == Toggle::Auto &&
                            !resolve(settings_.friction, census_.rough_pair()) && census_.dynamic_polygons == 0;
  if (!counted || (spin_decides && census_.spinning_disks > 0))
  {
    census_ = take_census();
    census_known_ = true;
    census_version_ = version_;
  }
  return census_;
}

BodyCensus WorldImpl::take_census()
{
  // Counts only, so the parts' sums are the one-pass ones. A resting body's
  // count cannot change while it rests: the resting bodies' census is kept
  // with their grid and only the movers are counted again.
  const bool movers_only = movers_current();
  const std::size_t n = movers_only ? movers_.size() : bodies_.size();
  const auto count_range = [&](std::size_t begin, std::size_t end) {
    BodyCensus counted;
    for (std::size_t k = begin; k < end; ++k)
    {
      count_body(movers_only ? movers_[k] : k, counted);
    }
    return counted;
  };
  const BodyCensus start = movers_only ? resting_census_ : BodyCensus{};
  return fold_in_parts(n, kMinSharedBodies, census_parts_, start, count_range,
                       [](BodyCensus census, const BodyCensus& part) {
                         census.add(part);
                         return census;
                       });
}

void WorldImpl::count_body(std::size_t i, BodyCensus& census) const
{
  const Body& b = bodies_[i];
  const bool dynamic = b.type() == BodyType::Dynamic;
  const bool rough = friction_of(materials_[i]) > 0.0;
  const bool bouncy = restitution_of(materials_[i]) > 0.0;
  census.dynamic += dynamic ? 1 : 0;
  census.rough += rough ? 1 : 0;
  census.dynamic_rough += rough && dynamic ? 1 : 0;
  census.bouncy += bouncy ? 1 : 0;
  census.dynamic_bouncy += bouncy && dynamic ? 1 : 0;
  const bool polygon = b.shape() == Shape::Polygon;
  census.dynamic_polygons += dynamic && polygon ? 1 : 0;
  census.widest_dynamic_polygon = std::max(census.widest_dynamic_polygon, dynamic && polygon ? b.radius() : 0.0);
  census.spinning_disks += dynamic && !polygon && b.omega() != 0.0 ? 1 : 0;
  census.disks += polygon ? 0 : 1;
  census.turning_face_bodies += b.type() == BodyType::Kinematic && polygon && b.omega() != 0.0 ? 1 : 0;
  census.moving_kinematic_bodies += b.type() == BodyType::Kinematic && b.velocity() != Vec2{0.0, 0.0} ? 1 : 0;
  census.kinematic_bodies += b.type() == BodyType::Kinematic ? 1 : 0;
}

StepContext WorldImpl::select_effects()
{
  const WorldSettings& s = settings_;
  const BodyCensus& census = census_for_frame();
  const bool contacts_possible = census.dynamic > 0 && bodies_.size() >= 2;
  StepContext e;
  e.effects.friction = resolve(s.friction, census.rough_pair());
  // Disks only turn under friction or with a spin of their own.
  const bool turning = census.dynamic_polygons > 0 || census.spinning_disks > 0;
  e.effects.rotation = resolve(s.rotation, e.effects.friction || turning);
  e.effects.restitution = resolve(s.restitution, census.bouncy_pair());
  e.effects.position_correction = resolve(s.position_correction, contacts_possible);
  // Without gravity (or another steady load) contacts do not persist from
  // frame to frame, and last frame's impulses would only disturb new impacts.
  const bool steady_load = s.gravity.x != 0.0 || s.gravity.y != 0.0;
  e.effects.warm_starting = resolve(s.warm_starting, contacts_possible && steady_load);
  // Without gravity a slow body is drifting, not resting on anything:
  // freezing it would change the motion (and take energy from a gas).
  e.effects.sleeping = resolve(s.sleeping, steady_load && census.dynamic >= s.sleep_auto_min_bodies);
  // Time of impact is decided per substep from the bodies' speeds (world_toi.cpp).
  e.effects.time_of_impact = false;
  // The last substep's contacts become the first substep's cache (world_step.cpp).
  e.warm_available = e.effects.warm_starting && !(contacts_.empty() && sleeping_contacts_.empty()) && cache_h_ > 0.0;
  return e;
}

}  // namespace detail
}  // namespace collision2d
