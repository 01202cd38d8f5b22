// SPDX-License-Identifier: MIT
// HugePageHeap against what the kernel reports of the process: each time the heap grows by 16 MB
// of small blocks, backGrowth has the growth on 2 MB pages where the system gives them on request
// only (transparent huge pages in `madvise` mode, with MADV_COLLAPSE), and the blocks keep their
// contents.

#include "tcl/analysis/driver/HugePageHeap.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

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

/// Why this system cannot show what backGrowth does, or "" when it can: huge pages must be given
/// on request only (in `always` mode every growth gets them anyway, in `never` none does), and a
/// touched, aligned 2 MB page must collapse on request (MADV_COLLAPSE, 25, Linux 6.1; EAGAIN or
/// ENOMEM when memory is too fragmented count as no).
std::string whyNotShown() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  if (!std::getline(mode, text) || text.find("[madvise]") == std::string::npos)
    return "transparent huge pages not in madvise mode";
  if (anonHugePagesKb() < 0) return "no /proc/self/smaps_rollup";
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  void* region =
      mmap(nullptr, 2 * kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (region == MAP_FAILED) return "no memory to probe";
  auto* aligned = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(region) + kHuge - 1) &
                                          ~(std::uintptr_t{kHuge} - 1));
  std::memset(aligned, 1, kHuge);
  const bool collapses = madvise(aligned, kHuge, 25) == 0;
  munmap(region, 2 * kHuge);
  return collapses ? "" : "MADV_COLLAPSE refused";
}

/// 16 MB in blocks of 8 KB, below malloc's mmap threshold: they come from the heap. The first
/// byte of each block and every 1021st are its number modulo 251.
std::vector<std::unique_ptr<char[]>> growHeap(std::size_t& first) {
  constexpr std::size_t kBlock = 8192, kBlocks = 2048;
  static std::size_t counter = 0;
  first = counter;
  std::vector<std::unique_ptr<char[]>> blocks;
  for (std::size_t i = 0; i < kBlocks; ++i, ++counter) {
    blocks.push_back(std::make_unique<char[]>(kBlock));
    std::memset(blocks.back().get(), static_cast<int>(counter % 251), kBlock);
  }
  return blocks;
}

// Three rounds, so that a request placed only on the first growth (or on the part of the heap
// read first) fails the second and third.
TEST(HugePageHeapTest, EachGrowthOfTheHeapLandsOnHugePages) {
  if (const std::string why = whyNotShown(); !why.empty()) GTEST_SKIP() << why;
  HugePageHeap heap;
  heap.backGrowth();  // what the heap holds before the test is not the test's
  std::vector<std::vector<std::unique_ptr<char[]>>> rounds;
  std::vector<std::size_t> firsts;
  for (int round = 0; round < 3; ++round) {
    const auto heapEndBefore = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const long before = anonHugePagesKb();
    std::size_t first = 0;
    rounds.push_back(growHeap(first));
    firsts.push_back(first);
    if (reinterpret_cast<std::uintptr_t>(sbrk(0)) < heapEndBefore + (std::uintptr_t{8} << 20))
      GTEST_SKIP() << "this allocator does not grow the heap (a sanitizer's, say)";
    heap.backGrowth();
    // At least half of the 16 MB, less a 2 MB page at each end, is on huge pages now.
    EXPECT_GE(anonHugePagesKb() - before, 4096) << "round " << round;
  }
  for (std::size_t r = 0; r < rounds.size(); ++r)
    for (std::size_t i = 0; i < rounds[r].size(); i += 97)
      for (std::size_t k = 0; k < 8192; k += 1021)
        ASSERT_EQ(rounds[r][i][k], static_cast<char>((firsts[r] + i) % 251))
            << "round " << r << " block " << i << " byte " << k;
}

}  // namespace
}  // namespace dabs::analysis
