// core/clock.h: wall time on the steady clock, CPU time of the process and of one thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "core/clock.h"

namespace fp {
namespace {

// Spins on the calling thread until it has used `seconds` of its own CPU time.
void burnCpu(double seconds) {
    volatile double sink = 0.0;
    double start = threadCpuSeconds();
    while (threadCpuSeconds() - start < seconds)
        for (int i = 0; i < 10000; ++i) sink = sink + 1e-9 * i;
}

TEST(Clock, SecondsBetweenIsTheDifferenceInSeconds) {
    SteadyClock::time_point t0{};
    EXPECT_DOUBLE_EQ(secondsBetween(t0, t0 + std::chrono::milliseconds(1500)), 1.5);
    EXPECT_DOUBLE_EQ(secondsBetween(t0 + std::chrono::microseconds(250), t0), -250e-6);
}

TEST(Clock, SecondsSinceCountsWallTimeAsleep) {
    auto start = SteadyClock::now();
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    double elapsed = secondsSince(start);
    EXPECT_GE(elapsed, 0.030);
    EXPECT_LT(elapsed, 5.0);
}

// Sleeping costs no CPU; spinning costs CPU on both clocks.
TEST(Clock, CpuClocksCountWorkAndNotSleep) {
    double process = processCpuSeconds(), thread = threadCpuSeconds();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_LT(processCpuSeconds() - process, 0.05);
    EXPECT_LT(threadCpuSeconds() - thread, 0.05);

    process = processCpuSeconds();
    burnCpu(0.05);
    EXPECT_GE(processCpuSeconds() - process, 0.05);
}

// The process clock counts every thread's CPU time, the thread clock only the caller's: the reason the
// benchmark measures llvmpipe (which rasterises on threads of its own) on the process clock.
TEST(Clock, ProcessCpuIncludesOtherThreadsAndThreadCpuDoesNot) {
    double process = processCpuSeconds(), thread = threadCpuSeconds();
    std::thread worker([] { burnCpu(0.1); });
    worker.join();
    EXPECT_GE(processCpuSeconds() - process, 0.1);
    EXPECT_LT(threadCpuSeconds() - thread, 0.05);
}

}  // namespace
}  // namespace fp
