// The paper's staggered loop (section 3.3; doc/architecture.md "A coupling step").
//
// The functions that take a State& are phases, not kernels: they run the moisture, solid and
// cracking kernels in turn, and so write the moisture (w, ledger, and on a split the moisture
// nodes), the solid (nodes, stresses, eigenstrains, joints, contact, supports, mechanics), the
// topology, time_s and coupling_steps (advance_to), and the stage clock.
#pragma once

#include <functional>

#include "ycore/input/deck.h"
#include "ycore/solid/relaxation.h"
#include "ycore/state/state.h"

namespace ydry {

// The longest step of the loop: the moisture stability limit, solver.max_coupling_step and
// the output interval, whichever is smallest.
double coupling_step_limit(const State& state, const Deck& deck);

// One step of the loop: (1) moisture update, (2) shrinkage eigenstrain, (3) the solid brought
// to equilibrium, (4) joint breakage and the moisture nodes split across the new cracks.
// Steps 2-4 run when `relax_now`, or once solver.mechanics_interval of moisture time has
// gathered since the last relaxation (the solid then catches up with all of it at once).
// Returns true when the moisture topology changed. `report` hears from a relaxation that runs
// long (relaxation.h).
bool coupling_step(State& state, const Deck& deck, double dt, bool relax_now, const RelaxationReport& report = nullptr);

// Steps 3 and 4 alone, over `dt` of moisture time (0: the initial equilibrium). Returns
// whether a joint broke.
bool equilibrate_and_break(State& state, const Deck& deck, double dt, const RelaxationReport& report = nullptr);

// Advances the state to until_s in coupling steps no longer than max_step_s, landing
// exactly on until_s. Returns the step limit to go on with: lower than max_step_s when a
// split of the moisture nodes made the moisture stability limit smaller. Stops early, after a
// whole coupling step, when `pause` returns true; called again with the same until_s and the
// limit it returned, it goes on as if it had not stopped. `report` hears from the relaxations
// that run long.
double advance_to(State& state, const Deck& deck, double until_s, double max_step_s,
                  const std::function<bool()>& pause = nullptr, const RelaxationReport& report = nullptr);

// Per triangle, 1 where its material has moisture (a moisture_conductivity).
std::vector<std::uint8_t> triangles_with_moisture(const State& state, const Deck& deck);

// Step 4 after joints broke: the corners are tied anew, the moisture nodes split across the
// broken joints (water is conserved), and their faces become contact surfaces.
void split_across_broken_joints(State& state, const Deck& deck);

}  // namespace ydry
