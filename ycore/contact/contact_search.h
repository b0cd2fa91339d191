// The contact broad phase (ycore/contact/contact_search.cpp), used by the force kernel.
#pragma once

#include "ycore/state/state.h"

namespace ydry {

// Rebuilds the candidate pairs: every (surface corner, surface edge) that may touch and lie
// within two buffers; the pairs that continue keep their friction slip.
void build_contact_pairs(State& state);

// The per-corner index (node_pairs) and the gather lists of the candidate pairs
// (pair_node, pair_edge: sorted by corner, then edge).
void index_contact_pairs(State& state);

// Whether a surface corner has moved more than the buffer since the last build (or there
// has been none since the surfaces changed).
bool contact_pairs_stale(const State& state);

}  // namespace ydry
