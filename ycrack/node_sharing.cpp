#include "ycrack/node_sharing.h"

#include <numeric>

#include "ycrack/union_find.h"

namespace ydry {

namespace {

// For every corner, the lowest corner connected to it through the intact joints that `ties`
// accepts (a joint ties corner pairs 4j+0 - 4j+3 and 4j+1 - 4j+2).
template <class Ties>
void group_corners(const Joints& joints, Ties&& ties, std::vector<index_t>& parent) {
  const index_t ncorners = static_cast<index_t>(parent.size());
  std::iota(parent.begin(), parent.end(), index_t(0));
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints.broken[j] || !ties(j)) continue;
    const index_t* n = &joints.node[4 * j];
    unite(parent, n[0], n[3]);
    unite(parent, n[1], n[2]);
  }
  // Every parent is smaller than its child (the smaller root wins), so in ascending order each
  // corner's parent already points at its root.
  for (index_t c = 0; c < ncorners; ++c) parent[c] = parent[parent[c]];
}

}  // namespace

void tie_corners(const Joints& joints, Nodes& nodes) {
  nodes.tie_group.resize(nodes.size());
  group_corners(joints, [](std::size_t) { return true; }, nodes.tie_group);
}

index_t group_moisture_nodes(const Joints& joints, const Triangles& triangles,
                             const std::vector<std::uint8_t>& has_moisture, Nodes& nodes, MoistureNodes& moisture) {
  tie_corners(joints, nodes);
  const index_t ncorners = static_cast<index_t>(nodes.size());
  // Moisture nodes never span two materials, which exchange no water (doc/physics.md
  // "Interface joints"): a bonded interface's joints tie corners for the solid only.
  std::vector<index_t> group(ncorners);
  group_corners(joints, [&](std::size_t j) {
    return triangles.material[triangle_of(joints.node[4 * j])] == triangles.material[triangle_of(joints.node[4 * j + 2])];
  }, group);

  index_t count = 0;
  std::vector<index_t> root_id(ncorners, kNoIndex);
  for (index_t c = 0; c < ncorners; ++c) {
    if (!has_moisture[triangle_of(c)]) {
      nodes.mnode[c] = kNoIndex;
      continue;
    }
    const index_t r = group[c];
    if (root_id[r] == kNoIndex) root_id[r] = count++;
    nodes.mnode[c] = root_id[r];
  }

  // CSR corner lists, each in increasing corner order (a counting sort).
  moisture.corner_offset.assign(std::size_t(count) + 1, 0);
  for (index_t c = 0; c < ncorners; ++c)
    if (nodes.mnode[c] != kNoIndex) ++moisture.corner_offset[nodes.mnode[c] + 1];
  std::partial_sum(moisture.corner_offset.begin(), moisture.corner_offset.end(),
                   moisture.corner_offset.begin());
  moisture.corner.resize(moisture.corner_offset.back());
  std::vector<index_t> fill(moisture.corner_offset.begin(), moisture.corner_offset.end() - 1);
  for (index_t c = 0; c < ncorners; ++c)
    if (nodes.mnode[c] != kNoIndex) moisture.corner[fill[nodes.mnode[c]]++] = c;
  return count;
}

}  // namespace ydry
