// Pre-existing cracks and notches ([[cracks]] in the deck, paper section 4.2).
#pragma once

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// Marks broken every joint whose edge lies on one of the deck's crack segments. A segment
// must follow mesh edges that carry joints over its whole length; otherwise InputError.
void break_joints_along_cracks(State& state, const Deck& deck);

}  // namespace ydry
