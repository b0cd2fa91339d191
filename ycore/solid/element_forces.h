// The element kernel: the forces and stresses of the constant-strain triangles with the
// co-rotational law (element_forces.cpp; doc/physics.md "Elements").
#pragma once

#include <vector>

#include "ycore/solid/node_integration.h"
#include "ycore/state/state.h"

namespace ydry {

// Element internal forces and gravity: overwrites nodes.fx, fy of every node (each triangle
// owns its three nodes). With move_first, each triangle's nodes are first moved by that
// pseudo-step (integrate_node_range), in the same pass, and the return is the moved
// components' sum of v_new . f with the forces that moved them (0 without), the same on any
// number of threads. Reads the mechanics' thickness and gravity.
double element_forces(const Triangles& triangles, const Mechanics& mechanics, const Ownership& ownership,
                      const std::vector<MaterialModel>& materials, Nodes& nodes,
                      const VelocityUpdate* move_first = nullptr);

// The element stress (triangles.sxx, syy, sxy) at the current positions. The forces do not
// need it: relaxations make it once, at the equilibrium reached.
void element_stresses(const Nodes& nodes, const Ownership& ownership, const std::vector<MaterialModel>& materials,
                      Triangles& triangles);

}  // namespace ydry
