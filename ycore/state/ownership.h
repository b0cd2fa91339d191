// Which thread works on which part of the solid (doc/threading.md "Ownership slots"). Every
// mechanical loop of a relaxation step gives thread t the same contiguous range of triangles,
// of their corner nodes and of the joints whose first triangle lies in it, so that the data a
// step writes (forces, positions) stay in the cache of the core that wrote them and is read
// there by the next loop. Interleaved and plain static schedules that differ from loop to
// loop would move most of it between cores at every loop.
//
// The ranges are cut once, into kOwnershipSlots slots of about the same estimated work
// (partition_for_threads): a rigid triangle, which costs almost nothing, counts as a tenth of
// a deformable one, wherever the Hilbert order puts it. A team of T threads shares the slots
// out evenly (240 is divisible by 1-6, 8, 10, 12, 15 and 16), and every index is done
// exactly once whatever T is. No result depends on the ranges: each triangle, node or joint
// is computed by one thread alone, and sums go over fixed blocks (blocked_sum.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace ydry {

// Loops shorter than this run on one thread: a relaxation step is five loops, each ending in
// a barrier, and a barrier costs a few microseconds. At 2048 the Peron mesh (10,067
// triangles, 14,053 joints) runs every loop on both cores. On a busy machine a barrier
// waiting for a descheduled thread costs a whole time slice: there run with
// OMP_WAIT_POLICY=passive or one thread (README). A variable, not a constant, so that the
// thread-invariance tests can run small meshes in parallel.
inline std::size_t parallel_minimum = 2048;

constexpr std::size_t kOwnershipSlots = 240;

struct Ownership {
  // [slots + 1] each: slot k owns [begin[k], begin[k + 1]).
  std::vector<std::size_t> triangle_begin, node_begin, joint_begin;
  std::size_t slots() const { return triangle_begin.empty() ? 0 : triangle_begin.size() - 1; }
};

struct Triangles;  // ycore/state/state.h
struct Joints;
struct MaterialModel;

// Cuts triangles, nodes and joints into `slots` ranges of about equal work: a rigid triangle
// is counted as a tenth of a deformable one (it has no element or joint forces, only its
// nodes' passes), and a joint goes with its first triangle.
Ownership partition_for_threads(const Triangles& triangles, const Joints& joints,
                                const std::vector<MaterialModel>& materials, std::size_t slots);

struct IndexRange {
  std::size_t begin = 0, end = 0;
};

// The calling thread's share of [0, count) in the current team: its slots' range of `begin`
// (an Ownership table for this count), or an even cut where there is no table.
inline IndexRange owned_range(const std::vector<std::size_t>& begin, std::size_t count) {
#ifdef _OPENMP
  const std::size_t team = std::size_t(omp_get_num_threads()), t = std::size_t(omp_get_thread_num());
#else
  const std::size_t team = 1, t = 0;
#endif
  if (begin.size() < 2 || begin.back() != count) return {count * t / team, count * (t + 1) / team};
  const std::size_t slots = begin.size() - 1;
  return {begin[slots * t / team], begin[slots * (t + 1) / team]};
}

// Runs body(i) for every i in [0, count), each thread over its owned range.
template <class Body>
void for_each_owned(const std::vector<std::size_t>& begin, std::size_t count, Body body) {
#pragma omp parallel if (count > parallel_minimum)
  {
    const IndexRange r = owned_range(begin, count);
    for (std::size_t i = r.begin; i < r.end; ++i) body(i);
  }
}

}  // namespace ydry
