#include "ycrack/cracks_csv.h"

#include "ycore/output/output_files.h"

namespace ydry {

void append_cracks_csv(CracksCsv& csv, double time_s, const std::vector<Crack>& cracks) {
  for (std::size_t k = 0; k < cracks.size(); ++k) {
    const Crack& c = cracks[k];
    csv.rows += format_double(time_s) + "," + std::to_string(k) + "," + format_double(c.x_m) + "," +
                format_double(c.width_m) + "," + format_double(c.length_m) + "," +
                (c.penetrating ? "1" : "0") + "," + (c.on_top_surface ? "1" : "0") + "\n";
  }
  write_cracks_csv(csv);
}

void write_cracks_csv(const CracksCsv& csv) {
  write_file_atomically(csv.path, "time_s,crack_id,x_m,width_m,length_m,penetrating,surface\n" + csv.rows);
}

}  // namespace ydry
