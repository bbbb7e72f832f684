// The World's step, top-down: frames of substeps in the Fx2D order. Each
// stage is a call below, in the order it runs; the file named beside it holds
// its code.
//
// Refinements of the plain Fx2D order, each a setting or explained where coded:
//  - warm starting on every substep, not just a frame's first;
//  - several penetration passes (position_iterations), optionally with a
//    manifold's two points as one block (position_block), and a sticking
//    contact taking back the tangential part of its integration move;
//  - velocity resolution on the contact-solver kernel (contact_kernel.h): a
//    manifold's normals as one 2x2 block, its friction as one row at its
//    midpoint, stick or slip as a contact state (mu_s, then mu_k);
//  - the exact (pivoting) mode per island (world_exact.cpp);
//  - poses advanced with predicted velocities (warm_start_before_integration,
//    world_warm_integration.cpp).
//
// Velocity derivation (Fx2D step 4): the penetration resolution shifts the
// previous pose by exactly the correction it applies, so (pose - previous) / h
// equals the velocity integrated in step 1. That integrated velocity is kept
// instead of the difference quotient, which would lose digits far from the
// origin and turn a time-of-impact clamp (a shortened move) into a loss of speed.
#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "scratch_buffer.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Bodies whose kinetic energies are summed as one chain (kinetic_energy):
/// a world of up to this many sums them all in one, as a serial loop would.
constexpr std::size_t kEnergyBlock = 512;

std::size_t energy_blocks(std::size_t bodies) { return (bodies + kEnergyBlock - 1) / kEnergyBlock; }

}  // namespace

StepReport WorldImpl::step(int frames)
{
  if (frames < 1)
  {
    std::ostringstream msg;
    msg << "step: frames must be >= 1 (got " << frames << ")";
    throw std::invalid_argument(msg.str());
  }
  workers_.resize(settings_.workers);
  StepReport report;
  if (replay_rest_step(frames, report))                   // world_rest.cpp
  {
    return report;
  }
  // finish_report must not allocate: the frames are kept by then.
  make_room(block_energies_, energy_blocks(bodies_.size()));
  save_motion(frames);                                    // world_rollback.cpp
  followed_known_ = false;  // publish_contacts works it out again for this step
  try
  {
    for (int f = 0; f < frames; ++f)
    {
      step_frame(report);
    }
  }
  catch (...)
  {
    restore_motion();
    throw;
  }
  rollback_.active = false;
  finish_report(report);
  note_finish(report);
  return report;
}

void WorldImpl::step_frame(StepReport& report)
{
  if (replay_rest_frame(report))                          // world_rest.cpp
  {
    return;
  }
  const bool started_at_rest = at_rest();
  StepReport frame;
  StepContext ctx = select_effects();                     // world_effects.cpp
  if (!ctx.effects.sleeping)
  {
    wake_everyone();                                      // world_sleeping_contacts.cpp
  }
  // Visiting every body is always right; only the movers, cheaper when
  // most of the world rests (for_each_body).
  const bool rebuilt = refresh_resting_grid();            // world_contacts.cpp
  body_pass_full_ = rebuilt || 2 * movers_.size() > bodies_.size();
  ctx.h = settings_.dt / settings_.substeps;
  ctx.inv_h = 1.0 / ctx.h;
  if (settings_.soft_step)
  {
    soft_frame(ctx, frame);                               // world_soft_step.cpp
  }
  else
  {
    fx2d_frame(ctx, frame);
  }
  if (ctx.effects.sleeping)
  {
    update_sleep();                                       // world_sleep.cpp
  }
  time_ += settings_.dt;
  ++frame_count_;
  ++frame.frames;
  frame.active = ctx.effects;
  add_frame(report, frame);
  note_frame(started_at_rest, frame);
}

void WorldImpl::fx2d_frame(StepContext& ctx, StepReport& report)
{
  for (int k = 0; k < settings_.substeps; ++k)
  {
    ctx.first = k == 0;
    ctx.warm = ctx.warm_available;
    substep(ctx, report);
    if (k + 1 == settings_.substeps)
    {
      require_finite_state();                             // before the frame's contacts are published
    }
    publish_contacts();                                   // world_contacts.cpp
    cache_h_ = ctx.h;
  }
}

void WorldImpl::substep(StepContext& ctx, StepReport& report)
{
  // 1. Integrate: gravity into velocity, then the pose (swept for time of impact).
  kick(ctx);
  const bool predict = ctx.warm && settings_.warm_start_before_integration;
  if (predict)
  {
    predict_velocities(ctx);                              // world_warm_integration.cpp
  }
  advance(ctx, report);
  // 2. Detect: broad then narrow phase, impulses matched from the cache.
  detect(ctx, 0.0, report);                               // world_contacts.cpp
  if (predict)
  {
    restore_velocities();
  }
  // 3. Penetration resolution, positions only.
  load_velocities();                                      // world_solve.cpp
  prepare_points(ctx.effects);
  if (ctx.effects.position_correction)
  {
    correct_positions(ctx, report);                       // world_position.cpp
  }
  // 4.-6. Velocity resolution with warm starting.
  solve_velocity_stage(ctx, report);
  store_velocities();
  // 7. No centroid passed into a static body in the substep.
  stop_static_crossings(ctx, report, false);              // world_static_crossing.cpp
  ++report.substeps;
  report.contact_count = points_.size() + sleeping_contacts_.size();
}

