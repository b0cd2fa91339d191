// Crack statistics and crack output on hand-built states: a 40 mm x 20 mm rectangle of 5 mm
// cells whose joints are broken and whose nodes are moved by hand.
#include <catch2/catch.hpp>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <utility>

#include "tests/test_support.h"
#include "ycore/state/mesh_rectangle.h"
#include "ycore/state/build_state.h"
#include "ycore/output/csv_table.h"
#include "ycore/output/vtk_output.h"
#include "ycrack/crack_statistics.h"
#include "ycrack/cracks_csv.h"
#include "ycrack/node_sharing.h"
#include "ycrack/surface_profile.h"

using namespace ydry;

namespace {

constexpr double kWidth = 0.04, kHeight = 0.02, kCell = 0.005;

State rectangle_state() {
  Deck deck;
  deck.materials["soil"] = MaterialDeck{};
  MeshInput mesh = generate_rectangle(kWidth, kHeight, kCell, "right", "soil");
  orient_counter_clockwise(mesh);
  return build_state(mesh, deck);
}

// The joints whose two ends lie in the box [x_from, x_to] x [y_from, y_to] (initial
// positions): a vertical or horizontal line when the box is flat.
std::vector<std::size_t> joints_within(const State& s, double x_from, double x_to, double y_from, double y_to) {
  const auto inside = [&](index_t c) {
    return s.nodes.x0[c] >= x_from - 1e-12 && s.nodes.x0[c] <= x_to + 1e-12 && s.nodes.y0[c] >= y_from - 1e-12 &&
           s.nodes.y0[c] <= y_to + 1e-12;
  };
  std::vector<std::size_t> found;
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    if (inside(s.joints.node[4 * j]) && inside(s.joints.node[4 * j + 1])) found.push_back(j);
  return found;
}

// Breaks the joints of joints_within; returns how many.
int break_within(State& s, double x_from, double x_to, double y_from, double y_to) {
  const std::vector<std::size_t> found = joints_within(s, x_from, x_to, y_from, y_to);
  for (const std::size_t j : found) s.joints.broken[j] = 1;
  return int(found.size());
}

// Breaks the joints on the vertical line x between heights y_from and y_to; returns how many.
int break_vertical(State& s, double x, double y_from, double y_to) { return break_within(s, x, x, y_from, y_to); }

// The broken joint with the lowest index: the first line of the cracks frame.
index_t first_broken(const State& s) {
  index_t joint = 0;
  while (!s.joints.broken[joint]) ++joint;
  return joint;
}

double centroid_x0(const State& s, index_t t) {
  return (s.nodes.x0[3 * t] + s.nodes.x0[3 * t + 1] + s.nodes.x0[3 * t + 2]) / 3.0;
}

// Moves every triangle whose centroid lies right of x by dx, rigidly.
void shift_right_of(State& s, double x, double dx) {
  for (index_t t = 0; t < s.triangles.size(); ++t) {
    if (centroid_x0(s, t) > x)
      for (int a = 0; a < 3; ++a) s.nodes.x[corner_node(t, a)] += dx;
  }
}

// A full-height crack at x = 30 mm opened by 80 um, and one through the upper half at
// x = 10 mm opened by 200 um. The first is found first (its joints come first), so the
// order of the result is the order in x, not of discovery.
State two_crack_state() {
  State s = rectangle_state();
  REQUIRE(break_vertical(s, 0.03, 0.0, kHeight) == 4);
  REQUIRE(break_vertical(s, 0.01, kHeight / 2, kHeight) == 2);
  shift_right_of(s, 0.01, 200e-6);
  shift_right_of(s, 0.03, 80e-6);
  return s;
}

}  // namespace

TEST_CASE("two broken vertical lines are two cracks, in x order, with their lengths", "[crack]") {
  const std::vector<Crack> cracks = find_cracks(two_crack_state(), 0.0);
  REQUIRE(cracks.size() == 2);
  CHECK(cracks[0].x_m == Approx(0.01).margin(200e-6));
  CHECK(cracks[1].x_m == Approx(0.03 + 200e-6).margin(80e-6));  // it moved with the right part
  CHECK(cracks[0].length_m == Approx(kHeight / 2).epsilon(1e-12));
  CHECK(cracks[1].length_m == Approx(kHeight).epsilon(1e-12));
  CHECK(cracks[0].joints.size() == 2);
  CHECK(cracks[1].joints.size() == 4);
}

