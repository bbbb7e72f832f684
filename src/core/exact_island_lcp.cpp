#include "exact_island_lcp.h"

#include <cmath>

namespace collision2d
{
namespace detail
{
namespace
{
/// G = J W J^T over the island's normal and tangent directions.
void assemble_delassus(const ContactPoints& rows, IslandRange island,
                       const std::vector<BodyVelocity>& state, IslandLcp& lcp)
{
  const Eigen::Index contacts = static_cast<Eigen::Index>(island.end - island.begin);
  begin_jacobian(rows, island, state, 2 * contacts, lcp);
  for (Eigen::Index i = 0; i < contacts; ++i)
  {
    const ContactPoint& row = rows[island.begin + i];
    add_jacobian_entry(lcp, 2 * i, row.b, 1.0, row.normal, row.r_b);
    add_jacobian_entry(lcp, 2 * i, row.a, -1.0, row.normal, row.r_a);
    add_jacobian_entry(lcp, 2 * i + 1, row.b, 1.0, row.tangent(), row.r_b);
    add_jacobian_entry(lcp, 2 * i + 1, row.a, -1.0, row.tangent(), row.r_a);
  }
  finish_jacobian(rows, island, lcp);
}

void assemble_frictionless(const ContactPoints& rows, IslandRange island,
                           const std::vector<BodyVelocity>& state, IslandLcp& lcp)
{
  const Eigen::Index m = static_cast<Eigen::Index>(island.end - island.begin);
  lcp.M.resize(m, m);
  lcp.q.resize(m);
  for (Eigen::Index i = 0; i < m; ++i)
  {
    const ContactPoint& row = rows[island.begin + i];
    const double s_i = 1.0 / std::sqrt(row.k_n);
    for (Eigen::Index j = 0; j < m; ++j)
      lcp.M(i, j) = lcp.delassus(2 * i, 2 * j) * s_i / std::sqrt(rows[island.begin + j].k_n);
    lcp.q(i) = (dot(relative_velocity(row, state), row.normal) - row.target) * s_i;
  }
}

void assemble_frictional(const ContactPoints& rows, IslandRange island,
                         const std::vector<BodyVelocity>& state, IslandLcp& lcp)
{
  const Eigen::Index m = static_cast<Eigen::Index>(island.end - island.begin);
  const Eigen::Index k = kFrictionalUnknowns;
  lcp.M.setZero(k * m, k * m);
  lcp.q.resize(k * m);
  for (Eigen::Index i = 0; i < m; ++i)
  {
    const ContactPoint& row = rows[island.begin + i];
    const double s_i = 1.0 / std::sqrt(row.k_n);
    const Eigen::Index n_i = k * i;  // then t+ at n_i + 1, t- at n_i + 2, beta at n_i + 3
    for (Eigen::Index j = 0; j < m; ++j)
    {
      const double scale = s_i / std::sqrt(rows[island.begin + j].k_n);
      const double g_nn = lcp.delassus(2 * i, 2 * j) * scale;
      const double g_nt = lcp.delassus(2 * i, 2 * j + 1) * scale;
      const double g_tn = lcp.delassus(2 * i + 1, 2 * j) * scale;
      const double g_tt = lcp.delassus(2 * i + 1, 2 * j + 1) * scale;
      const Eigen::Index n_j = k * j;
      // Columns n, t+, t- of contact j act as +n, +t, -t impulses.
      lcp.M.block<3, 3>(n_i, n_j) << g_nn, g_nt, -g_nt,  //
          g_tn, g_tt, -g_tt,                              //
          -g_tn, -g_tt, g_tt;
    }
    // beta + vt >= 0 and beta - vt >= 0; mu lambda_n - lambda_t+ - lambda_t- >= 0.
    lcp.M(n_i + 1, n_i + 3) = 1.0;
    lcp.M(n_i + 2, n_i + 3) = 1.0;
    lcp.M(n_i + 3, n_i) = cone(row);
    lcp.M(n_i + 3, n_i + 1) = -1.0;
    lcp.M(n_i + 3, n_i + 2) = -1.0;

    const Vec2 dv = relative_velocity(row, state);
    const double vt = dot(dv, row.tangent());
    lcp.q(n_i) = (dot(dv, row.normal) - row.target) * s_i;
    lcp.q(n_i + 1) = vt * s_i;
    lcp.q(n_i + 2) = -vt * s_i;
    lcp.q(n_i + 3) = 0.0;
  }
}
}  // namespace

bool island_has_friction(const ContactPoints& rows, IslandRange island)
{
  for (std::size_t r = island.begin; r < island.end; ++r)
    if (cone(rows[r]) > 0.0)
      return true;
  return false;
}

std::size_t island_unknowns(const ContactPoints& rows, IslandRange island)
{
  const int k = island_has_friction(rows, island) ? kFrictionalUnknowns : kFrictionlessUnknowns;
  return (island.end - island.begin) * static_cast<std::size_t>(k);
}

void assemble_island_lcp(const ContactPoints& rows, IslandRange island,
                          const std::vector<BodyVelocity>& state, IslandLcp& lcp)
{
  assemble_delassus(rows, island, state, lcp);
  if (island_has_friction(rows, island))
    assemble_frictional(rows, island, state, lcp);
  else
    assemble_frictionless(rows, island, state, lcp);
}

void store_island_impulses(const Eigen::VectorXd& z, IslandRange island, ContactPoints& rows)
{
  const int k = island_has_friction(rows, island) ? kFrictionalUnknowns : kFrictionlessUnknowns;
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    ContactPoint& row = rows[r];
    const Eigen::Index n_i = k * static_cast<Eigen::Index>(r - island.begin);
    const double s = 1.0 / std::sqrt(row.k_n);
    row.lambda_n = z(n_i) * s;
    row.lambda_t = 0.0;
    row.sliding = false;
    if (k == 1)
      continue;
    const double t_plus = z(n_i + 1) * s;
    const double t_minus = z(n_i + 2) * s;
    row.sliding = z(n_i + 3) > 0.0;
    if (row.sliding)
      row.lambda_t = (t_plus >= t_minus ? 1.0 : -1.0) * cone(row) * row.lambda_n;
    else
      row.lambda_t = t_plus - t_minus;
  }
}

}  // namespace detail
}  // namespace collision2d
