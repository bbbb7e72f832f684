#include "worker_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
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
    threads_.emplace_back(&WorkerPool::serve, this, t + 1, generation_.load());
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
/// Spins between yields at a sync(): long enough to catch a worker that is
/// a few microseconds behind, short enough not to starve a busy machine.
constexpr int kSpinsBeforeYield = 64;
/// Yields before a thread waiting for a job (or for the workers to finish
/// one) sleeps: enough to stay awake through a frame's serial stages (about
/// a millisecond), since a worker woken from sleep starts its share late and
/// the others wait for it at the next sync. Between frames it sleeps.
constexpr int kYieldsBeforeSleep = 1024;
/// claims_' low bits: shares left to take (fewer than there are workers).
constexpr unsigned kShareBits = 16;
constexpr std::uint64_t kShareMask = (std::uint64_t{1} << kShareBits) - 1;

/// Thrown at a sync() whose team lost a member to an exception: it ends the
/// other members' shares; run() passes on the member's exception instead.
struct TeamStopped
{
};

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

void WorkerPool::sync()
{
  const std::size_t workers = threads_.size() + 1;
  if (workers == 1)
  {
    return;
  }
  const std::size_t phase = phase_.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == workers)
  {
    arrived_.store(0, std::memory_order_relaxed);
    phase_.fetch_add(1, std::memory_order_release);
    return;
  }
  for (int spins = 0; phase_.load(std::memory_order_acquire) == phase; ++spins)
  {
    if (failed_.load(std::memory_order_acquire))
    {
      throw TeamStopped{};
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

void WorkerPool::run(std::size_t count, Job job, void* context) { start(count, job, context, false); }

void WorkerPool::start(std::size_t count, Job job, void* context, bool team)
{
  if (threads_.empty() || count < 2)
  {
    job(context, 0, count);
    return;
  }
  const std::size_t others = threads_.size();
  const std::size_t number = generation_.load(std::memory_order_relaxed) / 2 + 1;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = job;
    context_ = context;
    count_ = count;
    failed_.store(false, std::memory_order_relaxed);
    failure_ = nullptr;
    arrived_.store(0, std::memory_order_relaxed);  // a stopped team may have left some counted
    shares_done_.store(0, std::memory_order_relaxed);
    claims_.store(team ? 0 : static_cast<std::uint64_t>(number) << kShareBits | others, std::memory_order_release);
    generation_.store(2 * number + (team ? 1 : 0), std::memory_order_release);
  }
  start_.notify_all();
  run_share(0);
  if (!team)
  {
    take_shares(number);
  }
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
  catch (const TeamStopped&)
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

void WorkerPool::serve(std::size_t index, std::size_t seen)
{
  for (;;)
  {
    // A new job is seen without the lock first; the lock is then taken only
    // to read it (and to sleep when none comes soon).
    spin_until([&] { return generation_.load(std::memory_order_acquire) != seen; });
    std::unique_lock<std::mutex> lock(mutex_);
    start_.wait(lock, [&] { return quitting_ || generation_.load(std::memory_order_relaxed) != seen; });
    if (quitting_)
    {
      return;
    }
    seen = generation_.load(std::memory_order_relaxed);
    lock.unlock();
    if (seen % 2 == 0)
    {
      take_shares(seen / 2);
      continue;
    }
    run_share(index);
    finish_share();
  }
}

}  // namespace detail
}  // namespace collision2d
