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
// Loops shorter than this run on one thread. A relaxation step is four short loops, each
// ending in a barrier; below some 10^4 items the barriers cost more than the threads save,
// and on a busy machine a barrier waiting for a descheduled thread costs a whole time slice.
// A variable, not a constant, so that the thread-invariance tests can run small meshes in
// parallel.
inline std::size_t parallel_minimum = 16384;

// Runs body(i, sums) for every i in [0, n), where body adds its terms into sums (K of them),
// and returns the K totals.
template <std::size_t K, class Body>
std::array<double, K> blocked_sum(std::size_t n, Body body) {
  const std::size_t blocks = (n + kReductionBlock - 1) / kReductionBlock;
  // Reused by the calling thread, so a step allocates nothing; bound to a reference here so
  // that the team writes the caller's buffer, not thread-local copies of its own.
  thread_local std::vector<std::array<double, K>> buffer;
  buffer.assign(blocks, std::array<double, K>{});
  std::vector<std::array<double, K>>& partial = buffer;
#pragma omp parallel for schedule(static) if (n > parallel_minimum)
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
