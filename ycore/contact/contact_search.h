// The contact broad phase (contact_search.cpp), used by the force kernel (contact_forces.h).
//
// A cell list of surface corners, rebuilt when one of them has moved more than a buffer since
// the last build; it keeps the (corner, edge) pairs closer than two buffers, so no contact can
// start between two builds unseen (doc/physics.md "Contact and friction").
#pragma once

#include "ycore/state/state.h"

namespace ydry {

// Rebuilds the candidate pairs: every (surface corner, surface edge) that may touch and lie
// within two buffers; the pairs that continue keep their friction slip. Reads the nodes'
// positions, tie groups and constraints; writes `contact` (index_contact_pairs included).
void build_contact_pairs(const Nodes& nodes, const Ownership& ownership, Contact& contact);

// The per-corner index (node_pairs, corner_owner_begin) and the gather lists of the candidate
// pairs (pair_node, pair_edge: sorted by corner, then edge), for nodes.size() nodes and the
// ownership table's node ranges.
void index_contact_pairs(const Nodes& nodes, const Ownership& ownership, Contact& contact);

// Whether a surface corner has moved more than the buffer since the last build (or there
// has been none since the surfaces changed).
bool contact_pairs_stale(const Nodes& nodes, const Contact& contact);

}  // namespace ydry
