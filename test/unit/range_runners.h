// Test support: RangeRunners (broad_phase.h) that run a job's parts on the
// calling thread, so a test can share a pass in parts without threads.
#pragma once

#include <cstddef>

#include "collision2d/broad_phase.h"

namespace collision2d
{
namespace test
{
/// Three parts, run one at a time, last first: parts that finish in another
/// order than their items'.
class ReversedRunner : public RangeRunner
{
public:
  int workers() const override { return 3; }
  void run(std::size_t count, Job job, void* context) override
  {
    for (std::size_t k = count; k > 0; --k)
    {
      job(context, k - 1, k);
    }
  }
};

}  // namespace test
}  // namespace collision2d
