#pragma once
// The one threading primitive of the BVH builder (internal to src/bvh): a fork-join loop over jobs.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace fp::detail {

// Runs job(i) for every i in [0, jobCount) on up to threadCount threads, the caller's included, and
// returns when all are done. Threads take the next index from a shared counter, so jobs listed largest
// first balance well. Which thread runs a job is unspecified: jobs must write disjoint data. The first
// exception a job throws is rethrown here once every thread has stopped.
template <class Job>
void parallelFor(int threadCount, size_t jobCount, const Job& job) {
    const size_t threads = std::min(size_t(std::max(threadCount, 1)), jobCount);
    if (threads <= 1) {
        for (size_t i = 0; i < jobCount; ++i) job(i);
        return;
    }
    std::atomic<size_t> next{0};
    std::exception_ptr error;
    std::mutex errorMutex;
    auto work = [&] {
        try {
            for (size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < jobCount;) job(i);
        } catch (...) {
            std::lock_guard<std::mutex> lock(errorMutex);
            if (!error) error = std::current_exception();
            next.store(jobCount);  // the others stop after their current job
        }
    };
    std::vector<std::thread> helpers;
    helpers.reserve(threads - 1);
    for (size_t t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back(work);
        } catch (const std::system_error&) {
            break;  // no more threads to be had: the ones running share the jobs
        }
    }
    work();
    for (std::thread& t : helpers) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace fp::detail
