// SPDX-License-Identifier: MIT
#include "tcl/analysis/driver/HugePageHeap.h"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#endif

namespace dabs::analysis {

#if defined(__linux__) && defined(MADV_HUGEPAGE)

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
/// MADV_COLLAPSE of the kernel's interface (asm-generic/mman-common.h, Linux 6.1), which glibc
/// 2.36's <sys/mman.h> does not name yet.
constexpr int kCollapse = 25;

/// The heap's address range from /proc/self/maps ([0, 0) when it cannot be read).
void heapRange(std::uintptr_t& begin, std::uintptr_t& end) {
  begin = end = 0;
  std::FILE* maps = std::fopen("/proc/self/maps", "r");
  if (maps == nullptr) return;
  char line[512];
  while (std::fgets(line, sizeof line, maps) != nullptr) {
    if (std::strstr(line, "[heap]") == nullptr) continue;
    unsigned long lo = 0, hi = 0;
    if (std::sscanf(line, "%lx-%lx", &lo, &hi) == 2) {
      begin = lo;
      end = hi;
    }
    break;
  }
  std::fclose(maps);
}

}  // namespace

void HugePageHeap::backGrowth() {
  // sbrk(0) is the heap's end as glibc keeps it (no system call).
  const auto brk = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (brk < backedEnd_ + kHugePage) return;
  std::uintptr_t begin = 0, end = 0;
  heapRange(begin, end);
  if (end == 0) return;
  if (backedEnd_ > begin) begin = backedEnd_;
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = end & ~(kHugePage - 1);
  backedEnd_ = end;
  if (last <= first) return;
  void* const start = reinterpret_cast<void*>(first);
  const std::size_t length = last - first;
  if (madvise(start, length, MADV_HUGEPAGE) != 0) return;
  // Best effort: a kernel without it (EINVAL), or without free huge pages, leaves the pages as
  // they are.
  static_cast<void>(madvise(start, length, kCollapse));
}

#else

void HugePageHeap::backGrowth() {}

#endif

}  // namespace dabs::analysis
