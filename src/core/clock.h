#pragma once
// Wall time and CPU time, measured the same way by every front end and stage.
#include <chrono>

namespace fp {

// The clock of every wall-time measurement: it never goes backwards, unlike the system clock.
using SteadyClock = std::chrono::steady_clock;

// Seconds from `start` to now.
double secondsSince(SteadyClock::time_point start);
// Seconds from `from` to `to` (negative when `to` comes first).
double secondsBetween(SteadyClock::time_point from, SteadyClock::time_point to);

// CPU time, user plus system, of every thread of this process so far: llvmpipe rasterises and the BVH
// builds on threads of this process, so this is what a render costs, not just the CPU of the thread that
// waits for it. Only differences of two readings mean anything.
double processCpuSeconds();
// CPU time of the calling thread alone (the native reference traces on one thread).
double threadCpuSeconds();

}  // namespace fp
