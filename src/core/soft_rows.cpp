// The soft step's rows in colours (soft_rows.h): the coloured manifolds
// (soft_rows_colour.cpp) packed into batches, the passes in colour order and
// the scalar lane path (the choice of path is soft_rows_dispatch.cpp).
#include "soft_rows.h"

#include <algorithm>

#include "scratch_buffer.h"
#include "soft_rows_kernel.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Row manifolds (lanes) below which filling the batches stays on the
/// calling thread: a lane is a few dozen copies.
constexpr std::size_t kMinSharedLanes = 512;

struct ScalarOps
{
  int j = 0;
  double load(const double* f) const { return f[j]; }
  void store(double* f, double v) const { f[j] = v; }
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<double>& side) const
  {
    const BodyVelocity& s = state[index[j]];
    side.v = {s.v.x, s.v.y};
    side.w = s.omega;
    side.moved = {s.moved.x, s.moved.y};
    side.c = s.turned_cos;
    side.s = s.turned_sin;
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<double>& side) const
  {
    BodyVelocity& s = state[index[j]];
    s.v = Vec2{side.v.x, side.v.y};
    s.omega = side.w;
  }
};

}  // namespace

void warm_start_batch_scalar(RowBatch& batch, int lanes, std::vector<BodyVelocity>& velocity)
{
  for (int j = 0; j < lanes; ++j)
  {
    rows::warm_start_rows<double>(ScalarOps{j}, batch, velocity);
  }
}

void solve_batch_scalar(RowBatch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  for (int j = 0; j < lanes; ++j)
  {
    rows::solve_rows<double>(ScalarOps{j}, batch, velocity, pass);
  }
}

void SoftRows::pack(std::vector<ContactPoint>& points, std::vector<BodyVelocity>& velocity, bool friction,
                    WorkerPool& workers)
{
  spare_ = static_cast<std::uint32_t>(velocity.size());
  velocity.push_back(body_velocity(Vec2{0.0, 0.0}, 0.0, 0.0, 0.0));
  colour_manifolds(velocity.size());                      // soft_rows_colour.cpp
  // Each colour's rows in whole batches, the last one padded. Every lane
  // has its own slot, so the workers can fill them in any split.
  std::size_t batches = 0;
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    RowColour& c = colours_[colour];
    c.begin = batches;
    batches += (c.lanes + kRowLanes - 1) / kRowLanes;
    c.end = batches;
  }
  resize_to_overwrite(rows_, batches);  // fill_lane writes every lane
  lane_of_.assign(points.size(), kNoLane);
  workers.parallel_for(row_slots_.size(), kMinSharedLanes, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r)
    {
      const RowSlot& row = row_slots_[r];
      const std::size_t lane = colours_[row.colour].begin * kRowLanes + row.slot;  // over all batches
      fill_lane(rows_[lane / kRowLanes], static_cast<int>(lane % kRowLanes), points, row.first, friction);
      lane_of_[row.first] = static_cast<std::uint32_t>(2 * lane);
      lane_of_[row.first + 1] = static_cast<std::uint32_t>(2 * lane + 1);
    }
  });
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    const RowColour& c = colours_[colour];
    for (std::size_t slot = c.lanes; slot < (c.end - c.begin) * kRowLanes; ++slot)
    {
      fill_lane(rows_[c.begin + slot / kRowLanes], static_cast<int>(slot % kRowLanes), points, SIZE_MAX, friction);
    }
  }
}

