// The crack network's census (network_census.h): union-find over the triangles through intact
// joints, the voids of the broken joints, and the junctions of the graph they make.
#include "ycrack/network_census.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "ycrack/union_find.h"

namespace ydry {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Degrees from which the largest angle of a three-branch junction makes it a T: nearer 180
// than 120.
constexpr double kTeeAngle = 150.0;
// How far a branch is followed to find its direction, in mean broken-joint lengths.
constexpr double kBranchReach = 3.0;

bool deformable(const Triangles& tri, const std::vector<MaterialModel>& materials, index_t t) {
  const MaterialModel& m = materials[tri.material[t]];
  return m.mechanical && !m.rigid;
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Current area of triangle t (positive: its corners run counter-clockwise).
double triangle_area(const Nodes& n, index_t t) {
  const index_t a = corner_node(t, 0), b = corner_node(t, 1), c = corner_node(t, 2);
  return 0.5 * cross(n.x[b] - n.x[a], n.y[b] - n.y[a], n.x[c] - n.x[a], n.y[c] - n.y[a]);
}

double edge_length(const Nodes& n, index_t e) {
  const index_t f = next_corner(e);
  return std::hypot(n.x[f] - n.x[e], n.y[f] - n.y[e]);
}

// The void between the faces a-b and b'-a' of joint j where they lie apart: the triangle keeps
// its side of a-b on the left, so the gap lies to its right and the outline a, b, b', a' runs
// clockwise round it.
double joint_void(const Nodes& n, const Joints& jt, std::size_t j) {
  const index_t* q = &jt.node[4 * j];  // a, b, b', a'
  double twice = 0.0;
  for (int k = 0; k < 4; ++k) {
    const index_t p = q[k], r = q[(k + 1) % 4];
    twice += n.x[p] * n.y[r] - n.x[r] * n.y[p];
  }
  return std::max(0.0, -0.5 * twice);
}

}  // namespace

std::size_t NetworkCensus::count(JunctionKind kind) const {
  return std::size_t(std::count_if(junctions.begin(), junctions.end(), [&](const Junction& j) { return j.kind == kind; }));
}

std::vector<index_t> fragment_cells(const Triangles& tri, const Joints& jt, const std::vector<MaterialModel>& materials) {
  std::vector<index_t> parent(tri.size());
  for (std::size_t t = 0; t < tri.size(); ++t) parent[t] = index_t(t);
  for (std::size_t j = 0; j < jt.size(); ++j)
    if (!jt.broken[j]) unite(parent, triangle_of(jt.node[4 * j]), triangle_of(jt.node[4 * j + 2]));
  std::vector<index_t> cell_of_triangle(tri.size(), kNoIndex), cell_of_root(tri.size(), kNoIndex);
  index_t cells = 0;
  for (std::size_t t = 0; t < tri.size(); ++t) {
    if (!deformable(tri, materials, index_t(t))) continue;
    index_t& cell = cell_of_root[find_root(parent, index_t(t))];
    if (cell == kNoIndex) cell = cells++;
    cell_of_triangle[t] = cell;
  }
  return cell_of_triangle;
}

NetworkCensus take_network_census(const Nodes& n, const Triangles& tri, const Joints& jt,
                                  const std::vector<MaterialModel>& materials, std::size_t material_count) {
  NetworkCensus census;
  census.cell_of_triangle = fragment_cells(tri, jt, materials);
  std::size_t cells = 0;  // numbered from 0 in order: one more than the largest
  for (const index_t cell : census.cell_of_triangle)
    if (cell != kNoIndex) cells = std::max(cells, std::size_t(cell) + 1);
  census.cell_area_m2.assign(cells, 0.0);
  census.cell_perimeter_m.assign(cells, 0.0);

  // The edges a joint covers are a-b (from node 4j) and b'-a' (from node 4j+2); an edge no
  // joint covers is on the outer boundary.
  std::vector<std::uint8_t> jointed(n.size(), 0);
  for (std::size_t j = 0; j < jt.size(); ++j) jointed[jt.node[4 * j]] = jointed[jt.node[4 * j + 2]] = 1;
  const std::size_t vertices = n.size() > 0 ? std::size_t(1 + *std::max_element(n.vertex.begin(), n.vertex.end())) : 0;
  std::vector<index_t> node_of_vertex(vertices, kNoIndex);  // a corner made from it
  std::vector<std::uint8_t> on_boundary(vertices, 0);
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const index_t cell = census.cell_of_triangle[t];
    if (cell == kNoIndex) continue;
    census.cell_area_m2[cell] += triangle_area(n, index_t(t));
    census.layer_area_m2 += tri.area0[t];
    for (int k = 0; k < 3; ++k) {
      const index_t e = corner_node(index_t(t), k);
      node_of_vertex[n.vertex[e]] = e;
      if (jointed[e]) continue;
      census.cell_perimeter_m[cell] += edge_length(n, e);
      on_boundary[n.vertex[e]] = on_boundary[n.vertex[next_corner(e)]] = 1;
    }
  }

