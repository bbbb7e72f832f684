// Internal to the core: ContactSolver's setup around the kernel: input
// checks, the kernel points of a contact list, the coupled islands they form,
// and loading and storing the bodies' velocities.
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
/// Rows [begin, end) of the solver's row list form one coupled island.
struct IslandRange
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

/// Builds one kernel point per contact whose normal effective mass is
/// positive (a pair of two non-dynamic bodies is skipped), with Coulomb
/// coefficient mu and the Newton target of restitution e from the velocities
/// now, before any impulse.
/// Throws std::invalid_argument for a contact naming a missing or the same body.
void build_rows(const std::vector<Body>& bodies, const std::vector<BodyVelocity>& state,
                const std::vector<Contact>& contacts, double restitution, double mu, ContactPoints& rows);

/// Reorders `rows` so each coupled island is contiguous (and, inside it, rows
/// of the same pair are adjacent) and fills `islands`. Only dynamic bodies
/// couple: contacts that share just a static or kinematic body stay apart,
/// because that body's velocity never changes. `parent` is working storage.
void partition_islands(const std::vector<BodyVelocity>& state, ContactPoints& rows,
                        std::vector<IslandRange>& islands, std::vector<std::size_t>& parent);

/// Everything a velocity solve works on, sized once per call so the
/// iterations allocate nothing.
struct ContactProblem
{
  std::vector<BodyVelocity> state;
  ContactPoints rows;
  std::vector<IslandRange> islands;
  std::vector<std::size_t> parent;  ///< union-find working storage
};

/// Loads the velocities, builds the rows with their fixed Newton targets and
/// groups them into coupled islands: the setup both solver modes share.
void prepare_problem(const std::vector<Body>& bodies, const std::vector<Contact>& contacts, double restitution,
                     double mu, ContactProblem& problem);

/// One ContactImpulse per input contact (zero for contacts that made no row).
void store_impulses(const ContactPoints& rows, std::size_t contact_count,
                    std::vector<ContactImpulse>& impulses);

}  // namespace detail
}  // namespace collision2d
