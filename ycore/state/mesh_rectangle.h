// The built-in mesh: a structured rectangle (mesh.generator = "rectangle").
#pragma once

#include <array>
#include <string>

#include "ycore/state/mesh_input.h"

namespace ydry {

// Built-in structured rectangle [0, lx] x [0, ly] of square-ish cells of about element_size;
// pattern "right" (diagonal /), "left" (diagonal \) or "cross" (4 triangles per cell around
// a centre vertex). Sides are named "left", "right", "bottom", "top". At most kMaxTriangles
// (read_deck checks it).
MeshInput generate_rectangle(double lx, double ly, double element_size,
                             const std::string& pattern, const std::string& material);

// generate_rectangle's cells along x and y, whole numbers as close to element_size as fit; as
// doubles, so that a deck can be checked against the 32-bit indices before they are made.
std::array<double, 2> rectangle_cells(double lx, double ly, double element_size);

}  // namespace ydry