  // Broken joints: their faces outline the cells, their voids are the crack area, and they
  // join the mesh vertices of the crack network.
  std::map<index_t, std::vector<std::size_t>> joints_at;  // mesh vertex -> its broken joints
  std::size_t broken = 0;
  for (std::size_t j = 0; j < jt.size(); ++j) {
    const index_t first = triangle_of(jt.node[4 * j]), second = triangle_of(jt.node[4 * j + 2]);
    if (!jt.broken[j] || is_interface_joint(jt, material_count, j) || census.cell_of_triangle[first] == kNoIndex) continue;
    census.cell_perimeter_m[census.cell_of_triangle[first]] += edge_length(n, jt.node[4 * j]);
    census.cell_perimeter_m[census.cell_of_triangle[second]] += edge_length(n, jt.node[4 * j + 2]);
    census.crack_area_m2 += joint_void(n, jt, j);
    census.crack_length_m += jt.length0[j];
    ++broken;
    for (int k = 0; k < 2; ++k) joints_at[n.vertex[jt.node[4 * j + k]]].push_back(j);
  }
  const double reach = broken > 0 ? kBranchReach * census.crack_length_m / double(broken) : 0.0;
  const auto other_end = [&](std::size_t j, index_t vertex) {
    const index_t a = n.vertex[jt.node[4 * j]];
    return a == vertex ? n.vertex[jt.node[4 * j + 1]] : a;
  };
  for (const auto& [vertex, joints] : joints_at) {
    // A crack that meets the outer boundary ends there: no junction.
    if (joints.size() < 3 || on_boundary[vertex]) continue;
    Junction junction;
    junction.x0 = n.x0[node_of_vertex[vertex]], junction.y0 = n.y0[node_of_vertex[vertex]];
    std::vector<double> directions;
    for (const std::size_t start : joints) {
      // Along the branch through vertices where its crack only passes (two broken joints).
      index_t at = other_end(start, vertex);
      std::size_t through = start;
      double run = jt.length0[start];
      while (run < reach && joints_at.at(at).size() == 2 && at != vertex) {
        const std::vector<std::size_t>& passing = joints_at.at(at);
        through = passing[0] == through ? passing[1] : passing[0];
        run += jt.length0[through];
        at = other_end(through, at);
      }
      const index_t end = node_of_vertex[at];
      directions.push_back(std::atan2(n.y0[end] - junction.y0, n.x0[end] - junction.x0) * 180.0 / kPi);
    }
    std::sort(directions.begin(), directions.end());
    for (std::size_t k = 0; k < directions.size(); ++k)
      junction.angles.push_back(k + 1 < directions.size() ? directions[k + 1] - directions[k]
                                                         : directions.front() + 360.0 - directions[k]);
    // Listed from the branch nearest +x (the smallest |direction|), counter-clockwise.
    const auto nearest_x = std::min_element(directions.begin(), directions.end(),
                                            [](double a, double b) { return std::fabs(a) < std::fabs(b); });
    std::rotate(junction.angles.begin(), junction.angles.begin() + (nearest_x - directions.begin()), junction.angles.end());
    if (junction.angles.size() == 3)
      junction.kind = *std::max_element(junction.angles.begin(), junction.angles.end()) >= kTeeAngle ? JunctionKind::T
                                                                                                      : JunctionKind::Y;
    census.junctions.push_back(std::move(junction));
  }
  return census;
}

}  // namespace ydry
