// Meshes to state: the rectangle generator, the exploded mesh, joints, named boundaries and
// the moisture nodes grouped under intact joints (ycrack).
#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include "tests/test_support.h"
#include "ycore/state/mesh_rectangle.h"
#include "ycore/state/build_state.h"
#include "ycore/driver/setup.h"

using namespace ydry;

namespace {

double total_area(const MeshInput& m) {
  double a = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const index_t* v = &m.tri[3 * t];
    a += 0.5 * ((m.vx[v[1]] - m.vx[v[0]]) * (m.vy[v[2]] - m.vy[v[0]]) -
                (m.vx[v[2]] - m.vx[v[0]]) * (m.vy[v[1]] - m.vy[v[0]]));
  }
  return a;
}

double boundary_length(const MeshInput& m, const std::string& name) {
  double l = 0;
  const auto& e = m.boundaries.at(name);
  for (std::size_t k = 0; k < e.size(); k += 2) l += std::hypot(m.vx[e[k + 1]] - m.vx[e[k]], m.vy[e[k + 1]] - m.vy[e[k]]);
  return l;
}

}  // namespace

TEST_CASE("rectangle patterns tile the rectangle with counter-clockwise triangles", "[mesh]") {
  struct Expect {
    const char* pattern;
    std::size_t triangles, vertices;
  };
  for (const Expect e : {Expect{"right", 2 * 20 * 2, 21 * 3}, Expect{"left", 2 * 20 * 2, 21 * 3},
                         Expect{"cross", 4 * 20 * 2, 21 * 3 + 20 * 2}}) {
    MeshInput m = generate_rectangle(0.1, 0.01, 0.005, e.pattern, "soil");
    orient_counter_clockwise(m);
    INFO(e.pattern);
    CHECK(m.triangle_count() == e.triangles);
    CHECK(m.vertex_count() == e.vertices);
    CHECK(total_area(m) == Approx(0.1 * 0.01).epsilon(1e-14));
    CHECK(boundary_length(m, "left") == Approx(0.01));
    CHECK(boundary_length(m, "right") == Approx(0.01));
    CHECK(boundary_length(m, "bottom") == Approx(0.1));
    CHECK(boundary_length(m, "top") == Approx(0.1));
  }
}

TEST_CASE("the exploded state: 3 nodes per triangle, a joint per interior edge, one moisture node per vertex", "[mesh]") {
  const Deck deck = ydry_test::strip_deck({"mesh.pattern=\"cross\""});
  const State s = setup_state(deck);
  const std::size_t nt = 4 * 20 * 2, nv = 21 * 3 + 20 * 2;
  CHECK(s.nodes.size() == 3 * nt);
  // Euler for a disc: edges = vertices + triangles - 1; interior = edges - boundary (2 * (20 + 2)).
  const std::size_t edges = nv + nt - 1;
  CHECK(s.joints.size() == edges - 2 * (20 + 2));
  CHECK(s.moisture.size() == nv);
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const index_t* n = &s.joints.node[4 * j];
    CHECK(s.nodes.vertex[n[0]] == s.nodes.vertex[n[3]]);
    CHECK(s.nodes.vertex[n[1]] == s.nodes.vertex[n[2]]);
    CHECK(triangle_of(n[0]) == triangle_of(n[1]));
    CHECK(triangle_of(n[2]) == triangle_of(n[3]));
  }
  for (index_t c = 0; c < s.nodes.size(); ++c)
    CHECK(s.nodes.mnode[c] == s.nodes.mnode[s.moisture.corner[s.moisture.corner_offset[s.nodes.mnode[c]]]]);
  double dry_mass = 0;
  for (const double m : s.moisture.dry_mass) dry_mass += m;
  CHECK(dry_mass == Approx(1333.0 * 0.1 * 0.01 * 1.0).epsilon(1e-13));
}

TEST_CASE("no joints between two materials, and each keeps its own moisture nodes", "[mesh]") {
  const State s = setup_state(load_deck(YDRY_SOURCE_DIR "/tests/data/two_materials.toml", {}));
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    CHECK(s.triangles.material[triangle_of(s.joints.node[4 * j])] ==
          s.triangles.material[triangle_of(s.joints.node[4 * j + 2])]);
  std::set<index_t> soil_vertices;
  for (index_t c = 0; c < s.nodes.size(); ++c) {
    const bool soil = s.material_names[s.triangles.material[triangle_of(c)]] == "soil";
    CHECK((s.nodes.mnode[c] != kNoIndex) == soil);  // the base has no moisture model
    if (soil) soil_vertices.insert(s.nodes.vertex[c]);
  }
  CHECK(s.moisture.size() == soil_vertices.size());
}