TEST_CASE("a crack reaching the bottom penetrates, one stopping halfway does not", "[crack]") {
  const std::vector<Crack> cracks = find_cracks(two_crack_state(), 0.0);
  REQUIRE(cracks.size() == 2);
  CHECK_FALSE(cracks[0].penetrating);
  CHECK(cracks[1].penetrating);
}

TEST_CASE("a crack's width is the opening imposed at its mouth on the top surface", "[crack]") {
  const std::vector<Crack> cracks = find_cracks(two_crack_state(), 0.0);
  REQUIRE(cracks.size() == 2);
  CHECK(cracks[0].width_m == Approx(200e-6).epsilon(1e-9));
  CHECK(cracks[1].width_m == Approx(80e-6).epsilon(1e-9));
}

TEST_CASE("the width threshold drops the narrower crack", "[crack]") {
  const State s = two_crack_state();
  const std::vector<Crack> cracks = find_cracks(s, 100e-6);
  REQUIRE(cracks.size() == 1);
  CHECK(cracks[0].width_m == Approx(200e-6).epsilon(1e-9));
  CHECK(find_cracks(s, 300e-6).empty());
}

TEST_CASE("broken stretches linked by a joint in the process zone are one crack; by a slightly damaged one, two", "[crack]") {
  // On x = 20 mm: broken from the top down to 10 mm and from 5 mm to the bottom; the joint
  // between (5 to 10 mm) carries committed damage `d` at its three points.
  for (const double d : {kProcessZoneDamage, 0.1}) {
    INFO("damage of the linking joint " << d);
    State s = rectangle_state();
    REQUIRE(break_vertical(s, 0.02, 0.01, kHeight) == 2);
    REQUIRE(break_vertical(s, 0.02, 0.0, 0.005) == 1);
    s.joints.damage.assign(3 * s.joints.size(), 0.0);
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
      const index_t* n = &s.joints.node[4 * j];
      const double ylo = std::min(s.nodes.y0[n[0]], s.nodes.y0[n[1]]);
      if (std::abs(s.nodes.x0[n[0]] - 0.02) < 1e-12 && std::abs(s.nodes.x0[n[1]] - 0.02) < 1e-12 &&
          std::abs(ylo - 0.005) < 1e-12)
        for (int p = 0; p < 3; ++p) s.joints.damage[3 * j + p] = d;
    }
    shift_right_of(s, 0.02, 100e-6);
    const std::vector<Crack> cracks = find_cracks(s, 0.0);
    if (d >= kProcessZoneDamage) {
      REQUIRE(cracks.size() == 1);
      CHECK(cracks[0].joints.size() == 4);
      CHECK(cracks[0].length_m == Approx(0.015).epsilon(1e-12));  // the broken joints only
      CHECK(cracks[0].penetrating);
      CHECK(cracks[0].width_m == Approx(100e-6).epsilon(1e-9));   // at the mouth on the top
    } else {
      REQUIRE(cracks.size() == 2);
      CHECK(cracks[0].length_m + cracks[1].length_m == Approx(0.015).epsilon(1e-12));
    }
  }
}

