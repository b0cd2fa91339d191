// The contact broad phase: a cell list of surface corners; each surface edge collects the
// corners within two buffers of it. Pairs come out sorted by (corner, edge) whatever the
// thread count, carry the friction slip of the pairs they continue, and are indexed per
// corner for the force kernel and per receiving node for the gather.
#include "ycore/contact/contact_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "ycore/state/blocked_sum.h"

namespace ydry {
namespace {

// Distance from (px, py) to the segment a-b, squared.
double segment_distance2(double px, double py, double ax, double ay, double bx, double by) {
  const double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
  double u = len2 > 0.0 ? ((px - ax) * ex + (py - ay) * ey) / len2 : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  const double dx = px - ax - u * ex, dy = py - ay - u * ey;
  return dx * dx + dy * dy;
}

struct CellGrid {
  double x0 = 0, y0 = 0, size = 1;
  std::int64_t nx = 1, ny = 1;
  std::vector<index_t> offset, item;  // CSR: surface-node positions per cell
  std::int64_t cell_x(double x) const { return std::clamp<std::int64_t>(std::int64_t((x - x0) / size), 0, nx - 1); }
  std::int64_t cell_y(double y) const { return std::clamp<std::int64_t>(std::int64_t((y - y0) / size), 0, ny - 1); }
};

// Bins the surface corners into square cells of about the mean surface edge length (at least
// 4 buffers), with no more cells than about 4 per corner.
CellGrid bin_surface_nodes(const Nodes& n, const Contact& c) {
  CellGrid g;
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, edge_sum = 0.0;
  for (const index_t i : c.surface_node) {
    xmin = std::min(xmin, n.x[i]), xmax = std::max(xmax, n.x[i]);
    ymin = std::min(ymin, n.y[i]), ymax = std::max(ymax, n.y[i]);
  }
  for (const index_t e : c.surface_edge) {
    const index_t f = next_corner(e);
    edge_sum += std::hypot(n.x[f] - n.x[e], n.y[f] - n.y[e]);
  }
  const double span = std::max(xmax - xmin, ymax - ymin);
  g.size = std::max({edge_sum / double(c.surface_edge.size()), 4.0 * c.buffer_m,
                     span / std::sqrt(4.0 * double(c.surface_node.size()))});
  g.x0 = xmin, g.y0 = ymin;
  g.nx = std::int64_t((xmax - xmin) / g.size) + 1;
  g.ny = std::int64_t((ymax - ymin) / g.size) + 1;
  std::vector<std::int64_t> cell(c.surface_node.size());
  g.offset.assign(std::size_t(g.nx * g.ny) + 1, 0);
  for (std::size_t k = 0; k < c.surface_node.size(); ++k) {
    const index_t i = c.surface_node[k];
    cell[k] = g.cell_y(n.y[i]) * g.nx + g.cell_x(n.x[i]);
    ++g.offset[cell[k] + 1];
  }
  std::partial_sum(g.offset.begin(), g.offset.end(), g.offset.begin());
  g.item.resize(c.surface_node.size());
  std::vector<index_t> fill(g.offset.begin(), g.offset.end() - 1);
  for (std::size_t k = 0; k < c.surface_node.size(); ++k) g.item[fill[cell[k]]++] = index_t(k);
  return g;
}

// Whether corner i may touch the edge starting at corner e at all. Not where it is tied to
// one of the edge's ends, nor where an intact joint's line joins it to one: it lies on that
// joint, which carries what passes between them, however far the joint has slid (a corner of
// a softening mode II joint passes the edge's end, and a thin layer's bottom corner lies
// under its top edge's end: doc/physics.md "Contact and friction").
bool may_touch(const Nodes& n, const Contact& c, index_t i, index_t e) {
  const index_t f = next_corner(e);
  if (triangle_of(i) == triangle_of(e)) return false;
  const index_t gi = n.tie_group[i];
  for (const index_t end : {e, f}) {
    const index_t g = n.tie_group[end];
    if (g == gi || std::binary_search(c.bonded_line.begin(), c.bonded_line.end(), bonded_line_key(g, gi)))
      return false;
  }
  const auto fixed = [&](index_t k) { return n.constraint[k] == (kFixX | kFixY); };
  return !(fixed(i) && fixed(e) && fixed(f));  // nothing could move
}

}  // namespace

void build_contact_pairs(const Nodes& n, const Ownership& ownership, Contact& c) {
  // A non-finite position has no cell (casting it to an index is undefined): the pairs stay
  // as they are, and the relaxation reports the state after this force evaluation.
  if (!std::all_of(c.surface_node.begin(), c.surface_node.end(),
                   [&](index_t i) { return std::isfinite(n.x[i]) && std::isfinite(n.y[i]); }))
    return;
  const double reach2 = 4.0 * c.buffer_m * c.buffer_m;
  struct Pair { index_t node, edge; };
  std::vector<Pair> pairs;
  if (!c.surface_node.empty()) {
    const CellGrid g = bin_surface_nodes(n, c);
    for (const index_t e : c.surface_edge) {
      const index_t f = next_corner(e);
      const double reach = 2.0 * c.buffer_m;
      const std::int64_t cx0 = g.cell_x(std::min(n.x[e], n.x[f]) - reach), cx1 = g.cell_x(std::max(n.x[e], n.x[f]) + reach);
      const std::int64_t cy0 = g.cell_y(std::min(n.y[e], n.y[f]) - reach), cy1 = g.cell_y(std::max(n.y[e], n.y[f]) + reach);
      for (std::int64_t cy = cy0; cy <= cy1; ++cy)
        for (std::int64_t cx = cx0; cx <= cx1; ++cx) {
          const std::size_t cell = std::size_t(cy * g.nx + cx);
          for (index_t k = g.offset[cell]; k < g.offset[cell + 1]; ++k) {
            const index_t i = c.surface_node[g.item[k]];
            if (may_touch(n, c, i, e) && segment_distance2(n.x[i], n.y[i], n.x[e], n.y[e], n.x[f], n.y[f]) <= reach2)
              pairs.push_back({i, e});
          }
        }
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.node != b.node ? a.node < b.node : a.edge < b.edge;
  });

  // Continuing pairs keep their friction slip and last force (both lists are sorted).
  std::vector<double> slip(pairs.size(), 0.0), force(6 * pairs.size(), 0.0);
  for (std::size_t k = 0, old = 0; k < pairs.size(); ++k) {
    while (old < c.pair_node.size() &&
           (c.pair_node[old] < pairs[k].node || (c.pair_node[old] == pairs[k].node && c.pair_edge[old] < pairs[k].edge)))
      ++old;
    if (old < c.pair_node.size() && c.pair_node[old] == pairs[k].node && c.pair_edge[old] == pairs[k].edge)
    {
      slip[k] = c.pair_slip[old];
      std::copy_n(&c.pair_force[6 * old], 6, &force[6 * k]);
    }
  }
  c.pair_slip = std::move(slip);
  c.pair_force = std::move(force);
  c.pair_node.resize(pairs.size());
  c.pair_edge.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    c.pair_node[k] = pairs[k].node;
    c.pair_edge[k] = pairs[k].edge;
  }
  index_contact_pairs(n, ownership, c);
  for (std::size_t k = 0; k < c.surface_node.size(); ++k) {
    c.x_built[k] = n.x[c.surface_node[k]];
    c.y_built[k] = n.y[c.surface_node[k]];
  }
  ++c.builds;
}

