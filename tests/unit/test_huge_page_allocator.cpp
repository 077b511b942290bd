// The allocator of the engine's large arrays: arrays of 2 MiB and more start on a huge-page
// boundary (the kernel can back them with huge pages only then), smaller ones keep the alignment
// of their type, and contents survive growth like any vector's.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "engine/particle_record.hpp"
#include "memory/huge_page_allocator.hpp"

namespace granule {
namespace {

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

TEST(HugePageAllocator, LargeArraysStartOnAHugePage) {
  HugePageVector<double> values(kHugePage / sizeof(double) + 1);
  EXPECT_EQ(address(values.data()) % kHugePage, 0u);
}

TEST(HugePageAllocator, SmallArraysKeepTheirTypesAlignment) {
  for (std::size_t n : {1u, 7u, 1000u}) {
    HugePageVector<ParticleRecord<3>> records(n);
    EXPECT_EQ(address(records.data()) % 64, 0u) << n << " records";
  }
}

TEST(HugePageAllocator, SphereRecordsAreLineAlignedAtEverySize) {
  // A 64-byte record at an offset of 16 would straddle two cache lines.
  for (std::size_t n : {100u, 108000u}) {
    HugePageVector<ParticleRecord<3>> records(n);
    for (std::size_t i : {std::size_t{0}, std::size_t{1}, n - 1}) EXPECT_EQ(address(&records[i]) % 64, 0u) << i;
  }
}

TEST(HugePageAllocator, GrowingAcrossTheThresholdKeepsTheContents) {
  HugePageVector<std::int32_t> values;
  const std::size_t n = 3 * kHugePage / sizeof(std::int32_t);
  for (std::size_t i = 0; i < n; ++i) values.push_back(static_cast<std::int32_t>(i));
  std::vector<std::int32_t> expected(n);
  std::iota(expected.begin(), expected.end(), 0);
  EXPECT_TRUE(std::equal(values.begin(), values.end(), expected.begin()));
}

}  // namespace
}  // namespace granule
