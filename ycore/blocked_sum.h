// Reductions whose result does not depend on the thread count: the index range is cut into
// fixed blocks, each block is summed in order by one thread, and the block sums are added
// in block order (DESIGN section 6: no reductions whose order depends on the schedule).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace ydry {

constexpr std::size_t kReductionBlock = 4096;
// Loops shorter than this run on one thread: starting a team costs more than they do, and
// on an oversubscribed machine (tests in parallel) spinning teams of tiny loops crawl.
constexpr std::size_t kParallelMinimum = 1024;

// Runs body(i, sums) for every i in [0, n), where body adds its terms into sums (K of them),
// and returns the K totals.
template <std::size_t K, class Body>
std::array<double, K> blocked_sum(std::size_t n, Body body) {
  const std::size_t blocks = (n + kReductionBlock - 1) / kReductionBlock;
  std::vector<std::array<double, K>> partial(blocks);
#pragma omp parallel for schedule(static) if (blocks > 1)
  for (std::size_t b = 0; b < blocks; ++b) {
    std::array<double, K> sums{};
    const std::size_t end = std::min(n, (b + 1) * kReductionBlock);
    for (std::size_t i = b * kReductionBlock; i < end; ++i) body(i, sums);
    partial[b] = sums;
  }
  std::array<double, K> total{};
  for (const auto& p : partial)
    for (std::size_t k = 0; k < K; ++k) total[k] += p[k];
  return total;
}

}  // namespace ydry
