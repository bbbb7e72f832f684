// Internal to the core: the per-contact rows the velocity solver iterates on,
// the coupled clusters they form, and the residual that decides convergence.
// Shared by the iterative solver and any other solver mode that works on the
// same rows and fixed targets.
#pragma once

#include <cstddef>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/vec2.h"
#include "contact_kernel.h"

namespace collision2d
{
namespace detail
{
/// One contact point: geometry, effective masses, the fixed Newton target and
/// the accumulated impulses.
struct ContactRow
{
  std::size_t contact = 0;  ///< index into the caller's contact list
  std::size_t cluster = 0;  ///< representative body of the coupled cluster
  std::size_t a = 0;
  std::size_t b = 0;
  Vec2 normal;
  Vec2 tangent;  ///< perp(normal)
  Vec2 r_a;      ///< lever arm from a's centre to the contact point
  Vec2 r_b;
  double k_n = 0.0;     ///< inverse effective mass along the normal (1/kg)
  double k_t = 0.0;     ///< inverse effective mass along the tangent (1/kg)
  double target = 0.0;  ///< post-solve normal separation speed to reach (m/s)
  double lambda_n = 0.0;  ///< accumulated normal impulse (N s), >= 0
  double lambda_t = 0.0;  ///< accumulated tangential impulse on b along tangent (N s)
  /// Coulomb coefficient of this contact's cone. The exact solver gives every
  /// row the same value; the World's exact mode gives each its materials' one.
  double mu = 0.0;
  bool sliding = false;  ///< exact solve: the contact slides (on its cone)
};

/// Rows [begin, end) of the solver's row list form one coupled cluster.
struct ClusterRange
{
  std::size_t begin = 0;
  std::size_t end = 0;
};

/// Throws std::invalid_argument naming contact `index` when it names a missing
/// body or the same body twice, or its normal, point or depth is unusable.
void validate_contact(const Contact& c, std::size_t index, std::size_t body_count);

/// Throws std::invalid_argument naming the body and field when a body's pose
/// or velocity is not finite. Body setters do not check (they run in every
/// world substep), so each ContactSolver entry point checks its input here.
void validate_bodies(const std::vector<Body>& bodies);

/// Runs `stages` (several stages that each change the bodies) as one: when a
/// stage throws, every body's pose and velocity are put back as they came in
/// and the exception goes on. Only the motion is kept aside (no outlines), in
/// one allocation per call.
template <typename Stages>
auto all_or_nothing(std::vector<Body>& bodies, Stages stages) -> decltype(stages())
{
  struct Motion
  {
    Vec2 position;
    double theta;
    Vec2 velocity;
    double omega;
  };
  std::vector<Motion> before(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
    before[i] = {bodies[i].position(), bodies[i].theta(), bodies[i].velocity(), bodies[i].omega()};
  try
  {
    return stages();
  }
  catch (...)
  {
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      bodies[i].set_position(before[i].position);
      bodies[i].set_theta(before[i].theta);
      bodies[i].set_velocity(before[i].velocity);
      bodies[i].set_omega(before[i].omega);
    }
    throw;
  }
}

/// Copies the bodies' velocities and inverse masses into `state`.
void load_velocities(const std::vector<Body>& bodies, std::vector<BodyVelocity>& state);
/// Writes the solved velocities back to the dynamic bodies; static and
/// kinematic bodies keep theirs untouched. Throws std::overflow_error naming
/// the body, and writes nothing, when a solved velocity is not finite (finite
/// input far beyond the supported ranges can overflow).
void store_velocities(const std::vector<BodyVelocity>& state, std::vector<Body>& bodies);
/// Sum of the bodies' kinetic energies (J).
double total_kinetic_energy(const std::vector<Body>& bodies);

/// Builds one row per contact whose normal effective mass is positive (a pair of
/// two non-dynamic bodies is skipped). Targets are e times the approach speed
/// measured now, before any impulse; 0 for separating or resting contacts.
/// Throws std::invalid_argument for a contact naming a missing or the same body.
void build_rows(const std::vector<Body>& bodies, const std::vector<BodyVelocity>& state,
                const std::vector<Contact>& contacts, double restitution, std::vector<ContactRow>& rows);

/// Reorders `rows` so each coupled cluster is contiguous (and, inside it, rows
/// of the same pair are adjacent) and fills `clusters`. Only dynamic bodies
/// couple: contacts that share just a static or kinematic body stay apart,
/// because that body's velocity never changes. `parent` is working storage.
void partition_clusters(const std::vector<BodyVelocity>& state, std::vector<ContactRow>& rows,
                        std::vector<ClusterRange>& clusters, std::vector<std::size_t>& parent);

/// Everything a velocity solve works on, sized once per call so the
/// iterations allocate nothing.
struct ContactProblem
{
  std::vector<BodyVelocity> state;
  std::vector<ContactRow> rows;
  std::vector<ClusterRange> clusters;
  std::vector<std::size_t> parent;  ///< union-find working storage
};

/// Loads the velocities, builds the rows with their fixed Newton targets and
/// groups them into coupled clusters: the setup both solver modes share.
void prepare_problem(const std::vector<Body>& bodies, const std::vector<Contact>& contacts, double restitution,
                     ContactProblem& problem);

/// One ContactImpulse per input contact (zero for contacts that made no row).
void store_impulses(const std::vector<ContactRow>& rows, std::size_t contact_count,
                    std::vector<ContactImpulse>& impulses);

/// Relative velocity of b with respect to a at the row's contact point.
inline Vec2 relative_velocity(const ContactRow& row, const std::vector<BodyVelocity>& state)
{
  const BodyVelocity& a = state[row.a];
  const BodyVelocity& b = state[row.b];
  return (b.v + cross(b.omega, row.r_b)) - (a.v + cross(a.omega, row.r_a));
}

/// Applies impulse p to b at the contact point and -p to a, so linear and
/// angular momentum are unchanged.
inline void apply_impulse(const ContactRow& row, Vec2 p, std::vector<BodyVelocity>& state)
{
  BodyVelocity& a = state[row.a];
  BodyVelocity& b = state[row.b];
  a.v -= a.inv_mass * p;
  a.omega -= a.inv_inertia * cross(row.r_a, p);
  b.v += b.inv_mass * p;
  b.omega += b.inv_inertia * cross(row.r_b, p);
}

/// Complementarity residual of one row at the current velocities (m/s); see
/// the definition in contact_rows.cpp.
double row_residual(const ContactRow& row, const std::vector<BodyVelocity>& state, double mu);

}  // namespace detail
}  // namespace collision2d