TEST_CASE("a crack that meets the top at a broken joint and, through its process zone, at a shut vertex has its mouth where it gapes", "[crack]") {
  // On x = 20 mm: broken from the top down to 15 mm, opened 100 um. From its lower end a process
  // zone (horizontal joint at y = 15 mm, vertical joint up to the top) reaches the top at
  // x = 15 mm, or at x = 25 mm, where nothing opens. One side or the other has the lower vertex
  // id, which would choose the mouth (and so a width of 0) if the opening did not come first.
  for (const double branch_x : {0.015, 0.025}) {
    INFO("process zone up to the top at x = " << branch_x);
    State s = rectangle_state();
    REQUIRE(break_vertical(s, 0.02, 0.015, kHeight) == 1);
    s.joints.damage.assign(3 * s.joints.size(), 0.0);
    std::vector<std::size_t> zone = joints_within(s, std::min(branch_x, 0.02), std::max(branch_x, 0.02), 0.015, 0.015);
    const std::vector<std::size_t> up = joints_within(s, branch_x, branch_x, 0.015, kHeight);
    zone.insert(zone.end(), up.begin(), up.end());
    REQUIRE(zone.size() == 2);
    for (const std::size_t j : zone)
      for (int p = 0; p < 3; ++p) s.joints.damage[3 * j + p] = kProcessZoneDamage;
    shift_right_of(s, 0.02, 100e-6);
    const std::vector<Crack> cracks = find_cracks(s, 1e-5);
    REQUIRE(cracks.size() == 1);
    CHECK(cracks[0].joints.size() == 3);
    CHECK(cracks[0].on_top_surface);
    CHECK(cracks[0].width_m == Approx(100e-6).epsilon(1e-9));
    CHECK(cracks[0].x_m == Approx(0.02).margin(100e-6));  // at x = 20 mm, not at the shut vertex
  }
}

TEST_CASE("an internal crack is measured at its highest vertex", "[crack]") {
  // One joint on x = 20 mm from y = 5 mm to 10 mm: no vertex on a surface. Its first
  // triangle's side is pulled back along the normal by 50 um.
  State s = rectangle_state();
  REQUIRE(break_vertical(s, 0.02, 0.005, 0.01) == 1);
  const index_t* n = &s.joints.node[4 * first_broken(s)];
  const double nx = s.nodes.y0[n[0]] < s.nodes.y0[n[1]] ? -1.0 : 1.0;  // into the first triangle
  for (const int k : {0, 1}) s.nodes.x[n[k]] += 50e-6 * nx;
  const std::vector<Crack> cracks = find_cracks(s, 0.0);
  REQUIRE(cracks.size() == 1);
  CHECK(cracks[0].width_m == Approx(50e-6).epsilon(1e-9));
  CHECK(cracks[0].length_m == Approx(0.005).epsilon(1e-12));
  CHECK(cracks[0].x_m == Approx(0.02).margin(50e-6));
  CHECK_FALSE(cracks[0].penetrating);
}

TEST_CASE("a crack pressed shut or slid shut is a closed crack: counted apart, not among the cracks", "[crack]") {
  // The internal crack of the case above, its first triangle's side moved 50 um: against the
  // other face (opening -50 um), or along the crack (slip 50 um, opening 0), or away from it.
  for (const char* motion : {"pressed", "slid", "opened"}) {
    State s = rectangle_state();
    REQUIRE(break_vertical(s, 0.02, 0.005, 0.01) == 1);
    const index_t* n = &s.joints.node[4 * first_broken(s)];
    const double nx = s.nodes.y0[n[0]] < s.nodes.y0[n[1]] ? -1.0 : 1.0;  // into the first triangle
    for (const int k : {0, 1}) {
      if (motion == std::string("slid")) s.nodes.y[n[k]] += 50e-6;
      else s.nodes.x[n[k]] += (motion == std::string("pressed") ? -50e-6 : 50e-6) * nx;
    }
    INFO(motion);
    const bool open = motion == std::string("opened");
    const CrackCensus census = take_crack_census(s, 1e-5);
    CHECK(census.open.size() == (open ? 1u : 0u));
    CHECK(census.closed == (open ? 0 : 1));
    CHECK(find_all_cracks(s).size() == 1u);
  }
  const CrackCensus two = take_crack_census(two_crack_state(), 1e-5);
  CHECK(two.open.size() == 2u);
  CHECK(two.closed == 0);
}

