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

void require_positive(const char* field, double value)
{
  if (!(std::isfinite(value) && value > 0.0))
  {
    reject(std::string("WorldSettings.") + field, "finite and > 0", value);
  }
}

void require_non_negative(const char* field, double value)
{
  if (!(std::isfinite(value) && value >= 0.0))
  {
    reject(std::string("WorldSettings.") + field, "finite and >= 0", value);
  }
}

void require_at_least_one(const char* field, int value)
{
  if (value < 1)
  {
    reject(std::string("WorldSettings.") + field, ">= 1", value);
  }
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
  if (!is_finite(s.gravity))
  {
    reject("WorldSettings.gravity", "finite", std::isfinite(s.gravity.x) ? s.gravity.y : s.gravity.x);
  }
  require_positive("dt", s.dt);
  require_at_least_one("substeps", s.substeps);
  require_at_least_one("velocity_iterations", s.velocity_iterations);
  require_at_least_one("position_iterations", s.position_iterations);
  require_non_negative("slop", s.slop);
  require_non_negative("compliance", s.compliance);
  require_non_negative("restitution_threshold", s.restitution_threshold);
  if (!(std::isfinite(s.warm_start_factor) && s.warm_start_factor >= 0.0 && s.warm_start_factor <= 1.0))
  {
    reject("WorldSettings.warm_start_factor", "in [0, 1]", s.warm_start_factor);
  }
  require_positive("toi_displacement_fraction", s.toi_displacement_fraction);
  require_non_negative("sleep_linear_speed", s.sleep_linear_speed);
  require_non_negative("sleep_angular_speed", s.sleep_angular_speed);
  require_non_negative("sleep_time", s.sleep_time);
  if (s.solver_mode != SolverMode::Iterative && s.solver_mode != SolverMode::Exact)
  {
    reject("WorldSettings.solver_mode", "Iterative or Exact", static_cast<double>(s.solver_mode));
  }
}

}  // namespace collision2d
