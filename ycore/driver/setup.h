// The state a run starts from: a deck's set-up, or a checkpoint's state on it.
#pragma once

#include "ycore/input/deck.h"
#include "ycore/output/checkpoint_file.h"
#include "ycore/state/state.h"

namespace ydry {

// Everything a run needs before its first step: mesh, exploded state, pre-existing cracks,
// moisture nodes and model, the solid and its initial equilibrium (gravity, and shrinkage
// when the moisture starts away from the stress-free value). Throws InputError for anything
// the deck asks that cannot be done.
State setup_state(const Deck& deck);

// setup_state without the initial equilibrium: everything that reads and checks the deck
// and the mesh, and sizes the steps.
State prepare_state(const Deck& deck);

// The state a checkpoint holds, on the set-up of `deck` (the checkpoint's): prepare_state, the
// broken joints, the moisture nodes and contact surfaces they make, and the rest of the state
// (ycore/output/checkpoint.h). Throws InputError for a checkpoint that does not fit the deck
// and mesh.
State state_from_checkpoint(const Deck& deck, const Checkpoint& checkpoint);

}  // namespace ydry
