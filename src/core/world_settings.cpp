// Validation of the world's settings and materials, with messages naming the field.
#include "collision2d/world_settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace collision2d
{
namespace
{
[[noreturn]] void reject(const std::string& field, const std::string& rule, double value)
{
  std::ostringstream msg;
  msg << field << " must be " << rule << " (got " << value << ")";
  throw std::invalid_argument(msg.str());
}

}  // namespace

void validate_material(const Material& m)
{
  if (!(std::isfinite(m.restitution) && m.restitution >= 0.0 && m.restitution <= 1.0))
  {
    reject("Material.restitution", "in [0, 1]", m.restitution);
  }
  if (!(std::isfinite(m.static_friction) && m.static_friction >= 0.0))
  {
    reject("Material.static_friction", "finite and >= 0", m.static_friction);
  }
  if (!(std::isfinite(m.kinetic_friction) && m.kinetic_friction >= 0.0))
  {
    reject("Material.kinetic_friction", "finite and >= 0", m.kinetic_friction);
  }
}

void validate_world_settings(const WorldSettings& s)
{
  visit_world_settings(s, SettingCheck("WorldSettings"));
}

const std::vector<FormerSetting>& former_world_settings()
{
  // {"old_name", "new_name" or "" when retired, "why"}: files that name
  // old_name keep loading, with a warning naming new_name.
  static const std::vector<FormerSetting> table = {
      {"warm_start_factor", "",
       "it acted only with soft_step false, where any value below 1 made stacks sag or collapse; "
       "warm starts apply the cached impulses in full"},
      {"warm_start_every_substep", "",
       "it acted only with soft_step false, where turning it off made stacks collapse; every substep warm-starts"},
  };
  return table;
}

}  // namespace collision2d
