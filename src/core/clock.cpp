#include "core/clock.h"

#include <time.h>

namespace fp {

namespace {

// Both CPU clocks are POSIX clock_gettime clocks, not std::clock() or getrusage(): std::clock() returns a
// clock_t that wraps after about 36 minutes where it is 32 bits (POSIX fixes CLOCKS_PER_SEC at 1e6), and the
// C standard does not even say it is CPU time of all threads (on Windows it is wall time); getrusage() has
// microsecond fields and, on Linux, splits user from system time by sampling ticks. CLOCK_PROCESS_CPUTIME_ID
// is the scheduler's own count of the time every thread of the process ran, in nanoseconds, and
// CLOCK_THREAD_CPUTIME_ID the same for one thread, so process and thread figures come from one source.
double cpuSeconds(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

double secondsSince(SteadyClock::time_point start) {
    return secondsBetween(start, SteadyClock::now());
}

double secondsBetween(SteadyClock::time_point from, SteadyClock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

double processCpuSeconds() {
    return cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
}

double threadCpuSeconds() {
    return cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
}

}  // namespace fp
