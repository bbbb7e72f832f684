// The soft step's passes over the frame's manifolds (world_soft_step.cpp
// calls them each substep): a warm start and a biased pass, or the relax.
// In the iterative mode they walk the colours of the soft rows (soft_rows.h);
// a colour's manifolds share no moving body, so its rows go four at a time
// and, with several workers, each colour is a stage whose shares any of them
// may take (worker_pool.h). Any split gives the same bits. The exact mode
// keeps the point order.
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Coloured manifolds below which a pass is too short to share among workers:
/// they wait for each other once a colour, which costs more than a short
/// colour's work (measured in docs/performance.md, profile notes).
constexpr std::size_t kMinSharedManifolds = 1024;

/// Part `part` of `parts` of [0, n).
std::size_t part_begin(std::size_t n, std::size_t part, std::size_t parts) { return n * part / parts; }

}  // namespace

/// One soft pass: the frame's context, the rows' parameters, and how many of
/// its stages warm start (0 without).
struct SoftPass
{
  const StepContext* ctx = nullptr;
  RowPass rows;
  std::size_t warm_stages = 0;
};

void WorldImpl::soft_pass(const StepContext& ctx, bool use_bias, bool warm)
{
  if (!rows_on())
  {
    if (warm)
    {
      warm_start();                                        // world_solve.cpp
    }
    // As in the colours, the ground after a kinematic body that presses on it.
    for_manifolds_kinematic_first([&](std::size_t k) { solve_soft_manifold(k, ctx, use_bias); });
    return;
  }
  // A stage a colour, then one for the overflow: the warm start's, then the solve's.
  const std::size_t colours = soft_rows_.colour_count();
  const SoftPass pass{&ctx, RowPass{ctx.inv_h, settings_.contact_push_speed, use_bias}, warm ? colours + 1 : 0};
  const std::size_t stages = pass.warm_stages + colours + 1;
  workers_.run_stages(
      stages, [&](std::size_t s, std::size_t part, std::size_t parts) { soft_stage(pass, s, part, parts); },
      soft_rows_.coloured() >= kMinSharedManifolds);
}

/// Stage `stage` of a soft pass (a colour, or the overflow after the
/// colours; the warm start's stages first), part `part` of `parts` of it.
void WorldImpl::soft_stage(const SoftPass& pass, std::size_t stage, std::size_t part, std::size_t parts)
{
  const bool warming = stage < pass.warm_stages;
  const std::size_t c = warming ? stage : stage - pass.warm_stages;
  if (c == soft_rows_.colour_count())
  {
    // The overflow's manifolds share bodies: one thread, in order.
    if (part == 0)
    {
      for (std::size_t first : soft_rows_.overflow())
      {
        warming ? warm_start_manifold(first) : solve_soft_manifold(first, *pass.ctx, pass.rows.use_bias);
      }
    }
    return;
  }
  const std::vector<std::size_t>& others = soft_rows_.others(c);
  const std::size_t end = part_begin(others.size(), part + 1, parts);
  if (warming)
  {
    soft_rows_.warm_start_rows(c, velocity_, part, parts);
    for (std::size_t k = part_begin(others.size(), part, parts); k < end; ++k)
    {
      warm_start_manifold(others[k]);
    }
    return;
  }
  soft_rows_.solve_rows(c, velocity_, pass.rows, part, parts);
  for (std::size_t k = part_begin(others.size(), part, parts); k < end; ++k)
  {
    solve_soft_manifold(others[k], *pass.ctx, pass.rows.use_bias);
  }
}

void WorldImpl::warm_start_manifold(std::size_t first)
{
  detail::warm_start(points_[first], velocity_);
  if (points_[first].count == 2)
  {
    detail::warm_start(points_[first + 1], velocity_);
  }
}

void WorldImpl::solve_soft_manifold(std::size_t k, const StepContext& ctx, bool use_bias)
{
  ContactPoint& p = points_[k];
  if (!p.active || p.exact)
  {
    return;
  }
  const bool rough = ctx.effects.friction && has_friction(p);
  const double push = settings_.contact_push_speed;
  // The anchors' offset gives both the gap and the slip; the passes move no
  // body, so it is read once per point (as the rows read it).
  const Vec2 offset = anchor_offset(p, velocity_);
  if (p.count == 2)
  {
    ContactPoint& q = points_[k + 1];
    const Vec2 second_offset = anchor_offset(q, velocity_);
    solve_soft_normal_block(p, q, springs_.of(p), separation_at(p, offset), separation_at(q, second_offset),
                            velocity_, ctx.inv_h, push, use_bias);
    if (rough)
    {
      const double pull =
          use_bias ? anchor_pull(p, 0.5 * (anchor_drift(p, offset) + anchor_drift(q, second_offset)), push) : 0.0;
      solve_friction_pair(p, q, velocity_, pull);
    }
    return;
  }
  solve_soft_normal(p, springs_.of(p), separation_at(p, offset), velocity_, ctx.inv_h, push, use_bias);
  if (rough)
  {
    solve_friction(p, velocity_, use_bias ? anchor_pull(p, anchor_drift(p, offset), push) : 0.0);
  }
}

double WorldImpl::anchor_drift(const ContactPoint& p, Vec2 offset) const
{
  return p.kinetic ? 0.0 : p.anchor_drift + slip_at(p, offset);
}

double WorldImpl::anchor_pull(const ContactPoint& p, double drift, double max_push) const
{
  // As the normal's push-out: the spring's rate, capped.
  const Softness& spring = springs_.of(p);
  const double pull = spring.mass_scale * spring.bias_rate * drift;
  return std::max(-max_push, std::min(max_push, pull));
}

}  // namespace detail
}  // namespace collision2d
