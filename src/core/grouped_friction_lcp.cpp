#include "grouped_friction_lcp.h"

#include <algorithm>
#include <cmath>

namespace collision2d
{
namespace detail
{
namespace
{
/// A group slides only when its net friction |t+ - t-| reaches the cone to
/// this relative precision. At a 1e6 mass ratio pivoting can return a
/// sticking pair with t+ and t- both near half the cone and a sliding slack
/// positive by round-off; projecting that onto the cone would throw the pair
/// sideways at the full friction bound.
constexpr double kConeReached = 1.0 - 1e-9;

/// Unknown indices of the layout described at GroupedLcp.
struct Layout
{
  Eigen::Index points;
  Eigen::Index groups;
  Eigen::Index t_plus(Eigen::Index g) const { return points + g; }
  Eigen::Index t_minus(Eigen::Index g) const { return points + groups + g; }
  Eigen::Index beta(Eigen::Index g) const { return points + 2 * groups + g; }
  Eigen::Index size() const { return points + 3 * groups; }
};

Layout layout_of(IslandRange island, const GroupedLcp& lcp)
{
  return Layout{static_cast<Eigen::Index>(island.end - island.begin), static_cast<Eigen::Index>(lcp.groups.size())};
}

void find_groups(const ContactPoints& rows, IslandRange island, GroupedLcp& lcp)
{
  lcp.groups.clear();
  for (std::size_t r = island.begin; r < island.end;)
  {
    FrictionGroup g;
    g.first = r;
    g.count = r + 1 < island.end && rows[r + 1].a == rows[r].a && rows[r + 1].b == rows[r].b ? 2 : 1;
    g.r_a = g.count == 2 ? 0.5 * (rows[r].r_a + rows[r + 1].r_a) : rows[r].r_a;
    g.r_b = g.count == 2 ? 0.5 * (rows[r].r_b + rows[r + 1].r_b) : rows[r].r_b;
    lcp.groups.push_back(g);
    r += g.count;
  }
}

void assemble_delassus(const ContactPoints& rows, IslandRange island,
                       const std::vector<BodyVelocity>& state, GroupedLcp& lcp, Layout layout)
{
  begin_jacobian(rows, island, state, layout.points + layout.groups, lcp);
  for (Eigen::Index i = 0; i < layout.points; ++i)
  {
    const ContactPoint& row = rows[island.begin + i];
    add_jacobian_entry(lcp, i, row.b, 1.0, row.normal, row.r_b);
    add_jacobian_entry(lcp, i, row.a, -1.0, row.normal, row.r_a);
  }
  for (Eigen::Index g = 0; g < layout.groups; ++g)
  {
    const FrictionGroup& group = lcp.groups[g];
    const ContactPoint& row = rows[group.first];
    add_jacobian_entry(lcp, layout.points + g, row.b, 1.0, row.tangent(), group.r_b);
    add_jacobian_entry(lcp, layout.points + g, row.a, -1.0, row.tangent(), group.r_a);
  }
  finish_jacobian(rows, island, lcp);
}

/// Unscaled M and q; beta couples with +1 into the tangent rows and the cone
/// row reads mu sum(lambda_n) - lambda_t+ - lambda_t-.
void fill_unscaled(const ContactPoints& rows, IslandRange island, const std::vector<BodyVelocity>& state,
                   GroupedLcp& lcp, Layout layout)
{
  const Eigen::Index points = layout.points;
  const Eigen::Index groups = layout.groups;
  const Eigen::Index delassus_size = points + groups;
  lcp.M.setZero(layout.size(), layout.size());
  lcp.q.setZero(layout.size());
  // Columns of the impulses acting on velocities: normals, then t+ (as +t) and t- (as -t).
  lcp.M.block(0, 0, delassus_size, delassus_size) = lcp.delassus;
  lcp.M.block(0, points + groups, delassus_size, groups) = -lcp.delassus.block(0, points, delassus_size, groups);
  lcp.M.block(points + groups, 0, groups, layout.size() - groups) =
      -lcp.M.block(points, 0, groups, layout.size() - groups);
  for (Eigen::Index i = 0; i < points; ++i)
  {
    const ContactPoint& row = rows[island.begin + i];
    lcp.q(i) = dot(relative_velocity(row, state), row.normal) - row.target;
  }
  for (Eigen::Index g = 0; g < groups; ++g)
  {
    const FrictionGroup& group = lcp.groups[g];
    const ContactPoint& row = rows[group.first];
    const double vt = dot(relative_velocity_at(row, group.r_a, group.r_b, state), row.tangent());
    lcp.q(layout.t_plus(g)) = vt;
    lcp.q(layout.t_minus(g)) = -vt;
    lcp.M(layout.t_plus(g), layout.beta(g)) = 1.0;
    lcp.M(layout.t_minus(g), layout.beta(g)) = 1.0;
    lcp.M(layout.beta(g), layout.t_plus(g)) = -1.0;
    lcp.M(layout.beta(g), layout.t_minus(g)) = -1.0;
    for (std::size_t k = 0; k < group.count; ++k)
      lcp.M(layout.beta(g), static_cast<Eigen::Index>(group.first + k - island.begin)) = cone(row);
  }
}

}  // namespace

std::size_t grouped_unknowns(const ContactPoints& rows, IslandRange island)
{
  constexpr std::size_t kUnknownsPerGroup = 3;  // lambda_t+, lambda_t-, beta
  std::size_t unknowns = 0;
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    const bool new_pair = r == island.begin || rows[r - 1].a != rows[r].a || rows[r - 1].b != rows[r].b;
    unknowns += 1 + (new_pair ? kUnknownsPerGroup : 0);
  }
  return unknowns;
}

void assemble_grouped_lcp(const ContactPoints& rows, IslandRange island,
                          const std::vector<BodyVelocity>& state, GroupedLcp& lcp)
{
  find_groups(rows, island, lcp);
  const Layout layout = layout_of(island, lcp);
  assemble_delassus(rows, island, state, lcp, layout);
  fill_unscaled(rows, island, state, lcp, layout);
  lcp.scale.resize(layout.size());
  for (Eigen::Index i = 0; i < layout.points + layout.groups; ++i)
    lcp.scale(i) = 1.0 / std::sqrt(lcp.delassus(i, i));
  lcp.scale.segment(layout.t_minus(0), layout.groups) = lcp.scale.segment(layout.t_plus(0), layout.groups);
  lcp.scale.segment(layout.beta(0), layout.groups) = lcp.scale.segment(layout.t_plus(0), layout.groups).cwiseInverse();
  lcp.M = lcp.scale.asDiagonal() * lcp.M * lcp.scale.asDiagonal();
  lcp.q = lcp.scale.cwiseProduct(lcp.q);
}

void store_grouped_impulses(const Eigen::VectorXd& z, const GroupedLcp& lcp, IslandRange island,
                            ContactPoints& rows)
{
  const Layout layout = layout_of(island, lcp);
  for (Eigen::Index i = 0; i < layout.points; ++i)
    rows[island.begin + i].lambda_n = z(i) * lcp.scale(i);
  for (Eigen::Index g = 0; g < layout.groups; ++g)
  {
    const FrictionGroup& group = lcp.groups[g];
    double normal_sum = 0.0;
    for (std::size_t k = 0; k < group.count; ++k)
      normal_sum += rows[group.first + k].lambda_n;
    const double t_plus = z(layout.t_plus(g)) * lcp.scale(layout.t_plus(g));
    const double t_minus = z(layout.t_minus(g)) * lcp.scale(layout.t_minus(g));
    const double bound = cone(rows[group.first]) * normal_sum;
    const bool sliding = z(layout.beta(g)) > 0.0 && std::abs(t_plus - t_minus) >= kConeReached * bound;
    // On the cone exactly when sliding (see store_island_impulses).
    const double total =
        sliding ? (t_plus >= t_minus ? 1.0 : -1.0) * bound : t_plus - t_minus;
    for (std::size_t k = 0; k < group.count; ++k)
    {
      ContactPoint& row = rows[group.first + k];
      const double share = normal_sum > 0.0 ? row.lambda_n / normal_sum : 1.0 / group.count;
      row.lambda_t = share * total;
      row.sliding = sliding;
    }
  }
}

double grouped_residual(const ContactPoints& rows, const GroupedLcp& lcp,
                        const std::vector<BodyVelocity>& state)
{
  double residual = 0.0;
  for (const FrictionGroup& group : lcp.groups)
  {
    double normal_sum = 0.0;
    double tangent_sum = 0.0;
    for (std::size_t k = 0; k < group.count; ++k)
    {
      const ContactPoint& row = rows[group.first + k];
      residual = std::max(residual, normal_residual(row, state));
      normal_sum += row.lambda_n;
      tangent_sum += row.lambda_t;
    }
    const ContactPoint& row = rows[group.first];
    const double vt = dot(relative_velocity_at(row, group.r_a, group.r_b, state), row.tangent());
    const double bound = cone(row) * normal_sum;
    const double magnitude = std::abs(tangent_sum);
    // The split into shares rounds, so the sliding flag (not |sum| == bound)
    // says which side of the cone the group is on.
    double friction = 0.0;
    if (!row.sliding)
      friction = std::abs(vt) + std::max(0.0, magnitude - bound) * row.k_t;  // sticks, inside the cone
    else
      friction = std::max(0.0, tangent_sum > 0.0 ? vt : (tangent_sum < 0.0 ? -vt : 0.0)) +
                 std::abs(magnitude - bound) * row.k_t;  // slides against its impulse, on the cone
    residual = std::max(residual, friction);
  }
  return residual;
}

}  // namespace detail
}  // namespace collision2d
