// ContactSolver residuals on random islands (see solver_metrics.h).
#include "solver_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "collision2d/scenes/random_scenes.h"
#include "timing.h"

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kMicrosecondsPerSecond = 1e6;

double relative_normal_speed(const std::vector<Body>& bodies, const Contact& c)
{
  return dot(bodies[c.b].velocity_at(c.point) - bodies[c.a].velocity_at(c.point), c.normal);
}

/// Inverse effective mass of the pair along `dir` at the contact point (1/kg).
double inverse_effective_mass(const std::vector<Body>& bodies, const Contact& c, Vec2 dir)
{
  const Body& a = bodies[c.a];
  const Body& b = bodies[c.b];
  const double ra = cross(c.point - a.position(), dir);
  const double rb = cross(c.point - b.position(), dir);
  return a.inv_mass() + b.inv_mass() + a.inv_inertia() * ra * ra + b.inv_inertia() * rb * rb;
}

struct Residuals
{
  double target = 0.0;
  double complementarity_max = 0.0;
  double complementarity_sum = 0.0;
  double coulomb = 0.0;
};

/// Recomputes the contract's residuals from the states before and after.
void add_residuals(const std::vector<Body>& before, const std::vector<Body>& after,
                   const std::vector<Contact>& contacts, const std::vector<ContactImpulse>& impulses, double e,
                   double mu, Residuals& r)
{
  for (std::size_t k = 0; k < contacts.size(); ++k)
  {
    const Contact& c = contacts[k];
    const double approach = -relative_normal_speed(before, c);
    const double target = approach > 0.0 ? e * approach : 0.0;
    const double gap_speed = relative_normal_speed(after, c) - target;
    const double wn = inverse_effective_mass(before, c, c.normal);
    const double wt = inverse_effective_mass(before, c, Vec2{-c.normal.y, c.normal.x});
    const double comp = std::min(std::abs(gap_speed), std::max(0.0, impulses[k].normal) * wn);
    r.target = std::max(r.target, std::max(0.0, -gap_speed));
    r.complementarity_max = std::max(r.complementarity_max, comp);
    r.complementarity_sum += comp;
    r.coulomb = std::max(r.coulomb, std::max(0.0, std::abs(impulses[k].tangent) - mu * impulses[k].normal) * wt);
  }
}

}  // namespace

SolverMetrics measure_solver(const SolverSweepPoint& point, std::size_t scenes, std::uint64_t seed)
{
  scenes::RandomSceneOptions options;
  options.max_mass_ratio = point.max_mass_ratio;
  scenes::RandomSceneGenerator generator(seed, options);
  SolverMetrics m;
  Residuals r;
  std::vector<double> us;
  std::vector<ContactImpulse> impulses;
  std::size_t converged = 0;
  for (std::size_t s = 0; s < scenes; ++s)
  {
    const scenes::RandomScene scene = generator.next();
    ContactSolver solver(scene.restitution, scene.friction, point.iterations, point.tolerance);
    solver.set_mode(point.mode);
    const std::vector<Contact> contacts = ContactSolver::detect_contacts(scene.bodies);
    std::vector<Body> bodies = scene.bodies;
    const auto start = std::chrono::steady_clock::now();
    const SolveReport report = solver.solve(bodies, contacts, &impulses);
    const auto stop = std::chrono::steady_clock::now();
    us.push_back(std::chrono::duration<double>(stop - start).count() * kMicrosecondsPerSecond);
    add_residuals(scene.bodies, bodies, contacts, impulses, scene.restitution, scene.friction, r);
    converged += report.converged ? 1 : 0;
    m.exact_fallbacks += report.exact_fallback ? 1 : 0;
    m.contacts += contacts.size();
  }
  m.scenes = scenes;
  m.us_per_solve = median(us);
  m.max_target_residual = r.target;
  m.max_complementarity = r.complementarity_max;
  m.mean_complementarity = m.contacts > 0 ? r.complementarity_sum / m.contacts : 0.0;
  m.max_coulomb_excess = r.coulomb;
  m.converged_fraction = scenes > 0 ? static_cast<double>(converged) / scenes : 0.0;
  return m;
}

}  // namespace bench
}  // namespace collision2d
