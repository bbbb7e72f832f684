// SolverMode::Exact: each island of the substep's contacts (dynamic bodies
// linked by contacts; static and kinematic bodies do not link) is solved as
// one linear complementarity problem by pivoting, with the machinery of the
// exact ContactSolver mode (exact_island_solve.h).
//
// Velocities: the world's per-contact Newton targets and Coulomb cones. Which
// friction coefficient: the LCP has one cone per contact, and the world's
// friction is a state (world_solve.cpp, coulomb()): a contact that stuck in
// the previous substep gets the static cone mu_s, one that slid gets the
// kinetic cone mu_k. That is the rule of the iterative passes, so a box on an
// incline sticks below tan(theta) = mu_s and slides at g (sin - mu_k cos) in
// both modes; one mu_s cone for all would brake a sliding box at the static
// bound, one mu_k cone would let a resting box slip between mu_k and mu_s.
// The LCP's answer sets the state for the next substep (a contact on its cone
// with a positive sliding slack slides). Exact rows carry the island's total
// impulses, so they are neither warm started nor touched by the passes; an
// island whose solve fails keeps its warm-start impulses and goes through the
// passes as in iterative mode.
//
// Positions (WorldSettings::exact_position_correction): the same island's
// penetrations beyond slop, linearised as in the penetration pass
// (world_position.cpp) with compliance on the diagonal, solved at once:
// K lambda + softness lambda >= depth - slop, lambda >= 0, complementary.
// A Gauss-Seidel position pass moves the light body of a 1e6 mass-ratio pair
// and almost never the heavy one, so without this a heavy box on a light one
// keeps the gravity sag of every substep and sinks steadily even with exact
// velocities. A static body's contacts take no compliance: the ground does
// not give, so a body a kinematic one squeezes against it keeps its overlap
// with the kinematic body (with compliance on both, the two shared it and a
// press at 1 m/s put the body through the ground).
#include <algorithm>
#include <cmath>
#include <vector>

#include "collision2d/exact_solver.h"
#include "world_impl.h"
#include "contact_rows.h"
#include "exact_island_solve.h"
#include "grouped_friction_lcp.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// An island's solve may raise its contacts' speeds (targets included) by
/// at most this factor. A body squeezed between a kinematic body and a
/// static one makes the LCP nearly singular; pivoting then answers with
/// huge impulses that cancel each other, within a residual scaled by those
/// impulses, and their friction flung a 114 kg box at 6.4e4 m/s.
constexpr double kMaxSpeedGain = 10.0;

/// A solve whose residual is within this fraction of its speeds, but not
/// round-off (kTrustedResidual), seeds the passes instead (m/s per m/s).
constexpr double kSeedResidual = 1e-2;

/// One substep's islands in the exact solver's terms; built per call (one
/// allocation per array, none per contact or pivot).
struct ExactIslands
{
  std::vector<detail::BodyVelocity> state;
  detail::ContactPoints rows;
  std::vector<detail::IslandRange> islands;
  std::vector<std::size_t> parent;
  detail::IslandLcp lcp;
  detail::GroupedLcp grouped;
};

/// Copies of the active points, partitioned into islands. A body's inertia
/// comes from its points: a frictionless disk's points drop it
/// (prepare_points), and so must its LCP; every copy then sees the island's
/// one inertia per body. Without friction (positions) the copies carry no cone.
void build_islands(const std::vector<detail::BodyVelocity>& velocity, const detail::ContactPoints& points,
                   bool friction, const std::vector<double>* targets, ExactIslands& out)
{
  out.state.resize(velocity.size());
  for (std::size_t i = 0; i < velocity.size(); ++i)
  {
    out.state[i] = detail::body_velocity(velocity[i].v, velocity[i].omega, velocity[i].inv_mass, 0.0);
  }
  for (const detail::ContactPoint& p : points)
  {
    if (p.active)
    {
      out.state[p.a].inv_inertia = std::max(out.state[p.a].inv_inertia, p.inv_inertia_a);
      out.state[p.b].inv_inertia = std::max(out.state[p.b].inv_inertia, p.inv_inertia_b);
    }
  }
  out.rows.clear();
  out.rows.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (!points[k].active)
    {
      continue;
    }
    detail::ContactPoint copy = points[k];
    copy.contact = k;
    copy.target = targets != nullptr ? (*targets)[k] : copy.target;
    copy.inv_inertia_a = out.state[copy.a].inv_inertia;
    copy.inv_inertia_b = out.state[copy.b].inv_inertia;
    if (!friction)
    {
      copy.mu_s = 0.0;
      copy.mu_k = 0.0;
    }
    out.rows.push_back(copy);
  }
  detail::partition_islands(out.state, out.rows, out.islands, out.parent);
  out.lcp.local_body.assign(velocity.size(), -1);
}

