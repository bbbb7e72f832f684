#include "island_jacobian.h"
#include "eigen_blocking.h"

namespace collision2d
{
namespace detail
{
namespace
{
constexpr int kDofPerBody = 3;  // vx, vy, omega
}  // namespace

void begin_jacobian(const ContactPoints& rows, IslandRange island, const std::vector<BodyVelocity>& state,
                    Eigen::Index directions, IslandJacobian& j)
{
  if (j.local_body.size() < state.size())
    j.local_body.resize(state.size(), -1);
  int count = 0;
  for (std::size_t r = island.begin; r < island.end; ++r)
    for (std::size_t body : {rows[r].a, rows[r].b})
      if (state[body].inv_mass > 0.0 && j.local_body[body] < 0)
        j.local_body[body] = kDofPerBody * count++;

  j.body_inverse_mass.resize(kDofPerBody * count);
  for (std::size_t r = island.begin; r < island.end; ++r)
    for (std::size_t body : {rows[r].a, rows[r].b})
      if (j.local_body[body] >= 0)
        j.body_inverse_mass.segment<kDofPerBody>(j.local_body[body]) << state[body].inv_mass, state[body].inv_mass,
            state[body].inv_inertia;
  j.jacobian.setZero(directions, kDofPerBody * count);
}

void add_jacobian_entry(IslandJacobian& j, Eigen::Index row, std::size_t body, double sign, Vec2 dir, Vec2 r)
{
  const int column = j.local_body[body];
  if (column < 0)
    return;
  j.jacobian(row, column) = sign * dir.x;
  j.jacobian(row, column + 1) = sign * dir.y;
  j.jacobian(row, column + 2) = sign * cross(r, dir);
}

void finish_jacobian(const ContactPoints& rows, IslandRange island, IslandJacobian& j)
{
  for (std::size_t r = island.begin; r < island.end; ++r)
  {
    j.local_body[rows[r].a] = -1;
    j.local_body[rows[r].b] = -1;
  }
  pin_eigen_blocking();
  j.delassus.noalias() = j.jacobian * j.body_inverse_mass.asDiagonal() * j.jacobian.transpose();
}

}  // namespace detail
}  // namespace collision2d
