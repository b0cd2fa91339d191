// What a run's rows hold: the row of series.csv and summary.json (doc/outputs.md "Files of a run").
#pragma once

#include <vector>

#include "ycore/input/deck.h"
#include "ycore/output/json_object.h"
#include "ycore/output/output_files.h"
#include "ycore/state/state.h"
#include "ycrack/crack_statistics.h"

namespace ydry {

// The corners of the top-right vertex of the breakable material (the largest x, then the
// largest y there): right_end_displacement_m is their mean x-displacement.
std::vector<index_t> right_end_corners(const State& state);

// A row of series.csv, in the order of series_columns(state.interface_names); NaN for what
// the run does not compute.
std::vector<double> series_row(const State& state, const Deck& deck, const std::vector<index_t>& right_end,
                               const std::vector<Crack>& cracks);

// summary.json: the last row of series.csv and the run's facts.
JsonObject summary_json(const Deck& deck, const State& state, const Series& series, int closed_cracks, double wall_s,
                        bool completed);

}  // namespace ydry
