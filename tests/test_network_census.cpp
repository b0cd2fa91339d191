// The census of a crack network seen in plan (ycrack/network_census.h), on a broken mesh made
// by hand whose cells, areas, perimeters, crack length and junctions are known.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tests/test_support.h"
#include "ycore/driver/setup.h"
#include "ycrack/network_census.h"

using namespace ydry;

namespace {

struct Segment {
  double ax, ay, bx, by;
  // Whether (x, y) lies on it (the mesh's vertices lie on a 1/8 grid: 1e-12 is round-off).
  bool holds(double x, double y) const {
    const double ex = bx - ax, ey = by - ay, dx = x - ax, dy = y - ay;
    const double along = (dx * ex + dy * ey) / (ex * ex + ey * ey);
    return std::fabs(dx * ey - dy * ex) <= 1e-12 && along >= -1e-12 && along <= 1.0 + 1e-12;
  }
};

// A 1 m square of 4 x 4 cells, each of 4 triangles round its centre ("cross"), all joints
// intact, at rest.
State unit_square() {
  return prepare_state(load_deck(YDRY_SOURCE_DIR "/verification/shrinkage/shrinkage.toml",
                                 {"mesh.size=[1.0, 1.0]", "mesh.element_size=0.25", "mesh.pattern=\"cross\""}));
}

// Breaks every joint whose two ends lie on one of the segments.
void break_along(const std::vector<Segment>& cracks, State& s) {
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const index_t a = s.joints.node[4 * j], b = s.joints.node[4 * j + 1];
    for (const Segment& c : cracks)
      if (c.holds(s.nodes.x0[a], s.nodes.y0[a]) && c.holds(s.nodes.x0[b], s.nodes.y0[b])) s.joints.broken[j] = 1;
  }
}

}  // namespace

TEST_CASE("the network census finds the cells, voids and junctions of a network broken by hand", "[census]") {
  // A crack across the square at x = 0.5; one from its middle to the right side (a T); and on
  // the left, a crack from the left side to (0.25, 0.5) that forks there along two cell
  // diagonals to meet the first crack at y = 0.75 and 0.25 (a Y at the fork, two T's where
  // the fork's branches end on the first crack).
  State s = unit_square();
  const double r2 = std::sqrt(2.0);
  break_along({{0.5, 0.0, 0.5, 1.0}, {0.5, 0.5, 1.0, 0.5}, {0.0, 0.5, 0.25, 0.5}, {0.25, 0.5, 0.5, 0.75},
               {0.25, 0.5, 0.5, 0.25}},
              s);
  // The bottom-right cell moved 1 mm to the right: the crack below (0.5, 0.5) opens by 1 mm,
  // and the one above it slides without opening.
  const double shift = 1e-3;
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.nodes.x0[i] >= 0.5 - 1e-12 && s.nodes.y0[i] <= 0.5 + 1e-12) {
      const index_t t = triangle_of(index_t(i));
      double cx = 0.0, cy = 0.0;
      for (int k = 0; k < 3; ++k) cx += s.nodes.x0[corner_node(t, k)] / 3.0, cy += s.nodes.y0[corner_node(t, k)] / 3.0;
      if (cx > 0.5 && cy < 0.5) s.nodes.x[i] += shift;
    }

  const NetworkCensus census = take_network_census(s.nodes, s.triangles, s.joints, s.materials, s.material_names.size());
  constexpr double kRoundOff = 1e-12;
  // Five cells: the two right quarters, the wedge between the fork and the first crack, and the
  // two left regions above and below it.
  REQUIRE(census.cell_area_m2.size() == 5);
  std::vector<double> areas = census.cell_area_m2;
  std::sort(areas.begin(), areas.end());
  const double expected[5] = {0.0625, 0.21875, 0.21875, 0.25, 0.25};
  for (int k = 0; k < 5; ++k) CHECK(std::fabs(areas[k] - expected[k]) <= kRoundOff);
  CHECK(std::fabs(census.layer_area_m2 - 1.0) <= kRoundOff);
  // Crack length: 1 + 0.5 + 0.25 + two forks of 0.25 sqrt 2; every crack is the outline of two
  // cells, the square's side of one.
  const double length = 1.75 + 0.5 * r2;
  CHECK(std::fabs(census.crack_length_m - length) <= kRoundOff);
  CHECK(std::fabs(census.crack_density_per_m() - length) <= kRoundOff);
  double perimeters = 0.0;
  for (const double p : census.cell_perimeter_m) perimeters += p;
  // The moved cell's outline is the same length; the square's right side below 0.5 is still
  // 0.5 long and its bottom side 0.5.
  CHECK(std::fabs(perimeters - (4.0 + 2.0 * length)) <= 1e-9);
  // The void: 1 mm over the 0.5 m of the first crack below the T.
  CHECK(std::fabs(census.crack_area_m2 - 0.5 * shift) <= 1e-12);
  CHECK(std::fabs(census.crack_intensity() - 0.5 * shift) <= 1e-12);

  // Junctions, by vertex: (0.25, 0.5) the Y, then (0.5, 0.25), (0.5, 0.5), (0.5, 0.75), the T's.
  REQUIRE(census.junctions.size() == 4);
  CHECK(census.count(JunctionKind::T) == 3);
  CHECK(census.count(JunctionKind::Y) == 1);
  for (const Junction& j : census.junctions) {
    INFO("junction at " << j.x0 << ", " << j.y0);
    REQUIRE(j.angles.size() == 3);
    // Counter-clockwise from the branch nearest +x (of two as near, the first from -180).
    std::vector<double> want;
    if (j.x0 < 0.4) want = {90, 135, 135};            // the Y: branches at -45, 45, 180 degrees
    else if (j.y0 < 0.4) want = {180, 45, 135};       // -90, 90, 135
    else if (j.y0 < 0.6) want = {90, 180, 90};        // 0, 90, -90
    else want = {180, 135, 45};                       // -90, 90, -135
    for (int k = 0; k < 3; ++k) CHECK(std::fabs(j.angles[k] - want[k]) <= 1e-9);
  }
}

