// Internal to the core: the World's worker threads. A job over [0, count) is
// cut into one contiguous share per worker; the calling thread takes the
// first, so one worker means no thread at all. The other shares go to
// whoever asks first: a worker that sleeps, or wakes late, leaves its share
// to the calling thread instead of holding it up. A job writes only to its
// own items' slots, so the result depends neither on the worker count nor
// on which thread ran which share.
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
  /// Runs `job` once on every worker at the same time, as job(context, w, w + 1)
  /// for worker w; inside it the workers may meet at sync(). Each worker runs
  /// its own share, so this waits for every one.
  void run_team(Job job, void* context) { start(static_cast<std::size_t>(workers()), job, context, true); }
  /// run_team for any callable: f(w) on every worker w at the same time.
  template <class F>
  void run_team(F&& f)
  {
    using Callable = std::remove_reference_t<F>;
    const Job trampoline = [](void* callable, std::size_t worker, std::size_t) {
      (*static_cast<Callable*>(callable))(worker);
    };
    run_team(trampoline, const_cast<void*>(static_cast<const void*>(&f)));
  }
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
  /// Inside a run_team job: returns once every worker has called it, and
  /// what each wrote before is seen by all after. Workers spin (they are
  /// expected to arrive within microseconds of each other). If a worker's
  /// job threw instead, the others leave their jobs here (by an exception
  /// run() does not pass on) rather than wait for it.
  void sync();

private:
  /// run() and run_team(): a `team` job's shares are not taken over.
  void start(std::size_t count, Job job, void* context, bool team);
  void stop();
  /// A thread's loop: waits for a job newer than `seen`, takes its share.
  void serve(std::size_t index, std::size_t seen);
  /// After a sleep: if this thread shares the calling thread's CPU and the
  /// process may run elsewhere, moves it to another allowed CPU (Linux).
  void leave_caller_cpu() const;
  /// Spins briefly until done() holds; returns whether it did (else the caller sleeps).
  template <class Done>
  static bool spin_until(Done done);
  /// Share `index` of [0, count_): worker `index`'s, unless another takes it.
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
  /// Set for each job (under the mutex) to twice its number, plus one for a
  /// team job; threads wait for a new one, spinning a little before they
  /// sleep, as the caller does for the job's end.
  std::atomic<std::size_t> generation_{0};
  /// Other jobs: the job's number (above kShareBits) and how many of its
  /// shares after the first are left to take (below). A thread takes one by
  /// counting it down while the number is still that of its job.
  std::atomic<std::uint64_t> claims_{0};
  std::atomic<std::size_t> shares_done_{0};  ///< shares after the first finished (any job)
  bool quitting_ = false;
  Job job_ = nullptr;
  void* context_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> arrived_{0};  ///< workers at the current sync()
  std::atomic<std::size_t> phase_{0};    ///< bumped when the last one arrives
  std::atomic<int> caller_cpu_{-1};      ///< the CPU the calling thread started the current job on
  std::atomic<std::size_t> sleepers_{0}; ///< workers asleep waiting for a job
  std::atomic<bool> failed_{false};      ///< a share of the current job threw ...
  std::exception_ptr failure_;           ///< ... this first (under the mutex)
};

}  // namespace detail
}  // namespace collision2d
