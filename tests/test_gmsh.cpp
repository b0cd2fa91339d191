// read_gmsh: the two-layer mesh in tests/data (made by gmsh from two_materials.geo), and
// small hand-written files for the errors, each of which must name the file and line.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "tests/test_support.h"
#include "ycore/input/input_error.h"
#include "ycore/state/mesh_gmsh.h"

using ydry::InputError;
using ydry::MeshInput;
using ydry::read_gmsh;
using ydry_test::kOneTriangleMsh;

namespace {

const std::string data_dir = std::string(YDRY_SOURCE_DIR) + "/tests/data/";

std::string write_temp(const std::string& name, const std::string& text) {
  static const ydry_test::TempDir dir;
  ydry_test::write_text(dir.file(name), text);
  return dir.file(name);
}

// The message of the InputError read_gmsh throws for `path`; fails the test if none.
std::string gmsh_error(const std::string& path) {
  try {
    read_gmsh(path);
  } catch (const InputError& error) {
    return error.what();
  }
  FAIL("read_gmsh accepted " << path);
  return "";
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

double triangle_area(const MeshInput& mesh, std::size_t t) {
  const auto a = mesh.tri[3 * t], b = mesh.tri[3 * t + 1], c = mesh.tri[3 * t + 2];
  return 0.5 * std::abs((mesh.vx[b] - mesh.vx[a]) * (mesh.vy[c] - mesh.vy[a]) -
                        (mesh.vx[c] - mesh.vx[a]) * (mesh.vy[b] - mesh.vy[a]));
}

double total_length(const MeshInput& mesh, const std::vector<ydry::index_t>& edges) {
  double length = 0.0;
  for (std::size_t e = 0; e < edges.size(); e += 2)
    length += std::hypot(mesh.vx[edges[e + 1]] - mesh.vx[edges[e]],
                         mesh.vy[edges[e + 1]] - mesh.vy[edges[e]]);
  return length;
}

}  // namespace

TEST_CASE("input_location leaves out line 0", "[gmsh]") {
  CHECK(ydry::input_location("a.msh", 12, "mesh.file") == "a.msh:12: mesh.file: ");
  CHECK(ydry::input_location("a.msh", 0, "mesh.file") == "a.msh: mesh.file: ");
}

TEST_CASE("gmsh: two-material rectangle", "[gmsh]") {
  const MeshInput mesh = read_gmsh(data_dir + "two_materials.msh");
  // The file holds 32 nodes, 22 triangles in each surface.
  REQUIRE(mesh.vertex_count() == 32);
  REQUIRE(mesh.vy.size() == 32);
  REQUIRE(mesh.triangle_count() == 44);
  REQUIRE(mesh.tri.size() == 3 * 44);
  for (const auto v : mesh.tri) REQUIRE(v < mesh.vertex_count());

  double soil_area = 0.0, base_area = 0.0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& material = mesh.tri_material[t];
    REQUIRE((material == "soil" || material == "base"));
    (material == "soil" ? soil_area : base_area) += triangle_area(mesh, t);
    // The layers meet at y = 0.5: soil above, base below.
    for (int k = 0; k < 3; ++k) {
      const double y = mesh.vy[mesh.tri[3 * t + k]];
      CHECK((material == "soil" ? y >= 0.5 - 1e-12 : y <= 0.5 + 1e-12));
    }
  }
  CHECK(soil_area == Approx(1.0).margin(1e-12));
  CHECK(base_area == Approx(1.0).margin(1e-12));

  std::set<std::string> names;
  for (const auto& [name, edges] : mesh.boundaries) names.insert(name);
  CHECK(names == std::set<std::string>{"bottom", "interface", "outer", "top"});

  const auto on_line = [&](const std::string& name, auto on) {
    const auto& edges = mesh.boundaries.at(name);
    REQUIRE(!edges.empty());
    REQUIRE(edges.size() % 2 == 0);
    for (const auto v : edges) CHECK(on(mesh.vx[v], mesh.vy[v]));
  };
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12; };
  on_line("top", [&](double, double y) { return near(y, 1.0); });
  on_line("bottom", [&](double, double y) { return near(y, 0.0); });
  on_line("interface", [&](double, double y) { return near(y, 0.5); });
  on_line("outer", [&](double x, double y) {
    return near(x, 0.0) || near(x, 2.0) || near(y, 0.0) || near(y, 1.0);
  });
  CHECK(total_length(mesh, mesh.boundaries.at("top")) == Approx(2.0).margin(1e-12));
  CHECK(total_length(mesh, mesh.boundaries.at("bottom")) == Approx(2.0).margin(1e-12));
  CHECK(total_length(mesh, mesh.boundaries.at("interface")) == Approx(2.0).margin(1e-12));
  // "outer" shares its top and bottom curves with "top" and "bottom".
  CHECK(total_length(mesh, mesh.boundaries.at("outer")) == Approx(6.0).margin(1e-12));
}

TEST_CASE("gmsh: parametric node coordinates are skipped", "[gmsh]") {
  const MeshInput plain = read_gmsh(data_dir + "two_materials.msh");
  const MeshInput parametric = read_gmsh(data_dir + "two_materials_parametric.msh");
  CHECK(parametric.vx == plain.vx);
  CHECK(parametric.vy == plain.vy);
  CHECK(parametric.tri == plain.tri);
  CHECK(parametric.tri_material == plain.tri_material);
  CHECK(parametric.boundaries == plain.boundaries);
}