TEST_CASE("a crack reaching the top splits its surface vertex into two points on two segments", "[crack][surface]") {
  // Top edges of the 40 mm rectangle: vertices every 5 mm. The x = 10 mm crack (upper half,
  // 200 um) and the x = 30 mm one (full height, 80 um) reach the top; a third through the
  // lower half at x = 20 mm does not, so that vertex stays one point.
  State s = two_crack_state();
  REQUIRE(break_vertical(s, 0.02, 0.0, kHeight / 2) == 2);
  tie_corners(s.joints, s.nodes);
  const std::vector<SurfacePoint> points = surface_profile(s.nodes, s.boundary_edges.at("top"));
  REQUIRE(points.size() == 9 + 2);
  const double x0[11] = {0, 5, 10, 10, 15, 20, 25, 30, 30, 35, 40};  // mm
  const int segment[11] = {0, 0, 0, 1, 1, 1, 1, 1, 2, 2, 2};
  const double ux[3] = {0.0, 200e-6, 280e-6};  // each segment's rigid shift
  for (std::size_t k = 0; k < points.size(); ++k) {
    INFO("point " << k);
    CHECK(points[k].x0_m == Approx(1e-3 * x0[k]).margin(1e-12));
    CHECK(points[k].y0_m == Approx(kHeight).margin(1e-12));
    CHECK(points[k].segment == segment[k]);
    CHECK(points[k].ux_m == Approx(ux[segment[k]]).margin(1e-15));
    CHECK(points[k].uy_m == Approx(0.0).margin(1e-15));
  }
}

TEST_CASE("the crack summary: count, mean and total width, mean length", "[crack]") {
  const CrackSummary sum = summarize_cracks(find_cracks(two_crack_state(), 0.0));
  CHECK(sum.count == 2);
  CHECK(sum.surface_count == 2);  // both open on the top
  CHECK(sum.surface_total_width_m == sum.total_width_m);
  CHECK(sum.total_width_m == Approx(280e-6).epsilon(1e-9));
  CHECK(sum.mean_width_m == Approx(140e-6).epsilon(1e-9));
  CHECK(sum.mean_length_m == Approx(0.75 * kHeight).epsilon(1e-12));
  const CrackSummary none = summarize_cracks({});
  CHECK(none.count == 0);
  CHECK(none.total_width_m == 0.0);
  CHECK(std::isnan(none.mean_width_m));
  CHECK(std::isnan(none.mean_length_m));
  CHECK(std::isnan(none.surface_mean_width_m));
}

TEST_CASE("a crack rising from the interface with a base is measured there and is no surface crack", "[crack]") {
  // The rectangle's lowest row of cells (y < 5 mm) is a base: no joints tie it to the soil.
  Deck deck;
  deck.materials["soil"] = MaterialDeck{};
  deck.materials["base"] = MaterialDeck{};
  MeshInput mesh = generate_rectangle(kWidth, kHeight, kCell, "right", "soil");
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    double y = 0;
    for (int a = 0; a < 3; ++a) y += mesh.vy[mesh.tri[3 * t + a]] / 3.0;
    if (y < kCell) mesh.tri_material[t] = "base";
  }
  orient_counter_clockwise(mesh);
  State s = build_state(mesh, deck);
  REQUIRE(break_vertical(s, 0.01, kCell, 2 * kCell) == 1);   // from the base up to 10 mm
  REQUIRE(break_vertical(s, 0.03, kHeight - kCell, kHeight) == 1);  // from the top down to 15 mm
  const std::uint16_t soil = ydry_test::material_id(s, "soil");
  for (const auto& [x, opening] : {std::pair{0.01, 100e-6}, std::pair{0.03, 60e-6}})
    for (index_t t = 0; t < s.triangles.size(); ++t)
      if (s.triangles.material[t] == soil && centroid_x0(s, t) > x)
        for (int a = 0; a < 3; ++a) s.nodes.x[corner_node(t, a)] += opening;

  const std::vector<Crack> cracks = find_cracks(s, 0.0);
  REQUIRE(cracks.size() == 2);
  CHECK_FALSE(cracks[0].on_top_surface);
  CHECK(cracks[0].width_m == Approx(100e-6).epsilon(1e-9));  // at its mouth on the interface
  CHECK(cracks[1].on_top_surface);
  CHECK(cracks[1].width_m == Approx(60e-6).epsilon(1e-9));
  const CrackSummary sum = summarize_cracks(cracks);
  CHECK(sum.count == 2);
  CHECK(sum.surface_count == 1);
  CHECK(sum.surface_mean_width_m == Approx(60e-6).epsilon(1e-9));
  CHECK(sum.mean_width_m == Approx(80e-6).epsilon(1e-9));
}