TEST_CASE("a plan-view run writes its network at every row and its cells and junctions at every frame, "
          "the same after a restart", "[census][planview]") {
  // The shear-lag strip cut by hand along its middle both ways: four cells, one junction of
  // four branches at right angles, 0.205 m of crack.
  ydry_test::TempDir dir;
  const std::string deck = YDRY_SOURCE_DIR "/verification/shear_lag/shear_lag.toml";
  const std::string sets = " --quiet --set run.end_time=4 --set run.output_interval=2 --set solver.max_coupling_step=1 "
                           "--set 'cracks=[{from=[0.1,0.0],to=[0.1,0.005]},{from=[0.0,0.0025],to=[0.2,0.0025]}]'";
  const auto whole = ydry_test::run_ydry(deck + " -o " + dir.file("whole") + sets + " --checkpoint-every-steps 2");
  INFO(whole.output);
  REQUIRE(whole.exit_code == 0);
  const std::string network = ydry_test::read_text(dir.file("whole/network.csv"));
  const std::string cells = ydry_test::read_text(dir.file("whole/cells.csv"));
  const std::string junctions = ydry_test::read_text(dir.file("whole/junctions.csv"));
  // A row and a frame at 0, 2 and 4 s (run.series_interval is the output interval).
  CHECK(std::count(network.begin(), network.end(), '\n') == 1 + 3);
  CHECK(std::count(cells.begin(), cells.end(), '\n') == 1 + 3 * 4);
  CHECK(network.find("\n4,4,") != std::string::npos);
  CHECK(network.find(",0.20499999999999999,") != std::string::npos);
  CHECK(junctions.find("\n4,0.10000000000000001,0.0025000000000000001,other,4,90 90 90 90\n") != std::string::npos);
  // Restarted from coupling step 2: the same files, bit for bit.
  std::filesystem::copy(dir.file("whole"), dir.file("restarted"), std::filesystem::copy_options::recursive);
  const auto restarted = ydry_test::run_ydry("--restart " + dir.file("restarted/checkpoints/shear_lag_000002.chk") + " --quiet");
  INFO(restarted.output);
  REQUIRE(restarted.exit_code == 0);
  for (const char* file : {"network.csv", "cells.csv", "junctions.csv"})
    CHECK(ydry_test::read_text(dir.file(std::string("restarted/") + file)) ==
          ydry_test::read_text(dir.file(std::string("whole/") + file)));
}
