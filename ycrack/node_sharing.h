// Node sharing for moisture: which coincident corners form one moisture node.
#pragma once

#include "ycore/state/state.h"

namespace ydry {

// Fills nodes.tie_group: for every corner, the lowest corner connected to it through intact
// joints, a bonded interface's included (coincident corners only: a joint ties corner pairs
// 4j+0 - 4j+3 and 4j+1 - 4j+2).
void tie_corners(const Joints& joints, Nodes& nodes);

// Groups the corners of every material with moisture into moisture nodes: the connected
// components of coincident corners under intact joints inside one material (an interface's
// joints tie none: materials exchange no water), so a broken joint separates the two
// sides of a crack while a crack tip stays one node (Eq. 14; doc/physics.md "Cracks and
// moisture"). Writes nodes.mnode (kNoIndex for corners with has_moisture[triangle] == 0) and
// the CSR corner lists of `moisture`; calls tie_corners first; numbers nodes in the order of
// their lowest corner, so the result does not depend on anything but the mesh and the broken
// flags. Returns the node count.
index_t group_moisture_nodes(const Joints& joints, const Triangles& triangles,
                             const std::vector<std::uint8_t>& has_moisture, Nodes& nodes, MoistureNodes& moisture);

}  // namespace ydry
