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

/// Where the heap starts: the lowest address of the `[heap]` lines of /proc/self/maps (asking for
/// huge pages on part of the heap splits it into several such lines); 0 when it cannot be read.
std::uintptr_t heapStart() {
  std::FILE* maps = std::fopen("/proc/self/maps", "r");
  if (maps == nullptr) return 0;
  std::uintptr_t lowest = 0;
  char line[512];
  while (std::fgets(line, sizeof line, maps) != nullptr) {
    if (std::strstr(line, "[heap]") == nullptr) continue;
    unsigned long lo = 0;
    if (std::sscanf(line, "%lx-", &lo) == 1 && (lowest == 0 || lo < lowest)) lowest = lo;
  }
  std::fclose(maps);
  return lowest;
}

}  // namespace

void HugePageHeap::backGrowth() {
  // sbrk(0) is the heap's end as glibc keeps it (no system call). A heap that shrank and grows
  // again has lost the request on the part it gave back.
  const auto brk = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t last = brk & ~(kHugePage - 1);
  if (last < backedEnd_) backedEnd_ = last;
  if (last < backedEnd_ + kHugePage) return;
  // The heap's start is read once; afterwards the growth starts where the last request ended
  // (a 2 MB boundary), never below the start.
  if (start_ == 0) start_ = heapStart();
  const std::uintptr_t begin = backedEnd_ > start_ ? backedEnd_ : start_;
  backedEnd_ = last;  // also when the start cannot be read: that part is not tried again
  if (start_ == 0) return;
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  if (last <= first) return;
  void* const pages = reinterpret_cast<void*>(first);
  const std::size_t length = last - first;
  if (madvise(pages, length, MADV_HUGEPAGE) != 0) return;
  // Best effort: a kernel without it (EINVAL), or without free huge pages, leaves the pages as
  // they are. It also backs the part of those pages that malloc has not handed out yet (the
  // heap's top below its last whole 2 MB page).
  static_cast<void>(madvise(pages, length, kCollapse));
}

#else

void HugePageHeap::backGrowth() {}

#endif

}  // namespace dabs::analysis
