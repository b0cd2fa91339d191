// The built-in mesh: a structured rectangle (mesh.generator = "rectangle").
#pragma once

#include <string>

#include "ycore/state/mesh_input.h"

namespace ydry {

// Built-in structured rectangle [0, lx] x [0, ly] of square-ish cells of about element_size;
// pattern "right" (diagonal /), "left" (diagonal \) or "cross" (4 triangles per cell around
// a centre vertex). Sides are named "left", "right", "bottom", "top". At most kMaxTriangles
// (read_deck checks it).
MeshInput generate_rectangle(double lx, double ly, double element_size,
                             const std::string& pattern, const std::string& material);

}  // namespace ydry
