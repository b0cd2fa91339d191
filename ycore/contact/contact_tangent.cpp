#include "ycore/contact/contact_tangent.h"

#include <cmath>

#include "ycore/contact/contact_geometry.h"

namespace ydry {
namespace {

constexpr double kOnEdge = 1e-6;  // |gap| / edge length of a corner that lies on the edge

// A corner that lies on the edge without pressing (a conforming interface at rest) is closed
// too: without it a body that only contact holds has no stiffness at all.
bool lies_on_edge(const EdgeProjection& at) {
  return at.along >= 0.0 && at.along <= 1.0 && std::fabs(at.gap) <= kOnEdge * at.length;
}

// stiffness B B^T into the entries, B = [d, -a d, -b d] over the corner and the edge's ends.
void add_penalty(const index_t receivers[3], const double share[3], double dx, double dy, double stiffness,
                 const std::vector<index_t>& unknown, std::vector<Eigen::Triplet<double>>& entries) {
  for (int r = 0; r < 6; ++r) {
    const index_t row = unknown[2 * std::size_t(receivers[r / 2]) + r % 2];
    if (row == kNoIndex) continue;
    const double br = share[r / 2] * (r % 2 == 0 ? dx : dy);
    for (int c = 0; c < 6; ++c) {
      const index_t column = unknown[2 * std::size_t(receivers[c / 2]) + c % 2];
      if (column != kNoIndex) entries.emplace_back(row, column, stiffness * br * share[c / 2] * (c % 2 == 0 ? dx : dy));
    }
  }
}

}  // namespace

void add_contact_tangent(const Nodes& n, const Triangles& tri, const Mechanics& mech, const Contact& c,
                         const std::vector<index_t>& unknown, std::vector<Eigen::Triplet<double>>& entries) {
  const std::size_t material_count = std::size_t(std::lround(std::sqrt(double(c.tan_friction.size()))));
  const double half_penalty = 0.5 * c.penalty_pa * mech.thickness_m;
  const std::size_t pairs = c.pair_node.size();
  // Pairs are sorted by corner; a corner presses through one of them at most (contact_forces)
  // and is counted once: by its pressing pair, else by the first edge it lies on.
  for (std::size_t first = 0, last; first < pairs; first = last) {
    std::size_t chosen = pairs;
    for (last = first; last < pairs && c.pair_node[last] == c.pair_node[first]; ++last) {
      if (c.pair_force[6 * last] != 0.0 || c.pair_force[6 * last + 1] != 0.0) chosen = last;
      else if (chosen == pairs && lies_on_edge(project(n, c.pair_node[last], c.pair_edge[last]))) chosen = last;
    }
    if (chosen == pairs) continue;
    const double* force = &c.pair_force[6 * chosen];
    const index_t i = c.pair_node[chosen], e = c.pair_edge[chosen];
    const EdgeProjection at = project(n, i, e);
    const index_t receivers[3] = {i, e, next_corner(e)};
    const double share[3] = {1.0, -(1.0 - at.along), -at.along};
    const double stiffness = half_penalty * (c.is_surface_edge[i] + c.is_surface_edge[previous_corner(i)]);
    add_penalty(receivers, share, at.ty, -at.tx, stiffness, unknown, entries);
    const double normal = force[0] * at.ty - force[1] * at.tx;
    const double tangential = force[0] * at.tx + force[1] * at.ty;
    const double mu = c.tan_friction[tri.material[triangle_of(i)] * material_count + tri.material[triangle_of(e)]];
    if (std::fabs(tangential) < (1.0 - 1e-9) * mu * normal)  // sticks
      add_penalty(receivers, share, at.tx, at.ty, stiffness, unknown, entries);
  }
}

}  // namespace ydry
