// The shipped Peron case (inputs/peron): its mesh has the geometry of the paper's section 5
// (Fig. 17) and its soil and base are two bodies that only touch.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "tests/test_support.h"
#include "ycore/state/build_state.h"

using namespace ydry;

namespace {

const double kLength = 0.295, kHeight = 0.012;  // the soil layer above the base's top, m
const double kNotch = 0.002;                     // notch width = depth = gap between notches, m
const int kNotches = 73;                         // as many as fit in 295 mm at a 4 mm pitch

// The edges of boundary `name` on triangles of `material`, as (first, second) corner pairs.
std::vector<std::pair<index_t, index_t>> boundary_edges_of(const State& s, const std::string& name,
                                                           std::uint16_t material) {
  std::vector<std::pair<index_t, index_t>> edges;
  const std::vector<index_t>& pairs = s.boundary_edges.at(name);
  for (std::size_t k = 0; k < pairs.size(); k += 2)
    if (s.triangles.material[triangle_of(pairs[k])] == material) edges.emplace_back(pairs[k], pairs[k + 1]);
  return edges;
}

double edge_length(const State& s, const std::pair<index_t, index_t>& e) {
  return std::hypot(s.nodes.x0[e.second] - s.nodes.x0[e.first], s.nodes.y0[e.second] - s.nodes.y0[e.first]);
}

}  // namespace

TEST_CASE("the Peron mesh is the paper's layer filling the notches of a base it is not tied to",
          "[deck][peron]") {
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/inputs/peron/peron.toml", {});
  const State s = build_state(load_mesh(deck), deck);
  const std::uint16_t soil = ydry_test::material_id(s, "soil"), base = ydry_test::material_id(s, "base");

  // The layer plus one 2 x 2 mm tooth per notch (exact for straight edges: round-off only).
  double soil_area = 0.0;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    if (s.triangles.material[t] == soil) soil_area += s.triangles.area0[t];
  CHECK(soil_area == Approx(kLength * kHeight + kNotches * kNotch * kNotch).epsilon(1e-9));

  // Evaporation leaves through the whole top, and only there.
  double top_length = 0.0;
  for (const auto& e : boundary_edges_of(s, "top", soil)) {
    CHECK(s.nodes.y0[e.first] == Approx(kHeight).margin(1e-12));
    top_length += edge_length(s, e);
  }
  CHECK(top_length == Approx(kLength).epsilon(1e-9));
  CHECK(boundary_edges_of(s, "top", base).empty());

  // The soil's side of the interface: its lands, and the walls and bottom of every notch.
  // Each tooth is at least 3 elements across (its bottom edges at most a third of a notch).
  double interface_length = 0.0, longest_tooth_bottom_edge = 0.0;
  for (const auto& e : boundary_edges_of(s, "interface", soil)) {
    interface_length += edge_length(s, e);
    if (std::fabs(s.nodes.y0[e.first] + kNotch) < 1e-12 && std::fabs(s.nodes.y0[e.second] + kNotch) < 1e-12)
      longest_tooth_bottom_edge = std::max(longest_tooth_bottom_edge, edge_length(s, e));
  }
  CHECK(interface_length == Approx(kLength + 2 * kNotches * kNotch).epsilon(1e-9));
  CHECK(longest_tooth_bottom_edge > 0.0);
  CHECK(longest_tooth_bottom_edge <= kNotch / 3.0 * (1.0 + 1e-9));
  CHECK(boundary_edges_of(s, "interface", base).size() == boundary_edges_of(s, "interface", soil).size());

  // Soil and base are two bodies: no joint ties a soil triangle to a base triangle.
  std::size_t mixed = 0;
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    mixed += s.triangles.material[triangle_of(s.joints.node[4 * j])] !=
             s.triangles.material[triangle_of(s.joints.node[4 * j + 2])];
  CHECK(mixed == 0);
}
