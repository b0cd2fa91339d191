// The coupling driver: the paper's staggered loop (section 3.3) and the run's outputs.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ycore/output/checkpoint_file.h"
#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

struct RunOptions {
  std::string deck_path;
  std::string outdir;                  // empty: runs/NAME
  std::vector<std::string> overrides;  // --set key.path=value
  int threads = 0;                     // 0: OpenMP's default
  bool force = false;
  bool quiet = false;
  double progress_every_s = 10.0;      // plain progress lines when stderr is not a terminal
  std::string restart_path;            // a checkpoint to continue; deck_path may then be empty
  double checkpoint_every_s = 0;       // wall seconds between checkpoints; 0: none
  std::uint64_t checkpoint_every_steps = 0;  // coupling steps between checkpoints; 0: none
};

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
// (ycore/output/checkpoint.h). Throws InputError for a checkpoint that does not fit the deck and mesh.
State state_from_checkpoint(const Deck& deck, const Checkpoint& checkpoint);

// `ydry check DECK`: reads the deck (with its --set overrides) and the mesh, checks them as
// a run would, prints the resolved deck (every value, defaults included) on stdout and a
// line with the mesh's sizes and steps on stderr, without running. Returns 0; bad input
// throws InputError like run(). `ydry check --restart CHECKPOINT` reads the checkpoint and
// restores its state as a restart would, and prints its deck.toml and a line on its time.
int check(const RunOptions& options);

// The longest step of the staggered loop: the moisture stability limit, solver.max_coupling_step
// and the output interval, whichever is smallest.
double coupling_step_limit(const State& state, const Deck& deck);

// One step of the paper's loop (section 3.3): (1) moisture update, (2) shrinkage eigenstrain,
// (3) mechanical relaxation to equilibrium, (4) joint breakage and the moisture nodes split
// across the new cracks. Steps 2-4 run when `relax_now`, or once solver.mechanics_interval of
// moisture time has gathered since the last relaxation (the solid then catches up with all of
// it at once). Returns true when the moisture topology changed.
bool coupling_step(State& state, const Deck& deck, double dt, bool relax_now);

// Advances the state to until_s in coupling steps no longer than max_step_s, landing
// exactly on until_s. Returns the step limit to go on with: lower than max_step_s when a
// split of the moisture nodes made the moisture stability limit smaller. Stops early, after a
// whole coupling step, when `pause` returns true; called again with the same until_s and the
// limit it returned, it goes on as if it had not stopped.
double advance_to(State& state, const Deck& deck, double until_s, double max_step_s,
                  const std::function<bool()>& pause = nullptr);

// Runs a deck end to end with outputs, or continues the run of options.restart_path; writes
// checkpoints on request, at the end, and on SIGINT or SIGTERM (then returns 130). Returns
// the process exit code.
int run(const RunOptions& options);

}  // namespace ydry
