// From the deck's mesh to the exploded FDEM state.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ycore/input/deck.h"
#include "ycore/state/mesh_input.h"
#include "ycore/state/state.h"

namespace ydry {

// The generated or read mesh, oriented, with every material checked against the deck.
MeshInput load_mesh(const Deck& deck);

// Explodes the mesh: 3 nodes per triangle, joints on every interior edge inside a material
// and on every edge of a bonded interface (deck.interfaces; none between two other materials:
// those are separate bodies), each with its properties' index (Joints::law), named
// boundary edges as node pairs. Moisture nodes are left to ycrack and ymoist.
State build_state(const MeshInput& mesh, const Deck& deck);

// The node pairs of a named boundary (State::boundary_edges); InputError at `where` if the
// mesh has no such name.
const std::vector<index_t>& boundary_nodes(const std::map<std::string, std::vector<index_t>>& boundary_edges,
                                           const std::string& name, const std::string& where);

}  // namespace ydry
