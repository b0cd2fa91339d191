#include "ycore/joint_law.h"

#include <algorithm>

namespace ydry {

double softening_curve(double damage) {
  constexpr double a = 0.63, b = 1.8, c = 6.0;
  if (damage <= 0.0) return 1.0;  // the intact joint: the common case, without exp
  const double d = std::min(damage, 1.0), r = 1.0 - d, r2 = r * r;
  return (1.0 - (a + b - 1.0) / (a + b) * std::exp(d * (a + c * b) / ((a + b) * (1.0 - a - b)))) *
         (a * r + b * r2 * r2 * r2);  // (1 - D)^c with c = 6
}

double softening_curve_area() {
  static const double area = [] {
    constexpr int n = 20000;  // composite Simpson; z is smooth, so this is exact to 1e-12
    double sum = softening_curve(0.0) + softening_curve(1.0);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * softening_curve(double(i) / n);
    return sum / (3.0 * n);
  }();
  return area;
}

JointKinematics joint_kinematics(const Nodes& n, const index_t* jn) {
  JointKinematics k;
  const double ex = 0.5 * (n.x[jn[1]] + n.x[jn[2]] - n.x[jn[0]] - n.x[jn[3]]);
  const double ey = 0.5 * (n.y[jn[1]] + n.y[jn[2]] - n.y[jn[0]] - n.y[jn[3]]);
  k.length = std::sqrt(ex * ex + ey * ey);
  const double tx = ex / k.length, ty = ey / k.length;
  k.nx = -ty;
  k.ny = tx;
  for (int end = 0; end < 2; ++end) {
    const index_t a = jn[end], b = jn[3 - end];
    const double dx = n.x[a] - n.x[b], dy = n.y[a] - n.y[b];
    k.opening[end] = dx * k.nx + dy * k.ny;
    k.slip[end] = dx * tx + dy * ty;
  }
  return k;
}

}  // namespace ydry
