#include "ycrack/cracks_csv.h"

#include "ycore/output/output_files.h"

namespace ydry {

const char* const kCracksCsvHeader = "time_s,crack_id,x_m,width_m,length_m,penetrating,surface";

std::string cracks_csv_rows(double time_s, const std::vector<Crack>& cracks) {
  std::string rows;
  for (std::size_t k = 0; k < cracks.size(); ++k) {
    const Crack& c = cracks[k];
    rows += format_double(time_s) + "," + std::to_string(k) + "," + format_double(c.x_m) + "," +
            format_double(c.width_m) + "," + format_double(c.length_m) + "," + (c.penetrating ? "1" : "0") + "," +
            (c.on_top_surface ? "1" : "0") + "\n";
  }
  return rows;
}

}  // namespace ydry
