#include "sbsim/kernel/HugePageAllocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace sbsim::kernel {
namespace {

template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

TEST(HugePageAllocator, LargeBlocksStartOnAHugePage) {
    HugeVector<std::uint64_t> big(HugePageAllocator<std::uint64_t>::kHugePage);  // 16 MiB
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % HugePageAllocator<std::uint64_t>::kHugePage, 0u);
    // Grown from small to large through every size, the values stay where they were put.
    HugeVector<std::uint64_t> grown;
    for (std::uint64_t k = 0; k < 1'000'000; ++k) grown.push_back(k * 7);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(grown.data()) % HugePageAllocator<std::uint64_t>::kHugePage, 0u);
    for (std::uint64_t k = 0; k < grown.size(); k += 997) ASSERT_EQ(grown[k], k * 7);
}

TEST(HugePageAllocator, SmallBlocksKeepTheirTypesAlignment) {
    struct alignas(64) Line {
        double x[8];
    };
    HugeVector<Line> few(3);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(few.data()) % 64, 0u);
}

}  // namespace
}  // namespace sbsim::kernel
