// cracks.csv (doc/outputs.md "Files of a run"): one row per crack per row time.
#pragma once

#include <string>
#include <vector>

#include "ycrack/crack_statistics.h"

namespace ydry {

extern const char* const kCracksCsvHeader;

// The rows of cracks at time_s (crack_id: the index in `cracks`, which find_cracks orders by x).
std::string cracks_csv_rows(double time_s, const std::vector<Crack>& cracks);

}  // namespace ydry
