// surface.csv end to end: the top of a freely shrinking block against the closed form, one
// row per surface point and frame, and a mesh without a "top" boundary said so in the log.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "tests/test_support.h"

namespace {

struct SurfaceRow {
  double time_s, x0, y0, ux, uy;
  int segment;
};

std::vector<SurfaceRow> read_surface_csv(const std::string& path, std::string& header) {
  std::istringstream text(ydry_test::read_text(path));
  std::getline(text, header);
  std::vector<SurfaceRow> rows;
  for (std::string line; std::getline(text, line);) {
    SurfaceRow r{};
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%d", &r.time_s, &r.x0, &r.y0, &r.ux, &r.uy,
                        &r.segment) == 6);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST_CASE("surface.csv: the top of a free block shrinks as alpha dw (x0 - centroid), a row per point and frame",
          "[output][surface]") {
  // The paper 4.3 block (0.1 m x 0.05 m, w = 0.8 below its stress-free 1.0, alpha = 0.1)
  // without its supports, on 1 cm cells: free isotropic shrinkage eps = alpha dw = -0.02 about
  // the centroid, which stays put (no external force).
  const ydry_test::TempDir dir;
  const auto r = ydry_test::run_ydry(std::string(YDRY_SOURCE_DIR) + "/verification/shrinkage/shrinkage.toml -o " +
                                     dir.file("out") + " --quiet --set mechanics.boundary=[] --set mesh.element_size=0.01"
                                     " --set run.end_time=20 --set run.output_interval=10");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::string header;
  const std::vector<SurfaceRow> rows = read_surface_csv(dir.file("out/surface.csv"), header);
  CHECK(header == "time_s,x0_m,y0_m,ux_m,uy_m,segment");
  const int points = 11, frames = 3;  // x0 = 0, 1, ..., 10 cm; frames at 0, 10 and 20 s
  REQUIRE(rows.size() == std::size_t(points * frames));
  const double eps = 0.1 * (0.8 - 1.0), xc = 0.05, yc = 0.025;
  const double tolerance = 1e-4 * std::fabs(eps) * xc;  // 0.01 % of the largest displacement
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const SurfaceRow& row = rows[k];
    CHECK(row.time_s == 10.0 * double(k / points));
    CHECK(row.x0 == Approx(0.01 * double(k % points)).margin(1e-12));
    CHECK(row.y0 == Approx(0.05).margin(1e-12));
    CHECK(row.segment == 0);
    CHECK(std::fabs(row.ux - eps * (row.x0 - xc)) < tolerance);
    CHECK(std::fabs(row.uy - eps * (row.y0 - yc)) < tolerance);
  }
  CHECK(ydry_test::read_text(dir.file("out/log.txt")).find("surface.csv") != std::string::npos);
}

TEST_CASE("a mesh without a \"top\" boundary writes no surface.csv and says so in the log", "[output][surface]") {
  const ydry_test::TempDir dir;
  ydry_test::write_text(dir.file("one.msh"), ydry_test::kOneTriangleMsh);
  ydry_test::write_text(dir.file("deck.toml"), R"([run]
name = "t"
end_time = 1.0
output_interval = 1.0
gravity = [0.0, 0.0]
[mesh]
file = "one.msh"
[materials.soil]
density = 1000.0
young = 1.0e6
poisson = 0.25
breakable = false
)");
  const auto r = ydry_test::run_ydry(dir.file("deck.toml") + " -o " + dir.file("out") + " --quiet");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_FALSE(std::filesystem::exists(dir.file("out/surface.csv")));
  const std::string log = ydry_test::read_text(dir.file("out/log.txt"));
  CHECK(log.find("no surface.csv: the mesh has no boundary named \"top\"") != std::string::npos);
}
