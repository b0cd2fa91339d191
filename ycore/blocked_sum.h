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
// Loops shorter than this run on one thread: a relaxation step is five loops, each ending in
// a barrier, and a barrier costs a few microseconds. At 2048 the Peron mesh (10,067
// triangles, 14,053 joints) runs every loop on both cores, 1.6x faster than on one; at 16384
// only its node loops ran in parallel (1.06x). On a busy machine a barrier waiting for a
// descheduled thread costs a whole time slice: there run with OMP_WAIT_POLICY=passive or one
// thread (README). A variable, not a constant, so that the thread-invariance tests can run
// small meshes in parallel.
inline std::size_t parallel_minimum = 2048;
// Chunk of the element and joint loops: rigid triangles and their joints, which cost nothing,
// lie together in the mesh, so a plain static split would leave one thread idle.
constexpr int kInterleavedChunk = 256;

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
