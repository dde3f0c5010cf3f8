// HugePageVector behaves as a std::vector whatever size it grows to, and its large blocks start on a
// 2 MiB boundary, which transparent huge pages need.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/huge_page_allocator.h"

namespace fp {
namespace {

TEST(HugePageAllocator, KeepsContentsWhileGrowingPastTheHugePageSize) {
    HugePageVector<uint32_t> v;
    const uint32_t n = 3u << 20;  // 12 MiB of elements, reached through small and large blocks
    for (uint32_t i = 0; i < n; ++i) v.push_back(i * 2654435761u);
    ASSERT_EQ(v.size(), n);
    for (uint32_t i = 0; i < n; ++i) ASSERT_EQ(v[i], i * 2654435761u) << i;
}

TEST(HugePageAllocator, LargeBlocksAreAlignedToHugePages) {
    HugePageVector<double> large(HugePageAllocator<double>::kHugePage / sizeof(double) + 1, 1.5);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % HugePageAllocator<double>::kHugePage, 0u);
    EXPECT_EQ(large.back(), 1.5);
    HugePageVector<double> small(16, 2.5);
    EXPECT_EQ(small[15], 2.5);
    HugePageVector<double> copy = large;  // copies allocate too
    EXPECT_EQ(copy, large);
}

}  // namespace
}  // namespace fp
