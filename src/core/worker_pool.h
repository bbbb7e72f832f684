// Internal to the core: the World's worker threads. A job over [0, count) is
// cut into one contiguous share per worker; the calling thread takes the
// first, so one worker means no thread at all. The other shares go to
// whoever asks first: a worker that sleeps, or wakes late, leaves its share
// to the calling thread instead of holding it up. A job writes only to its
// own items' slots, so the result depends neither on the worker count nor
// on which thread ran which share. A staged job (run_stages) is a row of
// such splits, each begun once the one before has finished; there too a
// thread takes any share nobody has started, so a worker whose CPU another
// process holds delays the others only by a share it has begun (and, once
// it has joined a job, by that job's end).
// An exception a job throws on any thread (running out of memory) comes out
// of run() on the calling thread once every share taken has finished.
// A worker woken from sleep can be queued on the calling thread's CPU while
// another CPU idles (seen on virtual machines), and would then only run
// when the caller pauses; it moves itself off that CPU first.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#include "collision2d/broad_phase.h"

namespace collision2d
{
namespace detail
{
class WorkerPool : public RangeRunner
{
public:
  WorkerPool() = default;
  /// A copy has its own threads, as many as the original.
  WorkerPool(const WorkerPool& other);
  WorkerPool& operator=(const WorkerPool& other);
  ~WorkerPool() override;

  /// Workers including the calling thread (at least 1).
  int workers() const override { return static_cast<int>(threads_.size()) + 1; }
  /// Starts or stops threads so `workers` take part (values below 1 count as 1).
  void resize(int workers);
  /// Runs `job` over [0, count) split across the workers; returns when all
  /// are done, rethrowing the first exception any of them threw.
  void run(std::size_t count, Job job, void* context) override;
  /// Calls body(begin, end) over [0, count) split across the workers, or once
  /// over all of it on the calling thread when count < min_shared (too little
  /// work to pay for waking the others). `body` is any callable; it is taken
  /// by address, so capturing it costs no allocation.
  template <class Body>
  void parallel_for(std::size_t count, std::size_t min_shared, Body&& body)
  {
    if (workers() == 1 || count < min_shared)
    {
      body(std::size_t{0}, count);
      return;
    }
    using Callable = std::remove_reference_t<Body>;
    const Job trampoline = [](void* callable, std::size_t begin, std::size_t end) {
      (*static_cast<Callable*>(callable))(begin, end);
    };
    run(count, trampoline, const_cast<void*>(static_cast<const void*>(&body)));
  }
  /// Runs `stages` stages in turn, each cut into one share per worker:
  /// work(stage, share, shares). A stage begins once every share of the one
  /// before has finished, and what those wrote is then seen. Each thread runs
  /// its own share of a stage first, then any share no thread has started.
  /// The shares of one stage must not depend on one another; which thread
  /// runs which then changes no result. With `shared` false (too little work
  /// to pay for the waits between stages) every stage runs whole on the
  /// calling thread, as with one worker.
  template <class Work>
  void run_stages(std::size_t stages, Work&& work, bool shared = true)
  {
    if (!shared || threads_.empty())
    {
      for (std::size_t stage = 0; stage < stages; ++stage)
      {
        work(stage, std::size_t{0}, std::size_t{1});
      }
      return;
    }
    begin_stages(stages);
    using Callable = std::remove_reference_t<Work>;
    Staged<Callable> job{this, stages, &work};
    // A share of this job is a member's walk through the stages.
    run(static_cast<std::size_t>(workers()), &Staged<Callable>::walk, &job);
  }

private:
  /// Share m of one stage, on a cache line of its own: whether a thread has
  /// taken it, and how many shares of the stage member m's walk finished.
  struct alignas(64) StageClaim
  {
    std::atomic<bool> taken{false};
    std::atomic<std::size_t> done{0};
  };
  /// A run_stages job: member m's share of it walks every stage.
  template <class Work>
  struct Staged
  {
    WorkerPool* pool;
    std::size_t stages;
    Work* work;
    static void walk(void* context, std::size_t member, std::size_t)
    {
      const Staged& s = *static_cast<const Staged*>(context);
      for (std::size_t stage = 0; stage < s.stages; ++stage)
      {
        s.pool->run_stage(stage, member, *s.work);
      }
    }
  };
  /// Sizes and clears the claims of a job of `stages` stages.
  void begin_stages(std::size_t stages);
  StageClaim* stage_row(std::size_t stage) { return stage_claims_.get() + stage * static_cast<std::size_t>(workers()); }
  /// Member `member`'s turn at `stage`: once the stage before is done, its
  /// own share if nobody took it, then the others' untaken ones.
  template <class Work>
  void run_stage(std::size_t stage, std::size_t member, Work& work)
  {
    const std::size_t shares = static_cast<std::size_t>(workers());
    if (stage > 0)
    {
      await_stage(stage - 1);
    }
    StageClaim* row = stage_row(stage);
    std::size_t done = 0;
    for (std::size_t k = 0; k < shares; ++k)
    {
      const std::size_t share = (member + k) % shares;
      if (!row[share].taken.exchange(true, std::memory_order_relaxed))
      {
        work(stage, share, shares);
        ++done;
      }
    }
    // Only this member's walk writes its row's count.
    row[member].done.store(done, std::memory_order_release);
  }
  /// Waits until every share of `stage` is done (spinning, then yielding);
  /// leaves by an exception run() does not pass on if a share threw.
  void await_stage(std::size_t stage);
  void start(std::size_t count, Job job, void* context);
  void stop();
  /// A thread's loop: waits for a job newer than `seen`, takes the shares left.
  void serve(std::size_t seen);
  /// After a sleep: if this thread shares the calling thread's CPU and the
  /// process may run elsewhere, moves it to another allowed CPU (Linux).
  void leave_caller_cpu() const;
  /// Spins briefly until done() holds; returns whether it did (else the caller sleeps).
  template <class Done>
  static bool spin_until(Done done);
  /// Share `index` of [0, count_).
  void range(std::size_t index, std::size_t& begin, std::size_t& end) const;
  /// Runs share `index` of the current job, keeping what it throws.
  void run_share(std::size_t index);
  /// Runs the shares after the first of job `number` that nobody has taken
  /// yet, one at a time, until none is left or that job is over.
  void take_shares(std::size_t number);
  /// Counts a share after the first as finished; the last one wakes run().
  void finish_share();

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  /// Set for each job (under the mutex) to its number; threads wait for a
  /// new one, spinning a little before they sleep, as the caller does for
  /// the job's end.
  std::atomic<std::size_t> generation_{0};
  /// The job's number (above kShareBits) and how many of its
  /// shares after the first are left to take (below). A thread takes one by
  /// counting it down while the number is still that of its job.
  std::atomic<std::uint64_t> claims_{0};
  std::atomic<std::size_t> shares_done_{0};  ///< shares after the first finished (any job)
  bool quitting_ = false;
  Job job_ = nullptr;
  void* context_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<int> caller_cpu_{-1};      ///< the CPU the calling thread started the current job on
  std::atomic<std::size_t> sleepers_{0}; ///< workers asleep waiting for a job
  std::atomic<bool> failed_{false};      ///< a share of the current job threw ...
  std::exception_ptr failure_;           ///< ... this first (under the mutex)
  std::unique_ptr<StageClaim[]> stage_claims_;  ///< a row of claims a stage (begin_stages)
  std::size_t stage_capacity_ = 0;              ///< claims stage_claims_ has room for
};

}  // namespace detail
}  // namespace collision2d
