#include "worker_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif
#if defined(__linux__)
#include <sched.h>
#endif

namespace collision2d
{
namespace detail
{
WorkerPool::WorkerPool(const WorkerPool& other) { resize(other.workers()); }

WorkerPool& WorkerPool::operator=(const WorkerPool& other)
{
  if (this != &other)
  {
    resize(other.workers());
  }
  return *this;
}

WorkerPool::~WorkerPool() { stop(); }

void WorkerPool::resize(int workers)
{
  const std::size_t threads = workers > 1 ? static_cast<std::size_t>(workers - 1) : 0;
  if (threads == threads_.size())
  {
    return;
  }
  stop();
  quitting_ = false;
  threads_.reserve(threads);
  for (std::size_t t = 0; t < threads; ++t)
  {
    threads_.emplace_back(&WorkerPool::serve, this, generation_.load());
  }
}

void WorkerPool::stop()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quitting_ = true;
  }
  start_.notify_all();
  for (std::thread& thread : threads_)
  {
    thread.join();
  }
  threads_.clear();
}

namespace
{
/// Spins before a waiting thread (for a job, a job's end or a stage's end)
/// starts to yield: long enough to catch a worker that is a few
/// microseconds behind, short enough not to starve a busy machine.
constexpr int kSpinsBeforeYield = 64;
/// Yields before a thread waiting for a job (or for the workers to finish
/// one) sleeps: enough to stay awake through a frame's serial stages (about
/// a millisecond), since a worker woken from sleep joins a job late and
/// leaves its shares to the others. Between frames it sleeps.
constexpr int kYieldsBeforeSleep = 1024;
/// claims_' low bits: shares left to take (fewer than there are workers).
constexpr unsigned kShareBits = 16;
constexpr std::uint64_t kShareMask = (std::uint64_t{1} << kShareBits) - 1;

/// Thrown while waiting for a stage whose share threw: it ends the other
/// members' walks; run() passes on the share's exception instead.
struct StagesStopped
{
};

/// The CPU this thread runs on, or -1 where that cannot be asked.
int current_cpu()
{
#if defined(__linux__)
  return sched_getcpu();
#else
  return -1;
#endif
}

void pause()
{
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}
}  // namespace

template <class Done>
bool WorkerPool::spin_until(Done done)
{
  for (int spins = 0; spins < kSpinsBeforeYield + kYieldsBeforeSleep; ++spins)
  {
    if (done())
    {
      return true;
    }
    if (spins < kSpinsBeforeYield)
    {
      pause();
    }
    else
    {
      std::this_thread::yield();
    }
  }
  return false;
}

void WorkerPool::begin_stages(std::size_t stages)
{
  const std::size_t claims = stages * static_cast<std::size_t>(workers());
  if (claims > stage_capacity_)
  {
    stage_claims_.reset(new StageClaim[claims]);
    stage_capacity_ = claims;
  }
  for (std::size_t k = 0; k < claims; ++k)
  {
    stage_claims_[k].taken.store(false, std::memory_order_relaxed);
    stage_claims_[k].done.store(0, std::memory_order_relaxed);
  }
}

void WorkerPool::await_stage(std::size_t stage)
{
  const std::size_t shares = static_cast<std::size_t>(workers());
  const StageClaim* row = stage_row(stage);
  const auto finished = [&] {
    std::size_t done = 0;
    for (std::size_t m = 0; m < shares; ++m)
    {
      done += row[m].done.load(std::memory_order_acquire);
    }
    return done == shares;
  };
  for (int spins = 0; !finished(); ++spins)
  {
    if (failed_.load(std::memory_order_acquire))
    {
      throw StagesStopped{};
    }
    if (spins < kSpinsBeforeYield)
    {
      pause();
    }
    else
    {
      std::this_thread::yield();
    }
  }
}

void WorkerPool::range(std::size_t index, std::size_t& begin, std::size_t& end) const
{
  const std::size_t parts = threads_.size() + 1;
  begin = count_ * index / parts;
  end = count_ * (index + 1) / parts;
}

void WorkerPool::run(std::size_t count, Job job, void* context) { start(count, job, context); }

