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

bool WorldImpl::any_pair_with(double (*property)(const Material&)) const
{
  // Pairs combine by min, so a pair shows the property only when both bodies
  // have it; a pair matters only when at least one of them is dynamic.
  std::size_t with_property = 0;
  bool dynamic_with_property = false;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (property(materials_[i]) > 0.0)
    {
      ++with_property;
      dynamic_with_property = dynamic_with_property || bodies_[i].type() == BodyType::Dynamic;
    }
  }
  return dynamic_with_property && with_property >= 2;
}

bool WorldImpl::needs_rotation(bool friction) const
{
  // Frictionless contact impulses on a disk act along a line through its
  // centre, so disks only turn under friction or with a spin of their own;
  // a polygon's impulses act off its centroid.
  if (friction)
  {
    return true;
  }
  for (const Body& b : bodies_)
  {
    if (b.type() == BodyType::Dynamic && (b.shape() == Shape::Polygon || b.omega() != 0.0))
    {
      return true;
    }
  }
  return false;
}

bool WorldImpl::sleeping_wanted() const
{
  // Without gravity a slow body is drifting, not resting on anything:
  // freezing it would change the motion (and take energy from a gas).
  if (settings_.gravity.x == 0.0 && settings_.gravity.y == 0.0)
  {
    return false;
  }
  std::size_t dynamic = 0;
  for (const Body& b : bodies_)
  {
    dynamic += b.type() == BodyType::Dynamic ? 1 : 0;
  }
  return dynamic >= settings_.sleep_auto_min_bodies;
}

StepContext WorldImpl::select_effects() const
{
  const WorldSettings& s = settings_;
  bool dynamic = false;
  for (const Body& b : bodies_)
  {
    dynamic = dynamic || b.type() == BodyType::Dynamic;
  }
  const bool contacts_possible = dynamic && bodies_.size() >= 2;
  StepContext e;
  e.effects.friction = resolve(s.friction, any_pair_with(friction_of));
  e.effects.rotation = resolve(s.rotation, needs_rotation(e.effects.friction));
  e.effects.restitution = resolve(s.restitution, any_pair_with(restitution_of));
  e.effects.position_correction = resolve(s.position_correction, contacts_possible);
  // Without gravity (or another steady load) contacts do not persist from
  // frame to frame, and last frame's impulses would only disturb new impacts.
  const bool steady_load = s.gravity.x != 0.0 || s.gravity.y != 0.0;
  e.effects.warm_starting = resolve(s.warm_starting, contacts_possible && steady_load);
  e.effects.sleeping = resolve(s.sleeping, sleeping_wanted());
  // Time of impact is decided per substep from the bodies' speeds (world_toi.cpp).
  e.effects.time_of_impact = false;
  // The last substep's contacts become the first substep's cache (world_step.cpp).
  e.warm_available = e.effects.warm_starting && !contacts_.empty() && cache_h_ > 0.0;
  return e;
}

}  // namespace detail
}  // namespace collision2d