TEST_CASE("a crack opening from the end of a layer is no surface crack: only the top is seen from above", "[crack]") {
  State s = rectangle_state();
  // Along y = 10 mm from the left end (x = 0) to x = 10 mm, the upper half lifted by 50 um.
  REQUIRE(break_within(s, 0.0, 2 * kCell, kHeight / 2, kHeight / 2) == 2);
  for (index_t t = 0; t < s.triangles.size(); ++t) {
    const double y = (s.nodes.y0[3 * t] + s.nodes.y0[3 * t + 1] + s.nodes.y0[3 * t + 2]) / 3.0;
    if (y > kHeight / 2)
      for (int a = 0; a < 3; ++a) s.nodes.y[corner_node(t, a)] += 50e-6;
  }
  const std::vector<Crack> cracks = find_cracks(s, 0.0);
  REQUIRE(cracks.size() == 1);
  CHECK_FALSE(cracks[0].on_top_surface);
  CHECK(cracks[0].x_m == Approx(0.0).margin(1e-12));          // its mouth on the left end
  CHECK(cracks[0].width_m == Approx(50e-6).epsilon(1e-9));
  const CrackSummary sum = summarize_cracks(cracks);
  CHECK(sum.count == 1);
  CHECK(sum.surface_count == 0);
}

namespace {

vtkNew<vtkXMLUnstructuredGridReader> read_vtu(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader;
}

}  // namespace

TEST_CASE("the cracks frame holds a line per broken joint with its opening, and reads back", "[crack][output]") {
  const ydry_test::TempDir dir;
  std::filesystem::create_directories(dir.path / "frames");
  FrameSeries series{dir.path.string(), "t", {}, {}};
  State s = rectangle_state();
  write_frame(series, s, 0.0);  // no broken joint yet: an empty grid
  State cracked = two_crack_state();
  const std::size_t nt = cracked.triangles.size();
  cracked.triangles.sxx.assign(nt, 1.0e3);
  cracked.triangles.syy.assign(nt, -2.0e3);
  cracked.triangles.sxy.assign(nt, 0.5e3);
  for (std::size_t j = 0; j < cracked.joints.size(); ++j) cracked.joints.strength_factor.push_back(1.0 + 1e-3 * j);
  write_frame(series, cracked, 3600.0);
  // The same cracks with moisture: 0.3 left of the x = 30 mm crack, 0.1 right of it.
  State wet = two_crack_state();
  wet.moisture.w.resize(
      group_moisture_nodes(wet.joints, wet.triangles, std::vector<std::uint8_t>(wet.triangles.size(), 1), wet.nodes, wet.moisture));
  for (index_t c = 0; c < wet.nodes.size(); ++c)
    wet.moisture.w[wet.nodes.mnode[c]] = centroid_x0(wet, triangle_of(c)) < 0.03 ? 0.3 : 0.1;
  write_frame(series, wet, 7200.0);

  auto empty = read_vtu(dir.file("frames/t_cracks_000000.vtu"));
  CHECK(empty->GetErrorCode() == 0);
  CHECK(empty->GetOutput()->GetNumberOfCells() == 0);
  CHECK(read_vtu(dir.file("frames/t_000000.vtu"))->GetOutput()->GetCellData()->GetArray("stress") == nullptr);
  CHECK(empty->GetOutput()->GetCellData()->GetArray("strength_factor") == nullptr);  // no mechanics

  auto lines = read_vtu(dir.file("frames/t_cracks_000001.vtu"));
  vtkUnstructuredGrid* grid = lines->GetOutput();
  REQUIRE(grid->GetNumberOfCells() == 6);
  vtkDataArray* opening = grid->GetCellData()->GetArray("opening");
  REQUIRE(opening != nullptr);
  REQUIRE(grid->GetCellData()->GetArray("slip") != nullptr);
  // The cells follow the joints in order: the first one is the bottom of the x = 30 mm crack.
  CHECK(opening->GetTuple1(0) == Approx(80e-6).epsilon(1e-9));
  double p[3];
  grid->GetPoint(0, p);
  CHECK(p[0] == Approx(0.03 + 200e-6 + 40e-6).margin(1e-12));
  CHECK(p[1] == Approx(0.0).margin(1e-12));
  CHECK(grid->GetCellData()->GetArray("slip")->GetTuple1(0) == Approx(0.0).margin(1e-15));
  REQUIRE(grid->GetCellData()->GetArray("moisture_face1") != nullptr);
  CHECK(std::isnan(grid->GetCellData()->GetArray("moisture_face1")->GetTuple1(0)));  // no moisture model
  REQUIRE(grid->GetCellData()->GetArray("strength_factor") != nullptr);
  CHECK(grid->GetCellData()->GetArray("strength_factor")->GetTuple1(0) == 1.0 + 1e-3 * first_broken(cracked));

  // Each face carries the moisture of its own side: face 1 is the first triangle's edge.
  auto wet_lines = read_vtu(dir.file("frames/t_cracks_000002.vtu"));
  vtkDataArray* face1 = wet_lines->GetOutput()->GetCellData()->GetArray("moisture_face1");
  vtkDataArray* face2 = wet_lines->GetOutput()->GetCellData()->GetArray("moisture_face2");
  REQUIRE(face1 != nullptr);
  REQUIRE(face2 != nullptr);
  const bool face1_left = centroid_x0(wet, triangle_of(wet.joints.node[4 * first_broken(wet)])) < 0.03;
  CHECK(face1->GetTuple1(0) == (face1_left ? 0.3 : 0.1));
  CHECK(face2->GetTuple1(0) == (face1_left ? 0.1 : 0.3));

  auto bulk = read_vtu(dir.file("frames/t_000001.vtu"));
  vtkDataArray* stress = bulk->GetOutput()->GetCellData()->GetArray("stress");
  REQUIRE(stress != nullptr);
  CHECK(stress->GetNumberOfComponents() == 3);
  CHECK(std::string(stress->GetComponentName(2)) == "sxy");
  CHECK(stress->GetComponent(0, 1) == Approx(-2.0e3).epsilon(1e-15));

  const std::string pvd = ydry_test::read_text(dir.file("t.pvd"));
  CHECK(pvd.find("timestep=\"3600\" part=\"1\" file=\"frames/t_cracks_000001.vtu\"") != std::string::npos);
  CHECK(pvd.find("timestep=\"3600\" part=\"0\" file=\"frames/t_000001.vtu\"") != std::string::npos);
}

