#include "contact_rows.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision2d
{
namespace detail
{
namespace
{
// Detection produces unit normals; a hand-made contact far from unit length
// would silently scale its impulses, so it is rejected.
constexpr double kUnitNormalTolerance = 1e-6;

bool is_dynamic(const BodyVelocity& body) { return body.inv_mass > 0.0; }

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];  // path halving keeps later finds short
    i = parent[i];
  }
  return i;
}

void unite(std::vector<std::size_t>& parent, std::size_t i, std::size_t j)
{
  const std::size_t ri = find_root(parent, i);
  const std::size_t rj = find_root(parent, j);
  // The smaller index becomes the root so the result does not depend on order.
  if (ri < rj)
    parent[rj] = ri;
  else if (rj < ri)
    parent[ri] = rj;
}

/// Inverse effective mass of an impulse along `dir` at lever arms r_a, r_b.
double inverse_effective_mass(const BodyVelocity& a, const BodyVelocity& b, Vec2 r_a, Vec2 r_b, Vec2 dir)
{
  const double ra_dir = cross(r_a, dir);
  const double rb_dir = cross(r_b, dir);
  return a.inv_mass + b.inv_mass + a.inv_inertia * ra_dir * ra_dir + b.inv_inertia * rb_dir * rb_dir;
}
}  // namespace

void validate_contact(const Contact& c, std::size_t index, std::size_t body_count)
{
  // Messages are built only on failure, so valid contacts cost no allocation.
  if (c.a >= body_count || c.b >= body_count || c.a == c.b)
    throw std::invalid_argument("contact " + std::to_string(index) + " names bodies " + std::to_string(c.a) +
                                " and " + std::to_string(c.b) + " of " + std::to_string(body_count));
  if (!is_finite(c.normal) || !(std::abs(length_sq(c.normal) - 1.0) <= kUnitNormalTolerance))
    throw std::invalid_argument("contact " + std::to_string(index) + ": normal is not a finite unit vector");
  if (!is_finite(c.point) || !std::isfinite(c.penetration))
    throw std::invalid_argument("contact " + std::to_string(index) + ": point or penetration is not finite");
}

void validate_bodies(const std::vector<Body>& bodies)
{
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const char* field = non_finite_state_field(bodies[i]);
    if (field != nullptr)
      throw std::invalid_argument("body " + std::to_string(i) + ": " + field + " is not finite");
  }
}

void load_velocities(const std::vector<Body>& bodies, std::vector<BodyVelocity>& state)
{
  state.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const Body& body = bodies[i];
    state[i] = {body.velocity(), body.omega(), body.inv_mass(), body.inv_inertia()};
  }
}

void store_velocities(const std::vector<BodyVelocity>& state, std::vector<Body>& bodies)
{
  // Checked before anything is written, so an overflow leaves the bodies as
  // they came in.
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    if (state[i].inv_mass > 0.0 && !(is_finite(state[i].v) && std::isfinite(state[i].omega)))
      throw std::overflow_error("body " + std::to_string(i) +
                                ": the solve overflowed to a non-finite velocity (the input's sizes, speeds or "
                                "masses lie beyond what double precision can resolve)");
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    if (state[i].inv_mass <= 0.0)
      continue;
    bodies[i].set_velocity(state[i].v);
    bodies[i].set_omega(state[i].omega);
  }
}

double total_kinetic_energy(const std::vector<Body>& bodies)
{
  double energy = 0.0;
  for (const Body& body : bodies)
    energy += body.kinetic_energy();
  return energy;
}

void prepare_problem(const std::vector<Body>& bodies, const std::vector<Contact>& contacts, double restitution,
                     ContactProblem& problem)
{
  load_velocities(bodies, problem.state);
  build_rows(bodies, problem.state, contacts, restitution, problem.rows);
  partition_clusters(problem.state, problem.rows, problem.clusters, problem.parent);
}

void store_impulses(const std::vector<ContactRow>& rows, std::size_t contact_count,
                    std::vector<ContactImpulse>& impulses)
{
  impulses.assign(contact_count, ContactImpulse{});
  for (const ContactRow& row : rows)
    impulses[row.contact] = {row.lambda_n, row.lambda_t};
}

