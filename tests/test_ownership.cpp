// The threads' ranges of the solid (ycore/state/ownership.h) and the Hilbert numbering of the
// triangles (ycore/state/mesh_order.cpp) that makes those ranges compact patches of the mesh.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <omp.h>

#include "tests/test_support.h"
#include "ycore/state/mesh_order.h"
#include "ycore/state/mesh_rectangle.h"
#include "ycore/state/blocked_sum.h"
#include "ycore/driver/setup.h"

using namespace ydry;
using namespace ydry_test;

namespace {

// How many interior edges of the mesh tie two of its triangles' `ranges` equal ranges.
std::size_t edges_between_ranges(const MeshInput& mesh, std::size_t ranges) {
  const std::size_t per_range = mesh.triangle_count() / ranges;
  std::map<std::uint64_t, std::vector<std::size_t>> sides;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) sides[edge_key(mesh.tri[3 * t + e], mesh.tri[3 * t + (e + 1) % 3])].push_back(t);
  std::size_t between = 0;
  for (const auto& [key, t] : sides) between += t.size() == 2 && t[0] / per_range != t[1] / per_range;
  return between;
}

// The triangles as sorted vertex triples, whatever their numbering and starting corner.
std::vector<std::array<index_t, 3>> triangle_set(const MeshInput& mesh) {
  std::vector<std::array<index_t, 3>> set(mesh.triangle_count());
  for (std::size_t t = 0; t < set.size(); ++t) {
    set[t] = {mesh.tri[3 * t], mesh.tri[3 * t + 1], mesh.tri[3 * t + 2]};
    std::sort(set[t].begin(), set[t].end());
  }
  std::sort(set.begin(), set.end());
  return set;
}

}  // namespace

TEST_CASE("triangles renumbered along a Hilbert curve are the same triangles, and 16 equal ranges of them are 16 squares of the mesh", "[mesh][threads]") {
  // 64 x 64 cells of two triangles, shuffled: a numbering without locality, in which 15/16 of
  // the 12,160 interior edges tie two ranges. Along the curve, the 16 ranges of 512 triangles are the
  // curve's 16 squares of 16 x 16 cells, so the only edges between ranges are the squares'
  // inner sides: 3 vertical and 3 horizontal lines of 64 edges, 384 edges. (Numbered row by
  // row, the ranges would be strips with 15 lines between them: 960 edges.)
  const MeshInput rows = generate_rectangle(1.0, 1.0, 1.0 / 64, "right", "soil");
  MeshInput mesh = rows;
  std::vector<std::size_t> order(rows.triangle_count());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  for (std::size_t k = 0; k < order.size(); ++k)
    for (int a = 0; a < 3; ++a) mesh.tri[3 * k + a] = rows.tri[3 * order[k] + a];
  REQUIRE(edges_between_ranges(mesh, 16) > 12160 * 7 / 8);
  order_triangles_along_hilbert_curve(mesh);
  CHECK(triangle_set(mesh) == triangle_set(rows));
  CHECK(mesh.tri_material == rows.tri_material);
  CHECK(edges_between_ranges(rows, 16) == 960);
  CHECK(edges_between_ranges(mesh, 16) == 384);
  // The curve is continuous: each triangle is in the cell of the one before it or the next
  // cell along the curve, an edge neighbour, so their centroids are less than 1.5 cells apart
  // (a Z-order curve, or one without the rotations, jumps).
  double farthest = 0;
  for (std::size_t t = 1; t < mesh.triangle_count(); ++t) {
    double dx = 0, dy = 0;
    for (int a = 0; a < 3; ++a) {
      dx += (mesh.vx[mesh.tri[3 * t + a]] - mesh.vx[mesh.tri[3 * t - 3 + a]]) / 3.0;
      dy += (mesh.vy[mesh.tri[3 * t + a]] - mesh.vy[mesh.tri[3 * t - 3 + a]]) / 3.0;
    }
    farthest = std::max(farthest, std::hypot(dx, dy));
  }
  CHECK(farthest < 1.5 / 64);
}

TEST_CASE("the threads' ranges hold equal work, and every triangle, node and joint is done once by a team of any size", "[threads]") {
  const State s = prepare_state(load_deck(kPeronDeck, {}));  // a third of its mesh is the rigid base
  const Ownership& own = s.ownership;
  REQUIRE(own.slots() == kOwnershipSlots);

  // Work per slot: a deformable triangle 1, a rigid one 0.1 (partition_for_threads). The
  // cut can miss the ideal share by at most one triangle's work.
  double total = 0;
  for (const std::uint16_t m : s.triangles.material) total += s.materials[m].mechanical ? 1.0 : 0.1;
  REQUIRE(total > 2.0 * kOwnershipSlots);  // a mesh that fills the slots
  for (std::size_t k = 0; k < own.slots(); ++k) {
    double work = 0;
    for (std::size_t t = own.triangle_begin[k]; t < own.triangle_begin[k + 1]; ++t)
      work += s.materials[s.triangles.material[t]].mechanical ? 1.0 : 0.1;
    INFO("slot " << k);
    CHECK(std::abs(work - total / double(own.slots())) <= 1.0);
  }
  // A joint is owned with its first triangle.
  for (std::size_t k = 0; k < own.slots(); ++k)
    for (std::size_t j = own.joint_begin[k]; j < own.joint_begin[k + 1]; ++j) {
      const std::size_t t = triangle_of(s.joints.node[4 * j]);
      REQUIRE((t >= own.triangle_begin[k] && t < own.triangle_begin[k + 1]));
    }

  RestoreThreadSettings restore;
  parallel_minimum = 0;
  for (const int team : {1, 2, 3, 7, 16}) {
    INFO("team of " << team);
    omp_set_num_threads(team);
    for (const auto* begin : {&own.triangle_begin, &own.node_begin, &own.joint_begin}) {
      const std::size_t n = begin->back();
      std::vector<std::atomic<int>> visits(n);
      for_each_owned(*begin, n, [&](std::size_t i) { ++visits[i]; });
      CHECK(std::all_of(visits.begin(), visits.end(), [](const std::atomic<int>& v) { return v == 1; }));
      // The blocked sums cover every index once too: the sum of i over [0, n).
      const auto sum = blocked_sum<1>(n, [](std::size_t i, std::array<double, 1>& s) { s[0] += double(i); }, *begin);
      CHECK(sum[0] == 0.5 * double(n) * double(n - 1));
    }
  }
}
