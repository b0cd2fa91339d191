// The size of a mesh in the numbers a deck gives: the index width that caps it and the cells
// of the generated rectangle. Shared by the deck reader, which checks a mesh before one is
// made, and the mesh generator and readers (ycore/state/mesh_input.h, mesh_rectangle.h).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ydry {

using index_t = std::uint32_t;  // all mesh indices are 32-bit

// The most triangles a mesh may have: the exploded mesh numbers 3 corners per triangle in
// 32 bits, the largest index meaning none (kNoIndex).
constexpr double kMaxTriangles = (std::numeric_limits<index_t>::max() - 1) / 3;

// generate_rectangle's cells along x and y, whole numbers as close to element_size as fit; as
// doubles, so that a deck can be checked against the 32-bit indices before they are made.
inline std::array<double, 2> rectangle_cells(double lx, double ly, double element_size) {
  return {std::max(1.0, std::round(lx / element_size)), std::max(1.0, std::round(ly / element_size))};
}

}  // namespace ydry
