// Reductions whose result does not depend on the thread count: the index range is cut into
// fixed blocks, each block is summed in order by one thread, and the block sums are added
// in block order: no reduction whose order depends on the schedule (doc/threading.md "Sums").
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "ycore/state/ownership.h"

namespace ydry {

constexpr std::size_t kReductionBlock = 4096;

// Runs body(i, sums) for every i in [0, n), where body adds its terms into sums (K of them),
// and returns the K totals. A block of `Block` indices is summed by the thread that owns its
// middle index (owner_begin: an Ownership table for n, or none for an even cut); the block
// size is part of the result's bits, so a loop keeps its size.
template <std::size_t K, std::size_t Block = kReductionBlock, class Body>
std::array<double, K> blocked_sum(std::size_t n, Body body, const std::vector<std::size_t>& owner_begin = {}) {
  const std::size_t blocks = (n + Block - 1) / Block;
  // Reused by the calling thread, so a step allocates nothing; bound to a reference here so
  // that the team writes the caller's buffer, not thread-local copies of its own.
  thread_local std::vector<std::array<double, K>> buffer;
  buffer.assign(blocks, std::array<double, K>{});
  std::vector<std::array<double, K>>& partial = buffer;
#pragma omp parallel if (n > parallel_minimum)
  {
    const IndexRange owned = owned_range(owner_begin, n);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t begin = b * Block, end = std::min(n, begin + Block);
      const std::size_t middle = begin + (end - begin) / 2;
      if (middle < owned.begin || middle >= owned.end) continue;
      std::array<double, K> sums{};
      for (std::size_t i = begin; i < end; ++i) body(i, sums);
      partial[b] = sums;
    }
  }
  std::array<double, K> total{};
  for (const auto& p : partial)
    for (std::size_t k = 0; k < K; ++k) total[k] += p[k];
  return total;
}

}  // namespace ydry
