// libFuzzer target: the Gmsh 4.1 reader (read_gmsh from a stream) and the orientation pass
// every mesh goes through before use. An InputError is a correct answer to any input; a
// crash, a sanitizer report, any other exception, or a mesh that breaks MeshInput's
// invariants (a vertex id out of range, a triangle without its material, half an edge, a
// triangle not counter-clockwise with a finite area after orientation) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "ycore/input/input_error.h"
#include "ycore/state/mesh_gmsh.h"

namespace {

void require(bool fact, const char* what) {
  if (fact) return;
  std::fprintf(stderr, "read_gmsh returned a mesh where %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  ydry::MeshInput mesh;
  try {
    mesh = ydry::read_gmsh(in, "fuzzed.msh");
    ydry::orient_counter_clockwise(mesh);
  } catch (const ydry::InputError&) {
    return 0;
  }
  require(mesh.vy.size() == mesh.vertex_count(), "x and y differ in length");
  require(mesh.tri.size() == 3 * mesh.triangle_count(), "a triangle has no material");
  for (const auto v : mesh.tri) require(v < mesh.vertex_count(), "a triangle has a vertex out of range");
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto a = mesh.tri[3 * t], b = mesh.tri[3 * t + 1], c = mesh.tri[3 * t + 2];
    const double twice_area = (mesh.vx[b] - mesh.vx[a]) * (mesh.vy[c] - mesh.vy[a]) -
                              (mesh.vx[c] - mesh.vx[a]) * (mesh.vy[b] - mesh.vy[a]);
    require(twice_area > 0 && std::isfinite(twice_area), "a triangle is not counter-clockwise with a finite area");
  }
  for (const auto& [name, edges] : mesh.boundaries) {
    require(edges.size() % 2 == 0, "a boundary holds half an edge");
    for (const auto v : edges) require(v < mesh.vertex_count(), "a boundary has a vertex out of range");
  }
  return 0;
}
