// cracks.csv (DESIGN section 5): one row per crack per output time.
#pragma once

#include <string>
#include <vector>

#include "ycrack/crack_statistics.h"

namespace ydry {

struct CracksCsv {
  std::string path;
  std::string rows;  // every row so far, as written
};

// Appends a row per crack at time_s (crack_id: the index in `cracks`, which find_cracks
// orders by x) and rewrites the whole file atomically, header first.
void append_cracks_csv(CracksCsv& csv, double time_s, const std::vector<Crack>& cracks);

// Writes the file with the rows so far (a restart's).
void write_cracks_csv(const CracksCsv& csv);

}  // namespace ydry
