#include "ymoist/shrinkage.h"

#include <algorithm>

#include "ycore/state/blocked_sum.h"

namespace ydry {

void update_shrinkage_strain(const Nodes& nodes, const MoistureNodes& moisture,
                             const std::vector<MaterialModel>& materials, Triangles& triangles) {
  const std::int64_t nt = std::int64_t(triangles.size());
#pragma omp parallel for schedule(static) if (std::size_t(nt) > parallel_minimum)
  for (std::int64_t t = 0; t < nt; ++t) {
    const MaterialModel& m = materials[triangles.material[t]];
    const index_t i = corner_node(index_t(t), 0);
    if (!m.mechanical || nodes.mnode[i] == kNoIndex) continue;
    double w = 0.0;  // element moisture: the mean of its corners'
    for (int a = 0; a < 3; ++a) w += moisture.w[nodes.mnode[i + a]] / 3.0;
    // Eq. 18: proportional to the moisture change, no further below the shrinkage limit.
    triangles.shrinkage_strain[t] = m.shrinkage_coefficient * (std::max(w, m.shrinkage_limit) - m.stress_free_moisture);
  }
}

}  // namespace ydry