void index_contact_pairs(const Nodes& n, const Ownership& ownership, Contact& c) {
  const std::size_t np = c.pair_node.size();
  c.node_pairs.clear();
  for (std::size_t k = 0; k < np; ++k)
    if (k == 0 || c.pair_node[k] != c.pair_node[k - 1]) c.node_pairs.push_back(index_t(k));
  c.node_pairs.push_back(index_t(np));
  // Each thread takes the corners in its own range of nodes (ycore/state/ownership.h).
  const std::vector<std::size_t>& node_begin = ownership.node_begin;
  c.corner_owner_begin.resize(node_begin.size());
  for (std::size_t k = 0; k < node_begin.size(); ++k)
    c.corner_owner_begin[k] = std::size_t(
        std::lower_bound(c.node_pairs.begin(), c.node_pairs.end() - 1, node_begin[k],
                         [&](index_t first, std::size_t node) { return c.pair_node[first] < node; }) -
        c.node_pairs.begin());

  // Per receiving node, the pair forces it gathers, in pair order (a counting sort).
  c.gather_offset.assign(n.size() + 1, 0);
  const auto receiver = [&](std::size_t k, int slot) {
    return slot == 0 ? c.pair_node[k] : slot == 1 ? c.pair_edge[k] : next_corner(c.pair_edge[k]);
  };
  for (std::size_t k = 0; k < np; ++k)
    for (int slot = 0; slot < 3; ++slot) ++c.gather_offset[receiver(k, slot) + 1];
  std::partial_sum(c.gather_offset.begin(), c.gather_offset.end(), c.gather_offset.begin());
  c.gather_entry.resize(3 * np);
  std::vector<index_t> fill(c.gather_offset.begin(), c.gather_offset.end() - 1);
  for (std::size_t k = 0; k < np; ++k)
    for (int slot = 0; slot < 3; ++slot) c.gather_entry[fill[receiver(k, slot)]++] = index_t(3 * k + slot);
}

bool contact_pairs_stale(const Nodes& n, const Contact& c) {
  if (c.node_pairs.empty()) return true;  // never built
  const double buffer2 = c.buffer_m * c.buffer_m;
  // On one thread: the Peron deck's 2,800 to 3,500 surface corners take a few microseconds,
  // less than a parallel region costs (as one on two threads, the check takes 7 us a step:
  // bench/RESULTS.md).
  for (std::size_t k = 0; k < c.surface_node.size(); ++k) {
    const index_t i = c.surface_node[k];
    const double dx = n.x[i] - c.x_built[k], dy = n.y[i] - c.y_built[k];
    if (!(dx * dx + dy * dy <= buffer2)) return true;  // also true after the surfaces changed
  }
  return false;
}

}  // namespace ydry
