// The lines log.txt opens and closes a run with.
#pragma once

#include <string>

#include "ycore/input/deck.h"
#include "ycore/output/log_file.h"
#include "ycore/state/state.h"

namespace ydry {

// "ydry VERSION (COMMIT)": the code a log, summary or checkpoint was written by.
std::string ydry_version_text();

// A new run's first lines: the code, the deck, the mesh, unused materials, the strength
// heterogeneity drawn, and the steps and solver controls.
void log_set_up(Log& log, const State& state, const Deck& deck, double max_step_s, const std::string& outdir);

// A restart's first line, and a warning when the checkpoint was written by another version.
void log_restart(Log& log, const State& state, const std::string& checkpoint_path,
                 const std::string& checkpoint_version, const std::string& outdir);

// A completed run's last lines: the time, steps, water and energy balances, the wall time by
// stage, and the outputs.
void log_end(Log& log, const State& state, const Deck& deck, double wall_s, const std::string& outputs);

}  // namespace ydry
