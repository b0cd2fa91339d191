// The mesh as it comes from a generator or a file, before it is exploded into the FDEM state:
// shared vertices, triangles tagged with a material, and named boundary edges.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ycore/input/mesh_size.h"

namespace ydry {

// A mesh edge's name: its two vertex ids, the smaller in the high word, so both directions
// of the edge give the same key.
inline std::uint64_t edge_key(index_t a, index_t b) {
  return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

struct MeshInput {
  std::vector<double> vx, vy;               // vertex coordinates, m            [vertices]
  std::vector<index_t> tri;                 // 3 vertex ids per triangle, CCW   [3 * triangles]
  std::vector<std::string> tri_material;    // material name per triangle       [triangles]
  // Named boundaries (rectangle sides, Gmsh physical curves): vertex pairs of mesh edges.
  std::map<std::string, std::vector<index_t>> boundaries;  // name -> 2 vertex ids per edge

  std::size_t vertex_count() const { return vx.size(); }
  std::size_t triangle_count() const { return tri_material.size(); }
};

// Makes every triangle counter-clockwise (swaps two corners of clockwise ones) and rejects
// degenerate triangles and areas too large for a double; run on every MeshInput before use.
void orient_counter_clockwise(MeshInput& mesh);

}  // namespace ydry
