// Shrinkage eigenstrain from moisture (paper Eqs. 18-19; doc/physics.md "Shrinkage").
#pragma once

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Each triangle's shrinkage strain eps_sh = alpha (max(w, w_s) - w_i) from the mean moisture
// of its corners (Eq. 18), into triangles.shrinkage_strain, for the triangles of a material
// with mechanics and moisture; the solid turns it into the stress 3 K* eps_sh (Eq. 19).
// Reads nodes.mnode, moisture.w and triangles.material.
void update_shrinkage_strain(const Nodes& nodes, const MoistureNodes& moisture,
                             const std::vector<MaterialModel>& materials, Triangles& triangles);

}  // namespace ydry
