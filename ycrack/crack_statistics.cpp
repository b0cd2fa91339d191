#include "ycrack/crack_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ycore/solid/joint_law.h"
#include "ycrack/union_find.h"

namespace ydry {
namespace {

// Where a vertex lies, for the choice of a crack's mouth.
enum SurfaceKind : std::uint8_t { kInside = 0, kInterface = 1, kSideSurface = 2, kTopSurface = 3 };

// An outer edge from corner c to the next (counter-clockwise) faces up when its outward normal
// (dy, -dx) lies within 45 degrees of +y, in the initial configuration: the surface an observer
// looking down on the sample sees (a layer's top, not its ends or its underside).
bool faces_up(const Nodes& n, index_t c) {
  const index_t d = next_corner(c);
  const double dx = n.x0[d] - n.x0[c], dy = n.y0[d] - n.y0[c];
  return -dx > std::fabs(dy);
}

// The vertices on an edge that no joint of a material sits on, intact or broken: on the mesh's
// outer boundary (an edge of one triangle only), facing up or not, or on an interface between
// materials (an edge two triangles share without a joint, or with a bonded interface's). A
// joint sits on the edge starting at its node 0 (first triangle) and at its node 2 (second
// triangle).
std::vector<std::uint8_t> surface_kinds(const State& s, index_t nvertices) {
  const Nodes& n = s.nodes;
  const Joints& joints = s.joints;
  std::vector<std::uint8_t> jointed(n.size(), 0);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (is_interface_joint(s, j)) continue;
    jointed[joints.node[4 * j]] = 1;
    jointed[joints.node[4 * j + 2]] = 1;
  }
  const auto edge_key = [&](index_t c) {
    const index_t a = n.vertex[c], b = n.vertex[corner_node(triangle_of(c), (c % 3 + 1) % 3)];
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
  };
  std::vector<std::uint64_t> edges(n.size());
  for (index_t c = 0; c < n.size(); ++c) edges[c] = edge_key(c);
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint8_t> kind(nvertices, kInside);
  for (index_t c = 0; c < n.size(); ++c) {
    if (jointed[c]) continue;
    const std::uint64_t key = edge_key(c);
    const auto same = std::equal_range(edges.begin(), edges.end(), key);
    const bool outer = same.second - same.first == 1;
    const std::uint8_t k = !outer ? kInterface : faces_up(n, c) ? kTopSurface : kSideSurface;
    for (const index_t v : {index_t(key >> 32), index_t(key & 0xffffffffu)}) kind[v] = std::max(kind[v], k);
  }
  return kind;
}

// Lowest initial y and layer height of each material.
struct Layer {
  double bottom_y0 = std::numeric_limits<double>::infinity();
  double top_y0 = -std::numeric_limits<double>::infinity();
};
std::vector<Layer> material_layers(const Nodes& n, const Triangles& triangles, std::size_t materials) {
  std::vector<Layer> layers(materials);
  for (index_t c = 0; c < n.size(); ++c) {
    Layer& l = layers[triangles.material[triangle_of(c)]];
    l.bottom_y0 = std::min(l.bottom_y0, n.y0[c]);
    l.top_y0 = std::max(l.top_y0, n.y0[c]);
  }
  return layers;
}

// The best mouth so far: a vertex on the top surface beats one on another outer surface, which
// beats one on an interface, which beats an internal one; then the higher y0; then the wider
// opening of a joint there (a crack that meets the top at a broken joint and, through its
// process zone, at a vertex still shut is seen where it gapes); then the lower vertex id.
struct Mouth {
  index_t vertex = kNoIndex;
  std::uint16_t material = 0;
  std::uint8_t surface = kInside;
  double y0 = 0;
  double opening = 0;  // of the joint end that proposed this vertex, m
  bool beaten_by(const Mouth& m) const {
    if (vertex == kNoIndex) return true;
    if (m.surface != surface) return m.surface > surface;
    if (m.y0 != y0) return m.y0 > y0;
    if (m.opening != opening) return m.opening > opening;
    return m.vertex < vertex;
  }
};

// A joint on the softening branch far enough to be part of a crack's process zone: two of
// its three points past kProcessZoneDamage (a broken joint has two at D = 1). It links the
// broken stretches of one crack that zig-zags through the mesh, so they count once, without
// linking the joints that passed their peak before the strain localised (D stays small there).
bool in_process_zone(const Joints& joints, std::size_t j) {
  if (joints.damage.empty()) return false;
  int past = 0;
  for (int p = 0; p < 3; ++p) past += joints.damage[3 * j + p] >= kProcessZoneDamage;
  return past >= 2;
}

}  // namespace

