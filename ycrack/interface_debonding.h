// How far each bonded interface has come apart, for series.csv (doc/outputs.md "Files of a
// run", debonded_length_NAME).
#pragma once

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Per bonded interface (State::interface_names), the initial length of its broken joints, m:
// the length of the interface that has debonded.
std::vector<double> interface_debonded_lengths(const State& state);

}  // namespace ydry
