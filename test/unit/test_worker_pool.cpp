// The World's worker threads (worker_pool.h): every item of a job runs
// exactly once whether the workers are awake, asleep or late; a team job
// still runs one share on each thread; an exception comes out of run(); a
// worker that moves off the calling thread's CPU keeps every CPU it may use.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "worker_pool.h"

#if defined(__linux__)
#include <sched.h>
#endif

namespace collision2d
{
namespace detail
{
namespace
{
/// Longer than a waiting worker spins and yields before it sleeps (about a
/// millisecond), so the next job finds it asleep.
constexpr std::chrono::milliseconds kLongEnoughToSleep{5};

/// Counts how often each item of [0, count) ran.
std::vector<int> hits_of_one_job(WorkerPool& pool, std::size_t count)
{
  std::vector<int> hits(count, 0);
  pool.parallel_for(count, 2, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      ++hits[k];  // each item belongs to one share: no two threads write it
    }
  });
  return hits;
}

TEST(WorkerPool, EveryItemRunsOnceWhetherTheWorkersAreAwakeOrAsleep)
{
  for (const int workers : {2, 4})
  {
    WorkerPool pool;
    pool.resize(workers);
    for (int round = 0; round < 60; ++round)
    {
      if (round % 10 == 0)
      {
        std::this_thread::sleep_for(kLongEnoughToSleep);
      }
      // Fewer items than workers, a few, and many.
      const std::size_t count = round % 3 == 0 ? 3 : round % 3 == 1 ? 17 : 5000;
      const std::vector<int> hits = hits_of_one_job(pool, count);
      for (std::size_t k = 0; k < count; ++k)
      {
        ASSERT_EQ(hits[k], 1) << workers << " workers, round " << round << ", item " << k << " of " << count;
      }
    }
  }
}

TEST(WorkerPool, ATeamJobRunsOneShareOnEachThreadEvenAfterTheySlept)
{
  for (const int workers : {2, 4})
  {
    WorkerPool pool;
    pool.resize(workers);
    std::this_thread::sleep_for(kLongEnoughToSleep);
    std::mutex mutex;
    std::set<std::thread::id> threads;
    std::vector<int> shares(static_cast<std::size_t>(workers), 0);
    pool.run_team([&](std::size_t worker) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        threads.insert(std::this_thread::get_id());
        ++shares[worker];
      }
      pool.sync();  // every member must be there: none may run two shares
    });
    EXPECT_EQ(threads.size(), static_cast<std::size_t>(workers));
    for (int w = 0; w < workers; ++w)
    {
      EXPECT_EQ(shares[static_cast<std::size_t>(w)], 1) << "worker " << w;
    }
  }
}

TEST(WorkerPool, AnExceptionInAnyShareComesOutOfRunAndThePoolGoesOn)
{
  WorkerPool pool;
  pool.resize(2);
  for (int round = 0; round < 6; ++round)
  {
    if (round % 2 == 0)
    {
      std::this_thread::sleep_for(kLongEnoughToSleep);
    }
    // The last item is in the last share, which either thread may run.
    const std::size_t count = 1000;
    EXPECT_THROW(pool.parallel_for(count, 2,
                                   [&](std::size_t, std::size_t end) {
                                     if (end == count)
                                     {
                                       throw std::runtime_error("last share");
                                     }
                                   }),
                 std::runtime_error);
    const std::vector<int> hits = hits_of_one_job(pool, count);
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), static_cast<long>(count)) << "round " << round;
  }
}

#if defined(__linux__)
/// The CPUs the calling thread may run on.
std::set<int> allowed_cpus()
{
  cpu_set_t mask;
  std::set<int> cpus;
  if (sched_getaffinity(0, sizeof mask, &mask) == 0)
  {
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    {
      if (CPU_ISSET(cpu, &mask))
      {
        cpus.insert(cpu);
      }
    }
  }
  return cpus;
}

/// The worker's mask, read inside a team job that wakes it from sleep,
/// in each of `rounds` rounds.
std::vector<std::set<int>> worker_masks_after_sleeps(WorkerPool& pool, int rounds)
{
  std::vector<std::set<int>> masks;
  for (int round = 0; round < rounds; ++round)
  {
    std::this_thread::sleep_for(kLongEnoughToSleep);
    std::set<int> worker_mask;
    pool.run_team([&](std::size_t worker) {
      if (worker == 1)
      {
        worker_mask = allowed_cpus();
      }
      pool.sync();
    });
    masks.push_back(worker_mask);
  }
  return masks;
}

TEST(WorkerPool, AWorkerWokenFromSleepKeepsEveryCpuItMayUse)
{
  cpu_set_t original;
  ASSERT_EQ(sched_getaffinity(0, sizeof original, &original), 0);
  // With the CPUs this process may use, and confined to the one this thread
  // is on, where the worker has nowhere else to go.
  for (const bool confined : {false, true})
  {
    if (confined)
    {
      cpu_set_t one;
      CPU_ZERO(&one);
      CPU_SET(sched_getcpu(), &one);
      ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    }
    const std::set<int> expected = allowed_cpus();  // the worker inherits this thread's mask
    {
      WorkerPool pool;
      pool.resize(2);
      for (const std::set<int>& mask : worker_masks_after_sleeps(pool, 5))
      {
        EXPECT_EQ(mask, expected) << (confined ? "confined to one CPU" : "every CPU");
      }
    }
    ASSERT_EQ(sched_setaffinity(0, sizeof original, &original), 0);
  }
}
#endif

}  // namespace
}  // namespace detail
}  // namespace collision2d