/// The island's rows without friction: an LCP of normal impulses only.
void drop_cones(detail::ContactPoints& rows, detail::IslandRange island)
{
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    rows[r].mu_s = 0.0;
    rows[r].mu_k = 0.0;
  }
}

/// The velocities of the island's bodies from `from` into `to`; other
/// bodies' are left as they are (a free body may have had its next gravity
/// kick since `from` was taken).
void set_island_velocities(const detail::ContactPoints& rows, detail::IslandRange island,
                           const std::vector<detail::BodyVelocity>& from, std::vector<detail::BodyVelocity>& to)
{
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    for (std::size_t i : {rows[r].a, rows[r].b})
    {
      to[i].v = from[i].v;
      to[i].omega = from[i].omega;
    }
  }
}

/// Whether a kinematic body that moves this frame touches the island.
bool kinematic_moves_island(const WorldImpl& world, const detail::ContactPoints& rows, detail::IslandRange island)
{
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    for (std::size_t i : {rows[r].a, rows[r].b})
    {
      if (world.moving_kinematic(i))
      {
        return true;
      }
    }
  }
  return false;
}

/// Pivots the island's velocity LCP and stores the impulses in its rows;
/// false when pivoting failed or the island is too large. With friction the
/// grouped form is used (grouped_friction_lcp.h).
bool pivot_velocity_island(ExactIslands& islands, detail::IslandRange island)
{
  int pivots = 0;
  if (!detail::island_has_friction(islands.rows, island))
  {
    return detail::solve_island(islands.rows, island, islands.state, islands.lcp, pivots);
  }
  if (detail::grouped_unknowns(islands.rows, island) > kMaxExactUnknowns)
  {
    return false;
  }
  detail::assemble_grouped_lcp(islands.rows, island, islands.state, islands.grouped);
  const LcpResult result = detail::pivot_with_retry(islands.grouped.M, islands.grouped.q, pivots);
  if (result.solved())
  {
    detail::store_grouped_impulses(result.z, islands.grouped, island, islands.rows);
  }
  return result.solved();
}

double island_residual(const ExactIslands& islands, detail::IslandRange island)
{
  return detail::island_has_friction(islands.rows, island)
             ? detail::grouped_residual(islands.rows, islands.grouped, islands.state)
             : detail::island_residual(islands.rows, island, islands.state);
}

/// How an island's velocity solve ended.
enum class IslandSolve
{
  Exact,   ///< impulses in the rows, velocities in the island's state
  Seed,    ///< not round-off exact, but near: its impulses start the passes
  Failed,  ///< nothing to keep
};

/// Velocity solve of one island: impulses in the rows and velocities in
/// `state`, or the island's velocities set to `velocity` (those the passes
/// go on from). The residual recomputed from the velocities must be round-off
/// of the speeds involved, as in solve_exact.
IslandSolve solve_velocity_island(const std::vector<detail::BodyVelocity>& velocity, ExactIslands& islands,
                                  detail::IslandRange island)
{
  if (!pivot_velocity_island(islands, island))
  {
    set_island_velocities(islands.rows, island, velocity, islands.state);  // a relax solving again began elsewhere
    return IslandSolve::Failed;
  }
  const double speed_before = detail::contact_speed_scale(islands.rows, island, islands.state);
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    const detail::ContactPoint& row = islands.rows[r];
    detail::apply_impulse(row, row.lambda_n * row.normal + row.lambda_t * row.tangent(), islands.state);
  }
  const double speed_after = detail::contact_speed_scale(islands.rows, island, islands.state);
  const double scale = std::max({speed_before, speed_after, detail::impulse_speed_scale(islands.rows, island)});
  const bool calm = speed_after <= kMaxSpeedGain * speed_before;
  const double residual = island_residual(islands, island);
  if (calm && residual <= kTrustedResidual * scale)
  {
    return IslandSolve::Exact;
  }
  set_island_velocities(islands.rows, island, velocity, islands.state);
  return calm && residual <= kSeedResidual * scale ? IslandSolve::Seed : IslandSolve::Failed;
}

}  // namespace

