// SPDX-License-Identifier: MIT
// HugePageHeap against what the kernel reports of the process: a heap grown by small blocks, 2 MB
// at a time with adviseGrowth after each (as the interpreter calls it after each command), is
// mostly on 2 MB pages where the system gives them on request only (transparent huge pages in
// `madvise` mode), with no copying: malloc grows the heap ahead of the blocks, and the growth is
// asked for before the blocks touch it. The blocks keep their contents.

#include "tcl/analysis/driver/HugePageHeap.h"

#include <gtest/gtest.h>

// Linux with glibc only: elsewhere HugePageHeap does nothing, and there is nothing to show.
#if defined(__linux__) && defined(__GLIBC__)
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

/// Why this system cannot show what HugePageHeap does, or "" when it can: huge pages must be
/// given on request only (in `always` mode every growth gets them anyway, in `never` none does),
/// and an aligned 2 MB page asked for before it is touched must get one (memory too fragmented
/// counts as no).
std::string whyNotShown() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  if (!std::getline(mode, text) || text.find("[madvise]") == std::string::npos)
    return "transparent huge pages not in madvise mode";
  const long before = anonHugePagesKb();
  if (before < 0) return "no /proc/self/smaps_rollup";
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  void* region =
      mmap(nullptr, 2 * kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (region == MAP_FAILED) return "no memory to probe";
  auto* aligned = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(region) + kHuge - 1) &
                                          ~(std::uintptr_t{kHuge} - 1));
  const bool advised = madvise(aligned, kHuge, MADV_HUGEPAGE) == 0;
  std::memset(aligned, 1, kHuge);
  const bool given = advised && anonHugePagesKb() - before >= 2048;
  munmap(region, 2 * kHuge);
  return given ? "" : "no huge page given on request";
}

/// 2 MB in blocks of 8 KB, below malloc's mmap threshold: they come from the heap. The first byte
/// of each block and every 1021st are its number modulo 251.
void growHeap(std::vector<std::unique_ptr<char[]>>& blocks) {
  constexpr std::size_t kBlock = 8192, kBlocks = 256;
  for (std::size_t i = 0; i < kBlocks; ++i) {
    const std::size_t number = blocks.size();
    blocks.push_back(std::make_unique<char[]>(kBlock));
    std::memset(blocks.back().get(), static_cast<int>(number % 251), kBlock);
  }
}

// 96 MB in 48 "commands": three times the 32 MB malloc grows the heap ahead, so the heap grows
// during the test and a request placed only on its first growth fails. Blocks freed before the
// test (already touched, on 4 KB pages) may take up to about 16 MB of it.
TEST(HugePageHeapTest, HeapGrownBetweenCallsLandsOnHugePages) {
  if (const std::string why = whyNotShown(); !why.empty()) GTEST_SKIP() << why;
  HugePageHeap heap;
  const auto heapEndBefore = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const long before = anonHugePagesKb();
  constexpr int kCommands = 48;
  std::vector<std::unique_ptr<char[]>> blocks;
  blocks.reserve(kCommands * 256);
  for (int command = 0; command < kCommands; ++command) {
    growHeap(blocks);
    heap.adviseGrowth();
  }
  if (reinterpret_cast<std::uintptr_t>(sbrk(0)) < heapEndBefore + (std::uintptr_t{64} << 20))
    GTEST_SKIP() << "the heap grew by less than 64 MB: an allocator that does not grow it with "
                    "sbrk (a sanitizer's, say), or freed blocks reused";
  // At least 60 of the 96 MB (what each heap growth touches before the next call, the 2 MB pages
  // at the ends and reused blocks stay on 4 KB pages; one request on the first growth alone
  // gives about 30 MB, no growth ahead none).
  EXPECT_GE(anonHugePagesKb() - before, 60 * 1024);
  for (std::size_t i = 0; i < blocks.size(); i += 97)
    for (std::size_t k = 0; k < 8192; k += 1021)
      ASSERT_EQ(blocks[i][k], static_cast<char>(i % 251)) << "block " << i << " byte " << k;
}

}  // namespace
}  // namespace dabs::analysis

#endif
