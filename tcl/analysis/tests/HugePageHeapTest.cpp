// SPDX-License-Identifier: MIT
// HugePageHeap against what the kernel reports of the process: after the heap grows by 16 MB of
// small blocks, backGrowth has them on 2 MB pages where the system offers them, and leaves the
// blocks' contents as they were.

#include "tcl/analysis/driver/HugePageHeap.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace dabs::analysis {
namespace {

/// AnonHugePages of /proc/self/smaps_rollup, in kB (-1 when it cannot be read).
long anonHugePagesKb() {
  std::ifstream rollup("/proc/self/smaps_rollup");
  std::string key;
  long value = -1;
  while (rollup >> key) {
    if (key == "AnonHugePages:") {
      rollup >> value;
      return value;
    }
    rollup.ignore(1 << 10, '\n');
  }
  return -1;
}

/// Whether this system collapses memory onto huge pages on request: transparent huge pages not
/// `never`, and MADV_COLLAPSE (25) known to the kernel.
bool systemCollapses() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  if (!std::getline(mode, text) || text.find("[never]") != std::string::npos) return false;
  // A huge page's worth of touched memory, aligned, asked to collapse: EINVAL where the kernel
  // does not know the request.
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  void* region =
      mmap(nullptr, 2 * kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (region == MAP_FAILED) return false;
  auto* aligned = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(region) + kHuge - 1) &
                                          ~(std::uintptr_t{kHuge} - 1));
  std::memset(aligned, 1, kHuge);
  const bool known = madvise(aligned, kHuge, 25) == 0 || errno != EINVAL;
  munmap(region, 2 * kHuge);
  return known;
}

TEST(HugePageHeapTest, GrowthOfTheHeapLandsOnHugePages) {
  if (!systemCollapses()) GTEST_SKIP() << "no transparent huge pages on request here";
  HugePageHeap heap;
  heap.backGrowth();  // what the heap holds before the test is not the test's
  const long before = anonHugePagesKb();
  ASSERT_GE(before, 0);
  // 16 MB in blocks of 8 KB, below malloc's mmap threshold: they come from the heap.
  const auto heapEndBefore = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::vector<std::unique_ptr<char[]>> blocks;
  constexpr std::size_t kBlock = 8192, kBlocks = 2048;
  for (std::size_t i = 0; i < kBlocks; ++i) {
    blocks.push_back(std::make_unique<char[]>(kBlock));
    std::memset(blocks.back().get(), static_cast<int>(i % 251), kBlock);
  }
  const auto heapEndAfter = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (heapEndAfter < heapEndBefore + (std::uintptr_t{8} << 20))
    GTEST_SKIP() << "this allocator does not grow the heap (a sanitizer's, say)";
  heap.backGrowth();
  // At least half of the growth, less a huge page at each end, is on huge pages now.
  EXPECT_GE(anonHugePagesKb() - before, 4096);
  for (std::size_t i = 0; i < kBlocks; i += 97)
    for (std::size_t k = 0; k < kBlock; k += 1021)
      ASSERT_EQ(blocks[i][k], static_cast<char>(i % 251)) << "block " << i << " byte " << k;
}

TEST(HugePageHeapTest, CallsWithoutGrowthChangeNothing) {
  HugePageHeap heap;
  heap.backGrowth();
  const long before = anonHugePagesKb();
  for (int i = 0; i < 1000; ++i) heap.backGrowth();
  EXPECT_EQ(anonHugePagesKb(), before);
}

}  // namespace
}  // namespace dabs::analysis
