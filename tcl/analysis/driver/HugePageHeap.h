// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace dabs::analysis {

/// Puts malloc's heap on 2 MB pages (Linux transparent huge pages) as a model grows. A model's
/// state is in many small blocks on that heap (every fiber group's states and responses), and
/// every iteration reads all of them: a long viaduct's run to tens of megabytes, which on 4 KB
/// pages take a TLB miss every 64 fibers or so. Debian's kernels give huge pages to memory that
/// asks for them (`madvise` mode), and only to memory not yet touched: so malloc is set to grow
/// its heap 32 MB ahead of what it hands out (and to serve blocks up to 32 MB from it, and to give
/// back only a free top of 128 MB or more), and each call asks for huge pages on the heap grown
/// since the last one, most of which nothing has touched yet. The interpreter calls it after
/// every command and once an analysis has built its model. Only where the data sit changes, never a
/// number. Where the system does not offer huge pages the requests fail and nothing changes.
class HugePageHeap {
 public:
  /// Sets malloc's growth as above (for the whole process; the same values again for a second
  /// interpreter) and marks the heap's present end.
  HugePageHeap();
  /// Asks for huge pages on the heap grown since the last call; one comparison of the heap's end
  /// otherwise.
  void adviseGrowth();

 private:
  std::uintptr_t advisedEnd_ = 0;  ///< the heap up to here was asked for (or was there before)
};

}  // namespace dabs::analysis
