// Internal to the core: the World's worker threads. A job over [0, count) is
// cut into one contiguous range per worker; the calling thread takes the
// first range, so one worker means no thread at all. A job writes only to
// its own range's slots, so the result does not depend on the worker count.
// An exception a job throws on any worker (running out of memory) comes out
// of run() on the calling thread once every worker has stopped.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
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
  /// for worker w; inside it the workers may meet at sync().
  void run_team(Job job, void* context) { run(static_cast<std::size_t>(workers()), job, context); }
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
  void stop();
  /// A thread's loop: waits for a job newer than `seen`, takes its range.
  void serve(std::size_t index, std::size_t seen);
  /// Spins briefly until done() holds; returns whether it did (else the caller sleeps).
  template <class Done>
  static bool spin_until(Done done);
  /// The range of [0, count_) that worker `index` takes.
  void range(std::size_t index, std::size_t& begin, std::size_t& end) const;
  /// Runs one worker's share of the current job, keeping what it throws.
  void run_share(std::size_t index);

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  /// Bumped for each job (under the mutex); threads wait for a new one,
  /// spinning a little before they sleep, as the caller does for pending_.
  std::atomic<std::size_t> generation_{0};
  std::atomic<std::size_t> pending_{0};  ///< threads still working on the current job
  bool quitting_ = false;
  Job job_ = nullptr;
  void* context_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> arrived_{0};  ///< workers at the current sync()
  std::atomic<std::size_t> phase_{0};    ///< bumped when the last one arrives
  std::atomic<bool> failed_{false};      ///< a share of the current job threw ...
  std::exception_ptr failure_;           ///< ... this first (under the mutex)
};

}  // namespace detail
}  // namespace collision2d
