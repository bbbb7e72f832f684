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
  turning += other.turning;
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
  // Frictionless contact impulses on a disk act along a line through its
  // centre, so disks only turn under friction or with a spin of their own;
  // a polygon's impulses act off its centroid.
  census.turning += dynamic && (b.shape() == Shape::Polygon || b.omega() != 0.0) ? 1 : 0;
}

StepContext WorldImpl::select_effects()
{
  const WorldSettings& s = settings_;
  const BodyCensus census = take_census();
  const bool contacts_possible = census.dynamic > 0 && bodies_.size() >= 2;
  // Pairs combine materials by min, so a pair shows a property only when
  // both bodies have it; a pair matters only when one of them is dynamic.
  const bool rough_pair = census.dynamic_rough > 0 && census.rough >= 2;
  const bool bouncy_pair = census.dynamic_bouncy > 0 && census.bouncy >= 2;
  StepContext e;
  e.effects.friction = resolve(s.friction, rough_pair);
  e.effects.rotation = resolve(s.rotation, e.effects.friction || census.turning > 0);
  e.effects.restitution = resolve(s.restitution, bouncy_pair);
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