TEST_CASE("gmsh: sparse node tags become dense vertex indices", "[gmsh]") {
  const MeshInput mesh = read_gmsh(write_temp("one_triangle.msh", kOneTriangleMsh));
  CHECK(mesh.vx == std::vector<double>{0, 1, 0});
  CHECK(mesh.vy == std::vector<double>{0, 0, 1});
  CHECK(mesh.tri == std::vector<ydry::index_t>{2, 0, 1});  // node tags 30 10 20
  CHECK(mesh.tri_material == std::vector<std::string>{"soil"});
  CHECK(mesh.boundaries.empty());
}

TEST_CASE("gmsh: unknown sections are skipped", "[gmsh]") {
  const auto text = kOneTriangleMsh + "$NodeData\n1\n\"h\"\n1\n0.0\n3\n0\n1\n3\n10 1\n20 1\n30 1\n"
                                   "$EndNodeData\n";
  CHECK(read_gmsh(write_temp("node_data.msh", text)).triangle_count() == 1);
}

TEST_CASE("gmsh: errors name the file and line", "[gmsh]") {
  SECTION("format version") {
    const auto path = write_temp("version.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":2: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("2.2"));
  }
  SECTION("binary file") {
    const auto path = write_temp("binary.msh", replaced(kOneTriangleMsh, "4.1 0 8", "4.1 1 8"));
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":2: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("binary"));
  }
  SECTION("quadrangle") {
    const auto path = write_temp(
        "quad.msh", replaced(kOneTriangleMsh, "2 1 2 1\n1 30 10 20", "2 1 3 1\n1 30 10 20 40"));
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":24: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("element type 3"));
  }
  SECTION("surface without a physical surface") {
    const auto path = write_temp(
        "no_physical.msh", replaced(kOneTriangleMsh, "1 0 0 0 1 1 0 1 1 0", "1 0 0 0 1 1 0 0 0"));
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":24: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("no physical surface"));
  }
  SECTION("truncated $Nodes") {
    const auto nodes_cut = kOneTriangleMsh.substr(0, kOneTriangleMsh.find("\n30\n") + 1);
    const auto path = write_temp("truncated.msh", nodes_cut);
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":16: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("$Nodes"));
  }
  SECTION("node off the plane z = 0") {
    const auto path =
        write_temp("not_planar.msh", replaced(kOneTriangleMsh, "\n1 0 0\n", "\n1 0 1e-6\n"));
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":19: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("not planar"));
  }
  SECTION("element on an unknown node") {
    const auto path =
        write_temp("unknown_node.msh", replaced(kOneTriangleMsh, "1 30 10 20", "1 30 10 21"));
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":25: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("node 21"));
  }
  SECTION("partitioned mesh") {
    const auto path = write_temp(
        "partitioned.msh", replaced(kOneTriangleMsh, "$Nodes\n", "$PartitionedEntities\n$Nodes\n"));
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ":12: mesh.file: "));
    CHECK_THAT(message, Catch::Contains("partitioned"));
  }
  SECTION("missing file") {
    const auto path = write_temp("placeholder", "") + ".missing";
    const auto message = gmsh_error(path);
    CHECK(starts_with(message, path + ": mesh.file: "));
    CHECK_THAT(message, Catch::Contains("cannot open"));
  }
  SECTION("empty file") {
    const auto path = write_temp("empty.msh", "");
    CHECK(starts_with(gmsh_error(path), path + ": mesh.file: "));
  }
}

TEST_CASE("gmsh: a stream reads as its file, and errors name the name given", "[gmsh]") {
  const MeshInput from_file = read_gmsh(data_dir + "two_materials.msh");
  std::istringstream text(ydry_test::read_text(data_dir + "two_materials.msh"));
  const MeshInput from_stream = ydry::read_gmsh(text, "two_materials.msh");
  CHECK(from_stream.vx == from_file.vx);
  CHECK(from_stream.vy == from_file.vy);
  CHECK(from_stream.tri == from_file.tri);
  CHECK(from_stream.tri_material == from_file.tri_material);
  CHECK(from_stream.boundaries == from_file.boundaries);
  std::istringstream version("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  CHECK_THROWS_WITH(ydry::read_gmsh(version, "in memory"), Catch::StartsWith("in memory:2: mesh.file: "));
}

TEST_CASE("gmsh: a count larger than the file is an error where its items end, not an allocation", "[gmsh]") {
  // No count sizes a buffer: each item must be a line (or field) of the file, so the reader
  // stops at the first line that is not one (bad_alloc or a hang otherwise).
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"$Nodes\n1 3 10 30\n2 1 0 3\n", "$Nodes\n1 3 10 30\n2 1 0 4000000000000000000\n"},
           {"$Nodes\n1 3 10 30\n", "$Nodes\n4000000000000000000 3 10 30\n"},
           {"$Elements\n1 1 1 1\n2 1 2 1\n", "$Elements\n1 1 1 1\n2 1 2 4000000000000000000\n"},
           {"$PhysicalNames\n1\n", "$PhysicalNames\n4000000000000000000\n"}}) {
    INFO(to);
    std::istringstream in(replaced(kOneTriangleMsh, from, to));
    CHECK_THROWS_WITH(ydry::read_gmsh(in, "huge.msh"),
                      Catch::StartsWith("huge.msh:") && Catch::Contains("expected"));  // or "unexpected"
  }
}
