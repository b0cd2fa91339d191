// Node sharing across cracks (paper Eqs. 9 and 14, doc/physics.md "Cracks and moisture"): how
// the fan of corners at one vertex splits when joints break, and that the water stays put when
// the moisture nodes are regrouped. The mesh is 2 x 2 cells of 5 mm, "right" diagonals, so the centre vertex
// (5, 5) mm has six triangles and the bottom-middle vertex (5, 0) mm three.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "tests/test_support.h"
#include "ycore/driver/setup.h"
#include "ycrack/node_sharing.h"
#include "ycrack/precracks.h"
#include "ymoist/moisture_setup.h"
#include "ymoist/moisture_step.h"

using namespace ydry;

namespace {

using CornerSets = std::set<std::set<index_t>>;

struct Segment {
  double x0, y0, x1, y1;  // mm
};

struct Configuration {
  const char* name;
  std::vector<Segment> cracks;
  double vertex_x, vertex_y;  // mm: the vertex whose fan is checked
  std::size_t fan_size;       // its corners
  // The expected component of a corner at the vertex, from its triangle's centroid (mm).
  int (*side)(double cx, double cy);
  std::size_t moisture_nodes;  // in the whole mesh once the cracks are in (9 intact)
};

double centroid(const std::vector<double>& coordinate, index_t corner) {
  const index_t c0 = corner_node(triangle_of(corner), 0);
  return (coordinate[c0] + coordinate[c0 + 1] + coordinate[c0 + 2]) / 3.0;
}

struct Fan {
  std::size_t corners = 0;
  CornerSets by_node, by_side;
};

// The corners at the configuration's vertex grouped two ways: by the moisture node they are
// in, and by their expected side.
Fan fan_components(const State& s, const Configuration& c) {
  std::map<index_t, std::set<index_t>> by_node;
  std::map<int, std::set<index_t>> by_side;
  Fan fan;
  for (index_t corner = 0; corner < s.nodes.size(); ++corner) {
    if (std::abs(s.nodes.x0[corner] - 1e-3 * c.vertex_x) > 1e-12 ||
        std::abs(s.nodes.y0[corner] - 1e-3 * c.vertex_y) > 1e-12)
      continue;
    ++fan.corners;
    by_node[s.nodes.mnode[corner]].insert(corner);
    by_side[c.side(1e3 * centroid(s.nodes.x0, corner), 1e3 * centroid(s.nodes.y0, corner))].insert(corner);
  }
  for (const auto& [node, corners] : by_node) fan.by_node.insert(corners);
  for (const auto& [side, corners] : by_side) fan.by_side.insert(corners);
  return fan;
}

}  // namespace

TEST_CASE("a vertex fan splits into the sectors between broken joints, and the water stays", "[moisture][crack]") {
  const Configuration configurations[] = {
      {"interior vertex on a through crack", {{5, 0, 5, 10}}, 5, 5, 6,
       [](double cx, double) { return int(cx < 5); }, 12},
      {"boundary vertex at a crack mouth", {{5, 0, 5, 5}}, 5, 0, 3,
       [](double cx, double) { return int(cx < 5); }, 10},
      {"crack tip: one node (Eq. 14)", {{5, 0, 5, 5}}, 5, 5, 6,
       [](double, double) { return 0; }, 10},
      {"two cracks meeting at a vertex", {{5, 0, 5, 5}, {0, 5, 5, 5}}, 5, 5, 6,
       [](double cx, double cy) { return int(cx < 5 && cy < 5); }, 12},
  };
  const Deck deck = ydry_test::strip_deck({"mesh.size=[0.01, 0.01]"});
  for (const Configuration& c : configurations) {
    INFO(c.name);
    State s = setup_state(deck);
    REQUIRE(s.moisture.size() == 9);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uniform(0.05, 0.6);
    for (double& w : s.moisture.w) w = uniform(rng);
    const std::vector<index_t> old_mnode = s.nodes.mnode;
    const std::vector<double> old_w = s.moisture.w, old_dry_mass = s.moisture.dry_mass;
    const double water_before = total_water_kg(s.moisture);

    Deck precracks;
    for (const Segment& g : c.cracks)
      precracks.cracks.push_back({{1e-3 * g.x0, 1e-3 * g.y0}, {1e-3 * g.x1, 1e-3 * g.y1}, c.name});
    break_joints_along_cracks(s.nodes, precracks.cracks, s.joints);
    group_moisture_nodes(s.joints, s.triangles, std::vector<std::uint8_t>(s.triangles.size(), 1), s.nodes, s.moisture);
    remap_moisture_nodes(moisture_mesh(s), deck, old_mnode, old_w,
                         s.moisture);

    const Fan fan = fan_components(s, c);
    CHECK(fan.corners == c.fan_size);
    CHECK(fan.by_node == fan.by_side);
    CHECK(s.moisture.size() == c.moisture_nodes);

    // Every new node inherits the w of the node it was part of; the parts' dry masses add up
    // to the whole's, so the water does not change (to round-off).
    std::vector<double> parts_dry_mass(old_dry_mass.size(), 0.0);
    for (index_t i = 0; i < s.moisture.size(); ++i) {
      const index_t old = old_mnode[s.moisture.corner[s.moisture.corner_offset[i]]];
      CHECK(s.moisture.w[i] == old_w[old]);
      parts_dry_mass[old] += s.moisture.dry_mass[i];
    }
    for (std::size_t i = 0; i < old_dry_mass.size(); ++i)
      CHECK(parts_dry_mass[i] == Approx(old_dry_mass[i]).epsilon(1e-15));
    CHECK(std::abs(total_water_kg(s.moisture) - water_before) <= 1e-15 * water_before);
  }
}
