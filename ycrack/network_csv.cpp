#include "ycrack/network_csv.h"

#include <numeric>

#include "ycore/output/output_files.h"

namespace ydry {

const char* const kNetworkCsvHeader =
    "time_s,cells,mean_cell_area_m2,crack_intensity,crack_length_m,crack_density_per_m,junctions_T,junctions_Y,"
    "junctions_other";
const char* const kCellsCsvHeader = "time_s,cell,area_m2,perimeter_m";
const char* const kJunctionsCsvHeader = "time_s,x0_m,y0_m,kind,branches,angles_deg";

std::string network_csv_row(double time_s, const NetworkCensus& c) {
  const std::size_t cells = c.cell_area_m2.size();
  const double total = std::accumulate(c.cell_area_m2.begin(), c.cell_area_m2.end(), 0.0);
  return format_double(time_s) + "," + std::to_string(cells) + "," + format_double(cells ? total / double(cells) : 0.0) +
         "," + format_double(c.crack_intensity()) + "," + format_double(c.crack_length_m) + "," +
         format_double(c.crack_density_per_m()) + "," + std::to_string(c.count(JunctionKind::T)) + "," +
         std::to_string(c.count(JunctionKind::Y)) + "," + std::to_string(c.count(JunctionKind::other)) + "\n";
}

std::string cells_csv_rows(double time_s, const NetworkCensus& c) {
  std::string rows;
  for (std::size_t k = 0; k < c.cell_area_m2.size(); ++k)
    rows += format_double(time_s) + "," + std::to_string(k) + "," + format_double(c.cell_area_m2[k]) + "," +
            format_double(c.cell_perimeter_m[k]) + "\n";
  return rows;
}

std::string junctions_csv_rows(double time_s, const NetworkCensus& c) {
  static const char* const kKind[] = {"T", "Y", "other"};
  std::string rows;
  for (const Junction& j : c.junctions) {
    std::string angles;
    for (const double a : j.angles) angles += (angles.empty() ? "" : " ") + format_double(a);
    rows += format_double(time_s) + "," + format_double(j.x0) + "," + format_double(j.y0) + "," +
            kKind[std::size_t(j.kind)] + "," + std::to_string(j.angles.size()) + "," + angles + "\n";
  }
  return rows;
}

}  // namespace ydry
