// Pre-existing cracks and notches ([[cracks]] in the deck, paper section 4.2).
#pragma once

#include <vector>

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// Marks broken (joints.broken) every joint whose edge lies on one of the crack segments (the
// deck's [[cracks]]), by the nodes' initial positions. A segment must follow mesh edges that
// carry joints over its whole length; otherwise InputError.
void break_joints_along_cracks(const Nodes& nodes, const std::vector<CrackSegmentDeck>& cracks, Joints& joints);

}  // namespace ydry