void WorkerPool::start(std::size_t count, Job job, void* context)
{
  if (threads_.empty() || count < 2)
  {
    job(context, 0, count);
    return;
  }
  const std::size_t others = threads_.size();
  const std::size_t number = generation_.load(std::memory_order_relaxed) + 1;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = job;
    context_ = context;
    count_ = count;
    failed_.store(false, std::memory_order_relaxed);
    failure_ = nullptr;
    caller_cpu_.store(current_cpu(), std::memory_order_relaxed);
    shares_done_.store(0, std::memory_order_relaxed);
    claims_.store(static_cast<std::uint64_t>(number) << kShareBits | others, std::memory_order_release);
    generation_.store(number, std::memory_order_release);
  }
  start_.notify_all();
  if (sleepers_.load(std::memory_order_acquire) > 0)
  {
    // A woken worker may be queued behind this thread: let it run, so it
    // can move to another CPU before the shares start.
    std::this_thread::yield();
  }
  run_share(0);
  take_shares(number);
  const auto finished = [&] { return shares_done_.load(std::memory_order_acquire) == others; };
  if (!spin_until(finished))
  {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, finished);
  }
  if (failed_.load(std::memory_order_acquire))
  {
    std::exception_ptr failure;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      failure.swap(failure_);
    }
    std::rethrow_exception(failure);
  }
}

void WorkerPool::take_shares(std::size_t number)
{
  // A share taken while the number is this job's cannot outlive the job:
  // run() waits for every share taken, so the job's fields stay put.
  const std::uint64_t tag = static_cast<std::uint64_t>(number) << kShareBits;
  const std::size_t shares = threads_.size() + 1;
  std::uint64_t claims = claims_.load(std::memory_order_acquire);
  while ((claims & ~kShareMask) == tag && (claims & kShareMask) != 0)
  {
    if (!claims_.compare_exchange_weak(claims, claims - 1, std::memory_order_acq_rel, std::memory_order_acquire))
    {
      continue;
    }
    run_share(shares - static_cast<std::size_t>(claims & kShareMask));
    finish_share();
    claims = claims_.load(std::memory_order_acquire);
  }
}

void WorkerPool::finish_share()
{
  if (shares_done_.fetch_add(1, std::memory_order_acq_rel) + 1 == threads_.size())
  {
    // Under the lock, so a caller about to sleep cannot miss it.
    std::lock_guard<std::mutex> lock(mutex_);
    done_.notify_one();
  }
}

void WorkerPool::run_share(std::size_t index)
{
  std::size_t begin = 0;
  std::size_t end = 0;
  range(index, begin, end);
  try
  {
    job_(context_, begin, end);
  }
  catch (const StagesStopped&)
  {
    // Another share threw first; its exception is the one run() passes on.
  }
  catch (...)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_)
    {
      failure_ = std::current_exception();
    }
    failed_.store(true, std::memory_order_release);
  }
}

void WorkerPool::leave_caller_cpu() const
{
#if defined(__linux__)
  const int here = current_cpu();
  if (here < 0 || here >= CPU_SETSIZE || here != caller_cpu_.load(std::memory_order_relaxed))
  {
    return;
  }
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0)
  {
    return;
  }
  cpu_set_t elsewhere = allowed;
  CPU_CLR(here, &elsewhere);
  // Narrowing the mask moves the thread now; widening it again lets the
  // scheduler place it freely from there on.
  if (CPU_COUNT(&elsewhere) > 0 && sched_setaffinity(0, sizeof elsewhere, &elsewhere) == 0)
  {
    sched_setaffinity(0, sizeof allowed, &allowed);
  }
#endif
}

void WorkerPool::serve(std::size_t seen)
{
  for (;;)
  {
    // A new job is seen without the lock first; the lock is then taken only
    // to read it (and to sleep when none comes soon).
    const bool spun = spin_until([&] { return generation_.load(std::memory_order_acquire) != seen; });
    std::unique_lock<std::mutex> lock(mutex_);
    if (!spun)
    {
      sleepers_.fetch_add(1, std::memory_order_relaxed);
      start_.wait(lock, [&] { return quitting_ || generation_.load(std::memory_order_relaxed) != seen; });
      sleepers_.fetch_sub(1, std::memory_order_relaxed);
    }
    if (quitting_)
    {
      return;
    }
    seen = generation_.load(std::memory_order_relaxed);
    lock.unlock();
    if (!spun)
    {
      leave_caller_cpu();
    }
    take_shares(seen);
  }
}

}  // namespace detail
}  // namespace collision2d