void build_rows(const std::vector<Body>& bodies, const std::vector<BodyVelocity>& state,
                const std::vector<Contact>& contacts, double restitution, std::vector<ContactRow>& rows)
{
  rows.clear();
  rows.reserve(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const Contact& c = contacts[i];
    validate_contact(c, i, bodies.size());
    ContactRow row;
    row.contact = i;
    row.a = c.a;
    row.b = c.b;
    row.normal = c.normal;
    row.tangent = perp(c.normal);
    row.r_a = c.point - bodies[c.a].position();
    row.r_b = c.point - bodies[c.b].position();
    row.k_n = inverse_effective_mass(state[c.a], state[c.b], row.r_a, row.r_b, row.normal);
    if (!(row.k_n > 0.0))
      continue;  // neither body can move: nothing to solve
    row.k_t = inverse_effective_mass(state[c.a], state[c.b], row.r_a, row.r_b, row.tangent);
    // Measured once, before any impulse: later impulses never move the target.
    const double approach = dot(relative_velocity(row, state), row.normal);
    row.target = approach < 0.0 ? -restitution * approach : 0.0;
    rows.push_back(row);
  }
}

void partition_clusters(const std::vector<BodyVelocity>& state, std::vector<ContactRow>& rows,
                        std::vector<ClusterRange>& clusters, std::vector<std::size_t>& parent)
{
  parent.resize(state.size());
  for (std::size_t i = 0; i < parent.size(); ++i)
    parent[i] = i;
  for (const ContactRow& row : rows)
    if (is_dynamic(state[row.a]) && is_dynamic(state[row.b]))
      unite(parent, row.a, row.b);
  for (ContactRow& row : rows)
    row.cluster = find_root(parent, is_dynamic(state[row.a]) ? row.a : row.b);

  // Contact index last makes the order total, so the solve is deterministic.
  std::sort(rows.begin(), rows.end(), [](const ContactRow& l, const ContactRow& r) {
    if (l.cluster != r.cluster)
      return l.cluster < r.cluster;
    if (l.a != r.a)
      return l.a < r.a;
    if (l.b != r.b)
      return l.b < r.b;
    return l.contact < r.contact;
  });

  clusters.clear();
  clusters.reserve(rows.size());
  for (std::size_t begin = 0; begin < rows.size();)
  {
    std::size_t end = begin + 1;
    while (end < rows.size() && rows[end].cluster == rows[begin].cluster)
      ++end;
    clusters.push_back({begin, end});
    begin = end;
  }
}

// Residual of one row (m/s), zero exactly at a solution of the contact problem
// with fixed targets:
//  - normal: with impulse (lambda_n > 0) the contact must reach its target,
//    |vn - target|; without impulse it must not fall short of it,
//    max(0, target - vn).
//  - friction (mu > 0 only):
//    * lambda_n == 0: no friction may act; |lambda_t| * k_t is the velocity
//      change the stray impulse causes;
//    * strictly inside the cone (|lambda_t| < mu lambda_n): the contact sticks,
//      |vt|;
//    * on the cone: it must slide against the impulse, max(0, vt sign(lambda_t)),
//      plus (|lambda_t| - mu lambda_n) k_t for any excursion outside the cone.
// The row's residual is the larger of the two; a cluster's is the largest row's.
double row_residual(const ContactRow& row, const std::vector<BodyVelocity>& state, double mu)
{
  const Vec2 dv = relative_velocity(row, state);
  const double vn = dot(dv, row.normal);
  const double normal = row.lambda_n > 0.0 ? std::abs(vn - row.target) : std::max(0.0, row.target - vn);
  if (mu <= 0.0)
    return normal;

  const double friction_bound = mu * row.lambda_n;
  const double magnitude = std::abs(row.lambda_t);
  double friction = 0.0;
  if (row.lambda_n <= 0.0)
  {
    friction = magnitude * row.k_t;
  }
  else if (magnitude < friction_bound)
  {
    friction = std::abs(dot(dv, row.tangent));
  }
  else
  {
    const double vt = dot(dv, row.tangent);
    const double along_impulse = row.lambda_t > 0.0 ? vt : (row.lambda_t < 0.0 ? -vt : 0.0);
    friction = std::max(0.0, along_impulse) + (magnitude - friction_bound) * row.k_t;
  }
  return std::max(normal, friction);
}

}  // namespace detail
}  // namespace collision2d
