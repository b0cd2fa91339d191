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

namespace {

// The pre-peak shape of Fig. 2a, b: 2r - r^2 up to the peak, 1 beyond.
double hardening(double r) { return r < 1.0 ? r * (2.0 - r) : 1.0; }

// Softening length from peak to zero stress that makes the total work per unit area equal
// the fracture energy: (2/3) f delta_p before the peak plus area(z) f delta_t after it.
// A fracture energy smaller than the pre-peak work (possible for the mode II strength under
// high compression) keeps a minimal softening length instead.
double softening_length(double fracture_energy, double strength, double peak) {
  const double t = (fracture_energy - 2.0 / 3.0 * strength * peak) / (softening_curve_area() * strength);
  return std::max(t, 1e-3 * peak);
}

}  // namespace

PointTraction cohesive_traction(const MaterialModel& m, double strength_factor, double h0, double o,
                                double s, double committed_damage) {
  const double k = m.penalty / h0;  // Pa per m: the initial slope of both branches
  if (!m.breakable) return {k * o, k * s, 0.0};

  PointTraction t;
  const double ft = strength_factor * m.tensile_strength;
  const double op = 2.0 * ft / k;
  const double ot = softening_length(m.gf_I, ft, op);
  const double compression = o < 0.0 ? -k * o : 0.0;
  const double fs = strength_factor * m.cohesion + compression * m.tan_friction;  // Fig. 2b
  const double abs_s = std::fabs(s);
  double dn = o > op ? (o - op) / ot : 0.0;
  double ds = 0.0, sp = 0.0;
  if (fs > 0.0) {
    sp = 2.0 * fs / k;
    if (abs_s > sp) ds = (abs_s - sp) / softening_length(m.gf_II, fs, sp);
  }
  t.damage = std::min(1.0, std::sqrt(dn * dn + ds * ds));  // Fig. 2c: failure at D = 1
  const double z = softening_curve(std::max(t.damage, committed_damage));
  t.normal = o < 0.0 ? -compression : hardening(o / op) * z * ft;
  if (fs > 0.0) t.shear = std::copysign(hardening(abs_s / sp) * z * fs, s);
  return t;
}

JointKinematics joint_kinematics(const Nodes& n, const index_t* jn) {
  JointKinematics k;
  const double ex = 0.5 * (n.x[jn[1]] + n.x[jn[2]] - n.x[jn[0]] - n.x[jn[3]]);
  const double ey = 0.5 * (n.y[jn[1]] + n.y[jn[2]] - n.y[jn[0]] - n.y[jn[3]]);
  k.length = std::hypot(ex, ey);
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
