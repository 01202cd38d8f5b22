// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace dabs::analysis {

/// Backs malloc's heap with 2 MB pages (Linux transparent huge pages) as a model grows, before its
/// analyses run. A model's state is in many small blocks on that heap (every fiber group's states
/// and responses), and every iteration reads all of them: a long viaduct's run to tens of
/// megabytes, which on 4 KB pages take a TLB miss every 64 fibers or so. On 2 MB pages the 100-span
/// benchmark bridge (about 40 MB of heap) ran 8 % faster (medians of 9 alternating runs; the same
/// as GLIBC_TUNABLES=glibc.malloc.hugetlb=1, which does it for the whole heap from the start);
/// models that fit in the cache are unchanged. Debian's kernels give huge pages to memory that asks
/// for them (`madvise` mode): each call asks for the heap's growth since the last, in whole 2 MB
/// pages, and has the kernel move what is already there onto them (MADV_COLLAPSE, Linux 6.1).
/// Only where the data sit changes, never a number. Where the system does not offer huge pages
/// the requests fail and nothing changes.
class HugePageHeap {
 public:
  /// Asks for huge pages on the heap grown by a whole 2 MB page or more since the last call;
  /// cheap otherwise (one comparison of the heap's end). The heap is the process's: a second
  /// interpreter's analyses ask again for what the first one's asked for, once.
  void backGrowth();

 private:
  std::uintptr_t start_ = 0;      ///< the heap's start (0 before it is read)
  std::uintptr_t backedEnd_ = 0;  ///< the heap up to here (a 2 MB boundary) was asked for
};

}  // namespace dabs::analysis
