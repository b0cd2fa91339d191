#include "ycore/output/reactions_csv.h"

#include <iomanip>
#include <sstream>

namespace ydry {

const char* const kReactionsCsvHeader = "time_s,boundary,reaction_x_N,reaction_y_N,mean_ux_m,mean_uy_m,work_J";

std::string reactions_csv_rows(double time_s, const Nodes& n, const std::vector<MechanicsBoundary>& boundaries) {
  std::ostringstream csv;
  for (const MechanicsBoundary& b : boundaries) {
    double ux = 0, uy = 0;
    for (const index_t i : b.nodes) {
      ux += (n.x[i] - n.x0[i]) / b.nodes.size();
      uy += (n.y[i] - n.y0[i]) / b.nodes.size();
    }
    csv << std::setprecision(17) << time_s << ',' << b.name << ',' << b.reaction_x << ',' << b.reaction_y << ','
        << ux << ',' << uy << ',' << b.work_J << '\n';
  }
  return csv.str();
}

}  // namespace ydry
