// Setting up the solid from the deck (mechanics_setup.cpp; doc/deck.md "[materials.NAME]",
// "[[mechanics.boundary]]" and "[solver]").
#pragma once

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// Material constants, masses, reference geometry, joint data and boundary constraints from
// the deck, the contact (init_contact), the ownership table, and state.mechanics.step_s from
// the stability bound. Throws InputError for a key the solid needs and the deck lacks, or for
// contradictory boundary conditions.
//
// A phase, not a kernel: it writes every part of the solid (nodes, triangles, joints,
// mechanics, contact, mechanics_boundaries, ownership, materials) from the mesh that
// build_state made, and reads the material names and the named boundary edges.
void init_mechanics(State& state, const Deck& deck);

}  // namespace ydry