std::vector<Crack> find_all_cracks(const State& s) {
  const Nodes& n = s.nodes;
  const Joints& joints = s.joints;
  const index_t nvertices =
      n.vertex.empty() ? 0 : *std::max_element(n.vertex.begin(), n.vertex.end()) + 1;

  std::vector<index_t> parent(nvertices);
  std::iota(parent.begin(), parent.end(), index_t(0));
  // Broken, or in a crack's process zone: a joint of a material (an interface that comes
  // apart debonds, which is no crack). The vertices of an interface that is coming apart.
  std::vector<std::uint8_t> open(joints.size(), 0), debonding(nvertices, 0);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const bool apart = joints.broken[j] || in_process_zone(joints, j);
    if (is_interface_joint(s, j)) {
      if (apart) debonding[n.vertex[joints.node[4 * j]]] = debonding[n.vertex[joints.node[4 * j + 1]]] = 1;
      continue;
    }
    open[j] = apart;
    if (open[j]) unite(parent, n.vertex[joints.node[4 * j]], n.vertex[joints.node[4 * j + 1]]);
  }
  std::vector<std::uint8_t> has_broken(nvertices, 0);  // by root
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (open[j] && joints.broken[j]) has_broken[find_root(parent, n.vertex[joints.node[4 * j]])] = 1;

  const std::vector<std::uint8_t> surface = surface_kinds(s, nvertices);
  const std::vector<Layer> layers = material_layers(n, s.triangles, s.material_names.size());
  // Cracks numbered in the order of their first open joint.
  std::vector<index_t> crack_of_root(nvertices, kNoIndex);
  std::vector<Crack> cracks;
  std::vector<Mouth> mouths;
  for (index_t j = 0; j < joints.size(); ++j) {
    if (!open[j]) continue;
    const index_t* jn = &joints.node[4 * j];
    const index_t root = find_root(parent, n.vertex[jn[0]]);
    if (!has_broken[root]) continue;
    index_t& k = crack_of_root[root];
    if (k == kNoIndex) {
      k = static_cast<index_t>(cracks.size());
      cracks.emplace_back();
      mouths.emplace_back();
    }
    Crack& crack = cracks[k];
    crack.joints.push_back(j);
    const std::uint16_t material = s.triangles.material[triangle_of(jn[0])];
    const Layer& layer = layers[material];
    const JointKinematics kin = joint_kinematics(n, jn);
    for (int end = 0; end < 2; ++end) {
      const index_t v = n.vertex[jn[end]];
      const double y0 = n.y0[jn[end]];
      const Mouth candidate{v, material, surface[v], y0, kin.opening[end]};
      if (mouths[k].beaten_by(candidate)) mouths[k] = candidate;
      if (!joints.broken[j]) continue;  // length and penetration count broken joints only
      if (y0 <= layer.bottom_y0 + 1e-6 * (layer.top_y0 - layer.bottom_y0) || debonding[v]) crack.penetrating = true;
    }
    if (joints.broken[j]) crack.length_m += kin.length;
  }

  std::vector<index_t> crack_at_mouth(nvertices, kNoIndex);
  for (index_t k = 0; k < cracks.size(); ++k) {
    crack_at_mouth[mouths[k].vertex] = k;
    cracks[k].on_top_surface = mouths[k].surface == kTopSurface;
    // Of the joint ends at the mouth vertex the widest proposed it (Mouth::beaten_by).
    cracks[k].width_m = mouths[k].opening;
  }
  std::vector<int> corners_at_mouth(cracks.size(), 0);
  for (index_t c = 0; c < n.size(); ++c) {
    const index_t k = crack_at_mouth[n.vertex[c]];
    if (k == kNoIndex || s.triangles.material[triangle_of(c)] != mouths[k].material) continue;
    cracks[k].x_m += n.x[c];
    ++corners_at_mouth[k];
  }
  for (std::size_t k = 0; k < cracks.size(); ++k) cracks[k].x_m /= corners_at_mouth[k];

  std::stable_sort(cracks.begin(), cracks.end(),
                   [](const Crack& a, const Crack& b) { return a.x_m < b.x_m; });
  return cracks;
}

CrackCensus take_crack_census(const State& s, double width_threshold_m) {
  CrackCensus census;
  census.open = find_all_cracks(s);
  const auto closed = std::remove_if(census.open.begin(), census.open.end(),
                                     [&](const Crack& c) { return !(c.width_m > width_threshold_m); });
  census.closed = int(census.open.end() - closed);
  census.open.erase(closed, census.open.end());
  return census;
}

std::vector<Crack> find_cracks(const State& s, double width_threshold_m) {
  return take_crack_census(s, width_threshold_m).open;
}

CrackSummary summarize_cracks(const std::vector<Crack>& cracks) {
  CrackSummary sum;
  double length = 0;
  for (const Crack& c : cracks) {
    ++sum.count;
    sum.total_width_m += c.width_m;
    length += c.length_m;
    if (!c.on_top_surface) continue;
    ++sum.surface_count;
    sum.surface_total_width_m += c.width_m;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  sum.mean_width_m = sum.count ? sum.total_width_m / sum.count : nan;
  sum.mean_length_m = sum.count ? length / sum.count : nan;
  sum.surface_mean_width_m = sum.surface_count ? sum.surface_total_width_m / sum.surface_count : nan;
  return sum;
}

}  // namespace ydry