void WorldImpl::kick(const StepContext& ctx)
{
  const Vec2 gravity_kick = settings_.gravity * ctx.h;
  prev_position_.resize(bodies_.size());
  prev_theta_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    prev_position_[i] = bodies_[i].position();
    prev_theta_[i] = bodies_[i].theta();
    if (awake_dynamic(i))
    {
      bodies_[i].set_velocity(bodies_[i].velocity() + gravity_kick);
    }
  }
}

void WorldImpl::advance(StepContext& ctx, StepReport& report)
{
  const bool swept = sweep(ctx.h, report, true, ctx.effects.rotation);  // world_toi.cpp
  ctx.effects.time_of_impact = ctx.effects.time_of_impact || swept;
  advance_bodies(0, bodies_.size(), ctx, swept);
}

/// Bodies [begin, end) moved over the substep (up to their time of impact when `swept`).
void WorldImpl::advance_bodies(std::size_t begin, std::size_t end, const StepContext& ctx, bool swept)
{
  for (std::size_t i = begin; i < end; ++i)
  {
    advance_body(i, ctx, swept);
  }
}

void WorldImpl::advance_body(std::size_t i, const StepContext& ctx, bool swept)
{
  if (move_body(i, ctx, swept))
  {
    Body& b = bodies_[i];
    b.set_theta(b.theta() + b.omega() * turn_time(i, ctx, swept));
  }
}

void WorldImpl::solve_velocity_stage(const StepContext& ctx, StepReport& report)
{
  if (settings_.solver_mode == SolverMode::Exact)
  {
    solve_exact_islands(report, ctx.warm);                // world_exact.cpp
  }
  if (ctx.warm)
  {
    warm_start();                                         // world_solve.cpp
  }
  solve_velocities(ctx.effects.friction);
  const double residual = velocity_residual();
  report.velocity_residual = std::max(report.velocity_residual, residual);
  if (ctx.first)
  {
    report.warm_substep_residual = residual;
  }
}

void WorldImpl::finish_report(StepReport& report)
{
  // The soft step follows its contacts' gaps from the poses; the Fx2D step,
  // whose correction is linearised, measures them again.
  if (!settings_.soft_step)
  {
    report.max_penetration = measure_penetration();
  }
  else
  {
    report.max_penetration = followed_known_ ? followed_deepest_ : followed_penetration();
  }
  report.kinetic_energy += kinetic_energy();
  report.sleeping_bodies += asleep_bodies();
}

double WorldImpl::kinetic_energy()
{
  // Summed in blocks of a fixed number of body indices, then the blocks in
  // order: the bits do not depend on the worker count, and the workers share
  // the reads of the bodies' cold records. A body that does not move has no
  // energy, so a block summing only its movers has the bits of summing all
  // its bodies.
  const bool movers_only = movers_current() && !body_pass_full_;
  const std::size_t n = bodies_.size();
  const auto energy = [this](std::size_t i) {
    const Body& b = bodies_[i];
    return b.type() == BodyType::Dynamic ? b.kinetic_energy() : 0.0;  // + 0 leaves a sum >= 0 as it is
  };
  // Where body index i starts in the list summed: the bodies, or the movers (movers_ ascends).
  const auto position = [&](std::size_t i) {
    return movers_only ? static_cast<std::size_t>(std::lower_bound(movers_.begin(), movers_.end(), i) - movers_.begin())
                       : i;
  };
  const auto block_energy = [&](std::size_t block) {
    const std::size_t first = block * kEnergyBlock;
    const std::size_t last = std::min(n, first + kEnergyBlock);
    double sum = 0.0;
    const std::size_t end_k = position(last);
    for (std::size_t k = position(first); k < end_k; ++k)
    {
      sum += energy(movers_only ? movers_[k] : k);
    }
    return sum;
  };
  const std::size_t blocks = energy_blocks(n);
  if (blocks <= 1)
  {
    return block_energy(0);  // the sum of one block is that block (0 + a sum >= 0)
  }
  block_energies_.resize(blocks);  // room made before the frames (step)
  const std::size_t min_shared = kMinSharedBodies / kEnergyBlock;
  workers_.parallel_for(blocks, min_shared, [&](std::size_t begin, std::size_t end) {
    for (std::size_t block = begin; block < end; ++block)
    {
      block_energies_[block] = block_energy(block);
    }
  });
  double sum = 0.0;
  for (double block : block_energies_)
  {
    sum += block;
  }
  return sum;
}

void WorldImpl::require_finite_state()
{
  // Only the bodies the frame visited can have changed (for_each_body).
  std::atomic<std::size_t> first_bad{bodies_.size()};
  for_each_body([&](std::size_t i) { note_non_finite(i, first_bad); });
  if (first_bad.load() != bodies_.size())
  {
    throw_non_finite(first_bad.load());
  }
}

void WorldImpl::throw_non_finite(std::size_t i) const
{
  std::ostringstream msg;
  msg << "step: body " << ids_[i] << " overflowed to a non-finite state in frame " << frame_count_ + 1
      << " (its speed, size or mass lies far beyond the supported ranges)";
  throw std::overflow_error(msg.str());
}

}  // namespace detail
}  // namespace collision2d