TEST_CASE("cracks.csv gains a row per crack at each output time and keeps the earlier ones", "[crack][output]") {
  const ydry_test::TempDir dir;
  CsvTable csv{dir.file("cracks.csv"), kCracksCsvHeader, ""};
  csv.append(cracks_csv_rows(0.0, find_cracks(rectangle_state(), 1e-5)));
  CHECK(ydry_test::read_text(csv.path) == "time_s,crack_id,x_m,width_m,length_m,penetrating,surface\n");
  csv.append(cracks_csv_rows(7200.0, find_cracks(two_crack_state(), 1e-5)));

  std::istringstream text(ydry_test::read_text(csv.path));
  std::string header, line;
  std::getline(text, header);
  CHECK(header == "time_s,crack_id,x_m,width_m,length_m,penetrating,surface");
  const double expected_width[2] = {200e-6, 80e-6}, expected_length[2] = {kHeight / 2, kHeight};
  int rows = 0;
  while (std::getline(text, line) && rows < 2) {
    double time = 0, x = 0, width = 0, length = 0;
    int id = -1, penetrating = -1, surface = -1;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf,%lf,%d,%d", &time, &id, &x, &width, &length,
                        &penetrating, &surface) == 7);
    CHECK(id == rows);
    CHECK(time == Approx(7200.0).epsilon(1e-15));
    CHECK(width == Approx(expected_width[rows]).epsilon(1e-9));
    CHECK(length == Approx(expected_length[rows]).epsilon(1e-12));
    CHECK(penetrating == rows);  // only the full-height crack, second in x
    CHECK(surface == 1);         // both open on the top
    ++rows;
  }
  CHECK(rows == 2);
  CHECK_FALSE(std::getline(text, line));
}
