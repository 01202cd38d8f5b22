// SPDX-License-Identifier: MIT
#include "tcl/analysis/driver/HugePageHeap.h"

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace dabs::analysis {

#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)

namespace {

constexpr int kMegabyte = 1 << 20;

std::uintptr_t heapEnd() { return reinterpret_cast<std::uintptr_t>(sbrk(0)); }

}  // namespace

HugePageHeap::HugePageHeap() {
  // 32 MB is glibc's largest mmap threshold on 64-bit systems.
  mallopt(M_MMAP_THRESHOLD, 32 * kMegabyte);
  mallopt(M_TOP_PAD, 32 * kMegabyte);
  mallopt(M_TRIM_THRESHOLD, 128 * kMegabyte);
  advisedEnd_ = heapEnd();
}

void HugePageHeap::adviseGrowth() {
  // sbrk(0) is the heap's end as glibc keeps it (no system call).
  const std::uintptr_t end = heapEnd();
  if (end <= advisedEnd_) {
    advisedEnd_ = end;  // a heap that shrank and grows again is asked for again
    return;
  }
  // madvise takes a page-aligned start (the heap's end is page-aligned as glibc keeps it; the
  // last call's end is rounded down all the same).
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t begin = advisedEnd_ & ~(page - 1);
  advisedEnd_ = end;
  static_cast<void>(madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE));
}

#else

HugePageHeap::HugePageHeap() = default;
void HugePageHeap::adviseGrowth() {}

#endif

}  // namespace dabs::analysis
