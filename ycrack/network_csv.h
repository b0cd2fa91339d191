// The crack network's tables of a plan-view run (doc/outputs.md "network.csv", "cells.csv",
// "junctions.csv"), made from its census (network_census.h).
#pragma once

#include <string>

#include "ycrack/network_census.h"

namespace ydry {

extern const char* const kNetworkCsvHeader;
extern const char* const kCellsCsvHeader;
extern const char* const kJunctionsCsvHeader;

// network.csv's row at time_s: the number of cells, their mean area, the crack intensity
// factor, the crack length and its density, and the junctions of each kind.
std::string network_csv_row(double time_s, const NetworkCensus& census);

// cells.csv's rows at time_s, one per cell: its number (the frames' `cell`), area and perimeter.
std::string cells_csv_rows(double time_s, const NetworkCensus& census);

// junctions.csv's rows at time_s, one per interior junction: where, its kind, its branch count
// and the angles between neighbouring branches (degrees, space-separated, counter-clockwise
// from the branch nearest +x).
std::string junctions_csv_rows(double time_s, const NetworkCensus& census);

}  // namespace ydry
