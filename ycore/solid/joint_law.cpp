#include "ycore/solid/joint_law.h"

#include <algorithm>

namespace ydry {

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
  const JointFrame f = joint_frame(n.x[jn[0]], n.x[jn[1]], n.x[jn[2]], n.x[jn[3]], n.y[jn[0]], n.y[jn[1]],
                                   n.y[jn[2]], n.y[jn[3]]);
  JointKinematics k;
  k.length = f.length;
  k.nx = f.nx;
  k.ny = f.ny;
  k.opening[0] = f.d0x * f.nx + f.d0y * f.ny;
  k.slip[0] = f.d0x * f.tx + f.d0y * f.ty;
  k.opening[1] = f.d1x * f.nx + f.d1y * f.ny;
  k.slip[1] = f.d1x * f.tx + f.d1y * f.ty;
  return k;
}

}  // namespace ydry
