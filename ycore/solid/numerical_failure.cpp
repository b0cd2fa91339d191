#include "ycore/solid/numerical_failure.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace ydry {

std::string describe_node(const State& s, index_t i) {
  const index_t t = triangle_of(i);
  std::ostringstream m;
  m << "node " << i << " of triangle " << t << " (material " << s.material_names[s.triangles.material[t]]
    << ", initially at x = " << s.nodes.x0[i] << " m, y = " << s.nodes.y0[i] << " m)";
  return m.str();
}

void report_non_finite_solid(const State& s, const std::string& what) {
  const Nodes& n = s.nodes;
  std::ostringstream m;
  m << "numerical failure at t = " << s.time_s << " s, " << what << " (" << s.mechanics.steps
    << " mechanical steps before this relaxation): ";
  // A position gone wrong spreads to the forces of its neighbours: name it first.
  const auto first = [&](const std::vector<double>& a, const std::vector<double>& b) {
    index_t i = 0;
    while (i < n.size() && std::isfinite(a[i]) && std::isfinite(b[i])) ++i;
    return i;
  };
  const index_t moved = first(n.x, n.y), pushed = first(n.fx, n.fy);
  const index_t i = moved < n.size() ? moved : pushed;
  if (i < n.size()) {
    m << describe_node(s, i) << " has a non-finite " << (moved < n.size() ? "position" : "force");
  } else {
    m << "the out-of-balance force is not finite";
  }
  m << ": " << kNumericalFailureCauses;
  throw NumericalFailure(m.str());
}

}  // namespace ydry
