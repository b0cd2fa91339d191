#include "ycore/solid/joint_work.h"

#include "ycore/solid/joint_forces.h"

namespace ydry {

void book_joint_work(const Nodes& n, const Mechanics& mech, const std::vector<MaterialModel>& materials,
                     const std::vector<double>& x_from, const std::vector<double>& y_from, Joints& jt) {
  static constexpr double kPoint[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                       0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                       0.8983332387068134, 0.9801449282487681};
  static constexpr double kWeight[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                        0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                        0.1111905172266872, 0.0506142681451881};
#pragma omp parallel for schedule(static) if (jt.size() > parallel_minimum)
  for (std::size_t j = 0; j < jt.size(); ++j) {
    if (jt.broken[j] || !materials[jt.law[j]].mechanical) continue;
    const index_t* node = &jt.node[4 * j];
    double dx[4], dy[4], x[4], y[4], f[8], work = 0.0;
    for (int k = 0; k < 4; ++k) dx[k] = n.x[node[k]] - x_from[node[k]], dy[k] = n.y[node[k]] - y_from[node[k]];
    for (int q = 0; q < 8; ++q) {
      for (int k = 0; k < 4; ++k) x[k] = x_from[node[k]] + kPoint[q] * dx[k], y[k] = y_from[node[k]] + kPoint[q] * dy[k];
      joint_nodal_forces_at(jt, mech, materials, j, x, y, f);
      double power = 0.0;
      for (int k = 0; k < 4; ++k) power += f[2 * k] * dx[k] + f[2 * k + 1] * dy[k];
      work -= kWeight[q] * power;
    }
    jt.work[j] += work;
  }
}

void book_joint_step_work(const Nodes& n, const std::vector<MaterialModel>& materials,
                          const std::vector<double>& force_before, double dt, Joints& jt) {
  if (dt == 0.0) return;
#pragma omp parallel for schedule(static) if (jt.size() > parallel_minimum)
  for (std::size_t j = 0; j < jt.size(); ++j) {
    if (jt.broken[j] || !materials[jt.law[j]].mechanical) continue;
    const index_t* node = &jt.node[4 * j];
    const double* before = &force_before[8 * j];
    const double* after = &jt.force[8 * j];
    double power = 0.0;
    for (int k = 0; k < 4; ++k)
      power += 0.5 * ((before[2 * k] + after[2 * k]) * n.vx[node[k]] +
                      (before[2 * k + 1] + after[2 * k + 1]) * n.vy[node[k]]);
    jt.work[j] -= power * dt;
  }
}

}  // namespace ydry
