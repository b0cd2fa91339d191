#include "ycore/state/build_state.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

#include "ycore/input/input_error.h"
#include "ycore/state/mesh_gmsh.h"
#include "ycore/state/mesh_order.h"
#include "ycore/state/mesh_rectangle.h"

namespace ydry {
namespace {

struct EdgeSide {
  index_t triangle;
  int edge;  // local edge e runs from corner e to corner (e + 1) % 3
};

// Every mesh edge with the triangle sides that carry it.
std::unordered_map<std::uint64_t, std::vector<EdgeSide>> edge_sides(const MeshInput& mesh) {
  std::unordered_map<std::uint64_t, std::vector<EdgeSide>> sides;
  sides.reserve(3 * mesh.triangle_count());
  for (index_t t = 0; t < mesh.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e)
      sides[edge_key(mesh.tri[3 * t + e], mesh.tri[3 * t + (e + 1) % 3])].push_back({t, e});
  return sides;
}

}  // namespace

MeshInput load_mesh(const Deck& deck) {
  MeshInput mesh = deck.mesh_file.empty()
                       ? generate_rectangle(deck.mesh_size[0], deck.mesh_size[1], deck.element_size_m,
                                            deck.mesh_pattern, deck.mesh_material)
                       : read_gmsh(deck.mesh_file);
  orient_counter_clockwise(mesh);
  order_triangles_along_hilbert_curve(mesh);
  if (mesh.triangle_count() == 0) throw InputError(deck.mesh_where + ": the mesh has no triangles");
  for (const std::string& name : mesh.tri_material)
    if (!deck.materials.count(name))
      throw InputError(deck.mesh_where + ": the mesh has material \"" + name +
                       "\" but the deck has no [materials." + name + "]");
  return mesh;
}

State build_state(const MeshInput& mesh, const Deck& deck) {
  State s;
  for (const auto& [name, material] : deck.materials) s.material_names.push_back(name);
  std::map<std::string, std::uint16_t> material_id;
  for (std::size_t i = 0; i < s.material_names.size(); ++i) material_id[s.material_names[i]] = std::uint16_t(i);

  const index_t nt = static_cast<index_t>(mesh.triangle_count());
  Nodes& n = s.nodes;
  for (auto* v : {&n.x0, &n.y0, &n.x, &n.y, &n.vx, &n.vy}) v->assign(3 * std::size_t(nt), 0.0);
  n.vertex.resize(3 * std::size_t(nt));
  n.mnode.assign(3 * std::size_t(nt), kNoIndex);
  s.triangles.material.resize(nt);
  s.triangles.area0.resize(nt);
  for (index_t t = 0; t < nt; ++t) {
    for (int a = 0; a < 3; ++a) {
      const index_t v = mesh.tri[3 * t + a], i = corner_node(t, a);
      n.vertex[i] = v;
      n.x0[i] = n.x[i] = mesh.vx[v];
      n.y0[i] = n.y[i] = mesh.vy[v];
    }
    const index_t i = corner_node(t, 0);
    s.triangles.area0[t] = 0.5 * ((n.x0[i + 1] - n.x0[i]) * (n.y0[i + 2] - n.y0[i]) -
                                  (n.x0[i + 2] - n.x0[i]) * (n.y0[i + 1] - n.y0[i]));
    s.triangles.material[t] = material_id.at(mesh.tri_material[t]);
  }

  // The joint properties of an edge between materials a and b: the material's when a == b,
  // a bonded interface's (State::materials past the materials), or none (contact only).
  const std::size_t nm = s.material_names.size();
  std::map<std::pair<std::uint16_t, std::uint16_t>, std::uint16_t> bonded;
  for (const InterfaceDeck& f : deck.interfaces) {
    if (!f.bonded) continue;
    const std::uint16_t a = material_id.at(f.materials.first), b = material_id.at(f.materials.second);
    bonded[std::minmax(a, b)] = std::uint16_t(nm + s.interface_names.size());
    s.interface_names.push_back(f.name);
  }
  const auto joint_properties = [&](std::uint16_t a, std::uint16_t b) -> std::optional<std::uint16_t> {
    if (a == b) return a;
    const auto it = bonded.find(std::minmax(a, b));
    if (it == bonded.end()) return std::nullopt;
    return it->second;
  };

  const auto sides = edge_sides(mesh);
  // Joints in triangle order, so that their numbering does not depend on hashing.
  for (index_t t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      const std::vector<EdgeSide>& es =
          sides.at(edge_key(mesh.tri[3 * t + e], mesh.tri[3 * t + (e + 1) % 3]));
      if (es.size() > 2)
        throw InputError(deck.mesh_where + ": the mesh is not manifold: an edge of triangle " +
                         std::to_string(t) + " is shared by " + std::to_string(es.size()) + " triangles");
      if (es.size() != 2 || es[0].triangle != t) continue;  // boundary edge, or seen from the other side
      const EdgeSide other = es[1];
      const auto properties = joint_properties(s.triangles.material[t], s.triangles.material[other.triangle]);
      if (!properties) continue;  // two materials that meet through contact alone
      s.joints.law.push_back(*properties);
      s.joints.node.insert(s.joints.node.end(),
                           {corner_node(t, e), corner_node(t, (e + 1) % 3),
                            corner_node(other.triangle, other.edge),
                            corner_node(other.triangle, (other.edge + 1) % 3)});
      s.joints.broken.push_back(0);
    }

  for (const auto& [name, pairs] : mesh.boundaries) {
    std::vector<index_t>& out = s.boundary_edges[name];
    for (std::size_t k = 0; k < pairs.size(); k += 2) {
      const auto it = sides.find(edge_key(pairs[k], pairs[k + 1]));
      if (it == sides.end())
        throw InputError(deck.mesh_where + ": boundary \"" + name + "\" has an edge (vertices " +
                         std::to_string(pairs[k]) + ", " + std::to_string(pairs[k + 1]) +
                         ") that is not an edge of any triangle");
      for (const EdgeSide& side : it->second)
        out.insert(out.end(), {corner_node(side.triangle, side.edge),
                               corner_node(side.triangle, (side.edge + 1) % 3)});
    }
  }
  return s;
}

const std::vector<index_t>& boundary_nodes(const std::map<std::string, std::vector<index_t>>& boundary_edges,
                                           const std::string& name, const std::string& where) {
  const auto it = boundary_edges.find(name);
  if (it == boundary_edges.end()) {
    std::string names;
    for (const auto& kv : boundary_edges) names += (names.empty() ? "" : ", ") + kv.first;
    throw InputError(where + ": the mesh has no boundary named \"" + name + "\" (it has: " +
                     (names.empty() ? "none" : names) + ")");
  }
  return it->second;
}

}  // namespace ydry