void SoftRows::fill_lane(RowBatch& r, int j, const std::vector<ContactPoint>& points, std::size_t first,
                         bool friction) const
{
  if (first == SIZE_MAX)
  {
    // Padding: the spare body on both sides, nothing to push.
    r.a[j] = spare_;
    r.b[j] = spare_;
    for (double* f : {r.nx, r.ny, r.k12, r.inv_mass_a, r.inv_mass_b, r.inv_inertia_a, r.inv_inertia_b,
                      r.bias_rate, r.mu_s, r.mu_k, r.rough})
    {
      f[j] = 0.0;
    }
    for (double* f : {r.k11, r.k22, r.pair_tangent_mass, r.mass_scale})
    {
      f[j] = 1.0;
    }
    for (RowPoint& q : r.point)
    {
      for (double* f : {q.ra_x, q.ra_y, q.rb_x, q.rb_y, q.base, q.kinetic, q.anchor, q.normal, q.tangent,
                        q.sliding})
      {
        f[j] = 0.0;
      }
    }
    return;
  }
  const ContactPoint& p = points[first];
  r.a[j] = static_cast<std::uint32_t>(p.a);
  r.b[j] = static_cast<std::uint32_t>(p.b);
  r.nx[j] = p.normal.x;
  r.ny[j] = p.normal.y;
  r.k11[j] = p.k_n;
  r.k12[j] = p.pair_k12;
  r.k22[j] = points[first + 1].k_n;
  r.pair_tangent_mass[j] = p.pair_tangent_mass;
  r.inv_mass_a[j] = p.inv_mass_a;
  r.inv_mass_b[j] = p.inv_mass_b;
  r.inv_inertia_a[j] = p.inv_inertia_a;
  r.inv_inertia_b[j] = p.inv_inertia_b;
  r.bias_rate[j] = p.softness.bias_rate;
  r.mass_scale[j] = p.softness.mass_scale;
  r.mu_s[j] = p.mu_s;
  r.mu_k[j] = p.mu_k;
  r.rough[j] = friction && (p.mu_s > 0.0 || p.mu_k > 0.0) ? 1.0 : 0.0;
  for (int k = 0; k < 2; ++k)
  {
    const ContactPoint& c = points[first + k];
    RowPoint& q = r.point[k];
    q.ra_x[j] = c.r_a.x;
    q.ra_y[j] = c.r_a.y;
    q.rb_x[j] = c.r_b.x;
    q.rb_y[j] = c.r_b.y;
    q.base[j] = c.base_separation;
    q.kinetic[j] = c.kinetic ? 1.0 : 0.0;
    q.anchor[j] = c.anchor_drift;
    q.normal[j] = c.lambda_n;
    q.tangent[j] = c.lambda_t;
    q.sliding[j] = c.sliding ? 1.0 : 0.0;
  }
}

double* SoftRows::normal_impulse_of(std::size_t k)
{
  int lane = 0;
  // The rows are this object's own and it is not const here: writable.
  RowPoint* point = const_cast<RowPoint*>(row_point_of(k, lane));
  return point == nullptr ? nullptr : &point->normal[lane];
}

namespace
{
/// Calls f(batch, lanes) for part `part` of `parts` of a colour's batches.
template <class F>
void each_batch(const RowColour& c, std::vector<RowBatch>& rows, std::size_t part, std::size_t parts, F f)
{
  const std::size_t n = c.end - c.begin;
  for (std::size_t r = c.begin + n * part / parts; r < c.begin + n * (part + 1) / parts; ++r)
  {
    f(rows[r], static_cast<int>(std::min<std::size_t>(kRowLanes, c.lanes - (r - c.begin) * kRowLanes)));
  }
}
}  // namespace

void SoftRows::warm_start_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, std::size_t part,
                               std::size_t parts)
{
  const RowLanes path = row_lanes();
  each_batch(colours_[colour], rows_, part, parts,
             [&](RowBatch& batch, int lanes) { warm_start_batch(path, batch, lanes, velocity); });
}

void SoftRows::solve_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, const RowPass& pass,
                          std::size_t part, std::size_t parts)
{
  const RowLanes path = row_lanes();
  each_batch(colours_[colour], rows_, part, parts,
             [&](RowBatch& batch, int lanes) { solve_batch(path, batch, lanes, velocity, pass); });
}

void SoftRows::drop_spare_body(std::vector<BodyVelocity>& velocity) const { velocity.pop_back(); }

}  // namespace detail
}  // namespace collision2d
