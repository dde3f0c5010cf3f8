#pragma once
// A std::vector allocator for the large arrays the BVH builder fills: transparent huge pages for
// allocations of 2 MiB or more.
//
// Why: on the virtual machines fragpath is benchmarked on, the first touch of each 4 KiB page costs
// 10 to 25 µs (a fault that goes through the hypervisor; docs/optimisation-log.md, "BVH build: first
// touch"), and a build of a million triangles writes about 70 MB of fresh memory: its page faults cost as
// much as the build's own work. madvise(MADV_HUGEPAGE) asks for one fault per 2 MiB instead of 512, where
// the kernel's transparent huge pages are enabled ("madvise" or "always" in
// /sys/kernel/mm/transparent_hugepage/enabled); elsewhere it is a no-op, and the memory is ordinary.
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fp {

template <class T>
struct HugePageAllocator {
    using value_type = T;
    static constexpr size_t kHugePage = size_t(2) << 20;

    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes));
        const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        void* p = std::aligned_alloc(kHugePage, rounded);  // huge pages need 2 MiB-aligned ranges
        if (!p) throw std::bad_alloc();
#if defined(__linux__)
        madvise(p, rounded, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) noexcept {
        if (n * sizeof(T) < kHugePage)
            ::operator delete(p);
        else
            std::free(p);
    }
};

template <class T, class U>
bool operator==(const HugePageAllocator<T>&, const HugePageAllocator<U>&) {
    return true;
}
template <class T, class U>
bool operator!=(const HugePageAllocator<T>&, const HugePageAllocator<U>&) {
    return false;
}

template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace fp
