// reactions.csv (doc/outputs.md "Files of a run"): per row time and [[mechanics.boundary]],
// the force the support exerts, the mean displacement of its nodes and the work done through it.
#pragma once

#include <string>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

extern const char* const kReactionsCsvHeader;

// The rows of reactions.csv at time_s, one per boundary.
std::string reactions_csv_rows(double time_s, const Nodes& nodes, const std::vector<MechanicsBoundary>& boundaries);

}  // namespace ydry
