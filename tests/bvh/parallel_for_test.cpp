// The BVH builder's fork-join loop: every job runs exactly once, whatever the thread count, and a job's
// exception reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "bvh/parallel_for.h"

namespace fp {
namespace {

TEST(ParallelFor, RunsEveryJobOnce) {
    for (int threads : {0, 1, 2, 5}) {
        for (size_t jobs : {size_t(0), size_t(1), size_t(3), size_t(1000)}) {
            std::vector<std::atomic<int>> runs(jobs);
            detail::parallelFor(threads, jobs, [&](size_t i) { ++runs[i]; });
            for (size_t i = 0; i < jobs; ++i)
                EXPECT_EQ(runs[i].load(), 1)
                    << "job " << i << " of " << jobs << ", " << threads << " threads";
        }
    }
}

TEST(ParallelFor, RethrowsAJobsException) {
    for (int threads : {1, 2, 4}) {
        auto throwing = [](size_t i) {
            if (i == 7) throw std::runtime_error("job 7");
        };
        EXPECT_THROW(detail::parallelFor(threads, 100, throwing), std::runtime_error)
            << threads << " threads";
    }
}

}  // namespace
}  // namespace fp
