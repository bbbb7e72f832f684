// The World's worker threads (worker_pool.h): every item of a job runs
// exactly once whether the workers are awake, asleep or late; a staged job
// runs every share of every stage once, each stage after the one before (on
// the calling thread alone when too small to share); an exception comes out
// of run() and run_stages(); a worker that moves off the calling thread's
// CPU keeps every CPU it may use.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
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

TEST(WorkerPool, AStagedJobRunsEachShareOnceAndEachStageAfterTheOneBefore)
{
  constexpr std::size_t kStages = 7;
  for (const int workers : {1, 2, 4})
  {
    WorkerPool pool;
    pool.resize(workers);
    const std::size_t shares = static_cast<std::size_t>(workers);
    for (int round = 0; round < 40; ++round)
    {
      if (round % 8 == 0)
      {
        std::this_thread::sleep_for(kLongEnoughToSleep);
      }
      // Each share writes its own slot of its stage; a share of the next
      // stage adds up every slot of this one, which must all be written.
      std::vector<std::atomic<int>> runs(kStages * shares);
      std::vector<long> slot(kStages * shares, 0);
      std::atomic<int> early{0};
      pool.run_stages(kStages, [&](std::size_t stage, std::size_t share, std::size_t n) {
        ASSERT_EQ(n, shares);
        runs[stage * n + share].fetch_add(1);
        long sum = 1;
        for (std::size_t p = 0; stage > 0 && p < n; ++p)
        {
          early += slot[(stage - 1) * n + p] == 0 ? 1 : 0;
          sum += slot[(stage - 1) * n + p];
        }
        slot[stage * n + share] = sum;
      });
      EXPECT_EQ(early.load(), 0) << workers << " workers, round " << round;
      for (std::size_t k = 0; k < runs.size(); ++k)
      {
        ASSERT_EQ(runs[k].load(), 1) << workers << " workers, round " << round << ", stage " << k / shares;
      }
      // Stage s's slots each hold 1 + shares * (stage s - 1's), from 1.
      long expected = 1;
      for (std::size_t stage = 0; stage < kStages; ++stage)
      {
        EXPECT_EQ(slot[stage * shares + shares - 1], expected) << workers << " workers, stage " << stage;
        expected = 1 + static_cast<long>(shares) * expected;
      }
    }
  }
}

TEST(WorkerPool, AStagedJobTooSmallToShareRunsWholeOnTheCallingThread)
{
  WorkerPool pool;
  pool.resize(2);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<int> runs(3, 0);
  bool elsewhere = false;
  pool.run_stages(
      3,
      [&](std::size_t stage, std::size_t share, std::size_t n) {
        EXPECT_EQ(share, 0U);
        EXPECT_EQ(n, 1U);
        ++runs[stage];
        elsewhere = elsewhere || std::this_thread::get_id() != caller;
      },
      false);
  EXPECT_EQ(runs, std::vector<int>(3, 1));
  EXPECT_FALSE(elsewhere);
}

TEST(WorkerPool, AnExceptionInAnyStageComesOutOfRunStagesAndThePoolGoesOn)
{
  WorkerPool pool;
  pool.resize(2);
  for (std::size_t throwing_stage = 0; throwing_stage < 3; ++throwing_stage)
  {
    std::atomic<int> after{0};
    EXPECT_THROW(pool.run_stages(4,
                                 [&](std::size_t stage, std::size_t share, std::size_t) {
                                   if (stage == throwing_stage && share == 1)
                                   {
                                     throw std::runtime_error("stage share");
                                   }
                                   after += stage > throwing_stage ? 1 : 0;
                                 }),
                 std::runtime_error);
    EXPECT_EQ(after.load(), 0) << "a stage after the one that threw ran";
    const std::vector<int> hits = hits_of_one_job(pool, 1000);
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), 1000L) << "stage " << throwing_stage;
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

/// The worker's mask, read in the second share of a job that wakes it from
/// sleep, in each of `rounds` rounds: the first share, which the calling
/// thread runs, waits until another thread has run the second (a failed
/// test rather than a hang if none does within a few seconds).
std::vector<std::set<int>> worker_masks_after_sleeps(WorkerPool& pool, int rounds)
{
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::set<int>> masks;
  for (int round = 0; round < rounds; ++round)
  {
    std::this_thread::sleep_for(kLongEnoughToSleep);
    std::set<int> worker_mask;
    std::atomic<bool> second_ran{false};
    pool.parallel_for(2, 2, [&](std::size_t begin, std::size_t) {
      if (begin == 1)
      {
        if (std::this_thread::get_id() != caller)
        {
          worker_mask = allowed_cpus();
        }
        second_ran.store(true);
        return;
      }
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
      while (!second_ran.load() && std::chrono::steady_clock::now() < give_up)
      {
        std::this_thread::yield();
      }
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