void WorldImpl::solve_exact_islands(StepReport& report, bool seed, const std::vector<double>* targets, bool relax)
{
  // The relax's LCP only holds what the first pass left: with still
  // neighbours, no speed may grow (the answer is the nearest allowed
  // velocity, and rest is allowed), so it adds normal impulses only; cones
  // on those would hold what the relax pushes, not the substep's load. A
  // moving kinematic body does work: a disk it jams into a wedge found the
  // frictionless way out sideways (86.6 m/s under a bar closing at 10 m/s),
  // so such an island solves its impulses again, cones and all, from the
  // velocities the first pass began with.
  ExactIslands islands;
  build_islands(velocity_, points_, true, targets, islands);
  for (const detail::IslandRange& island : islands.islands)
  {
    const bool again = relax && kinematic_moves_island(*this, islands.rows, island);
    if (relax && !again)
    {
      drop_cones(islands.rows, island);
    }
    if (again)
    {
      set_island_velocities(islands.rows, island, solve_start_, islands.state);
    }
    const bool add = relax && !again;
    const IslandSolve solve = solve_velocity_island(velocity_, islands, island);
    const bool solved = solve == IslandSolve::Exact;
    ++(solved ? report.exact_islands : report.exact_fallbacks);
    // A near answer replaces the warm start the passes begin from (a light
    // body squeezed by a heavy one is where pivoting loses digits, and
    // where a pass from the last substep's impulses goes furthest wrong).
    const bool seeds = solve == IslandSolve::Seed && seed && !relax;
    for (std::size_t r = island.begin; (solved || seeds) && r < island.end; ++r)
    {
      const detail::ContactPoint& row = islands.rows[r];
      ContactPoint& w = points_[row.contact];
      w.exact = solved;
      w.lambda_n = add ? w.lambda_n + row.lambda_n : row.lambda_n;
      w.lambda_t = add ? w.lambda_t : row.lambda_t;
      w.sliding = add ? w.sliding : row.sliding;
    }
    set_island_velocities(islands.rows, island, islands.state, velocity_);
  }
}

void WorldImpl::solve_position_islands(double softness, StepReport& report)
{
  ExactIslands islands;
  build_islands(velocity_, points_, false, nullptr, islands);
  detail::IslandLcp& lcp = islands.lcp;
  for (const detail::IslandRange& island : islands.islands)
  {
    if (detail::island_unknowns(islands.rows, island) > kMaxExactUnknowns)
    {
      ++report.exact_fallbacks;
      continue;
    }
    // The frictionless velocity LCP's matrix is the position problem's too;
    // only the right-hand side (depths left) and the compliance differ.
    detail::assemble_island_lcp(islands.rows, island, islands.state, lcp);
    for (std::size_t r = island.begin; r < island.end; ++r)
    {
      const Eigen::Index i = static_cast<Eigen::Index>(r - island.begin);
      const double scale = 1.0 / std::sqrt(islands.rows[r].k_n);
      const ContactPoint& p = points_[islands.rows[r].contact];
      lcp.q(i) = -(current_depth(p) - settings_.slop) * scale;
      if (!p.against_static)
      {
        lcp.M(i, i) += softness * scale * scale;
      }
    }
    int pivots = 0;
    const LcpResult result = detail::pivot_with_retry(lcp.M, lcp.q, pivots);
    ++(result.solved() ? report.exact_islands : report.exact_fallbacks);
    for (std::size_t r = island.begin; result.solved() && r < island.end; ++r)
    {
      const Eigen::Index i = static_cast<Eigen::Index>(r - island.begin);
      ContactPoint& w = points_[islands.rows[r].contact];
      const double lambda = result.z(i) / std::sqrt(islands.rows[r].k_n);
      displace(w.a, -lambda, w.normal, w.r_a, w.inv_mass_a, w.inv_inertia_a);
      displace(w.b, lambda, w.normal, w.r_b, w.inv_mass_b, w.inv_inertia_b);
      w.position_solved = true;
    }
  }
}

}  // namespace detail
}  // namespace collision2d
