// The cohesive joint (doc/physics.md "Joints"): Munjiza's traction law at a point of a
// 4-node joint, and the joint's kinematics, shared by the force kernel, the damage commit
// and the crack statistics.
#pragma once

#include <algorithm>
#include <cmath>

#include "ycore/state/state.h"

namespace ydry {

namespace joint_law_detail {
// e^x for -3.3 <= x <= 0, the softening curve's exponents, within 2e-15 relative: the Taylor
// series of e^(x/8) to degree 13 (remainder below 5e-17) by Horner's rule, squared three
// times. Inline and without branches, so that the joint kernel's vector pass and the scalar
// law do the same operations and get the same bits; libm's exp has no vector twin with its
// bits.
inline double softening_exp(double x) {
  constexpr double inverse_factorial[14] = {1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040,
                                            1.0 / 40320, 1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800,
                                            1.0 / 479001600, 1.0 / 6227020800};
  const double y = 0.125 * x;
  double e = inverse_factorial[13];
#pragma GCC unroll 13
  for (int k = 12; k >= 0; --k) e = e * y + inverse_factorial[k];
  e *= e;
  e *= e;
  return e * e;
}
}  // namespace joint_law_detail

// Munjiza's softening curve z(D) (a = 0.63, b = 1.8, c = 6): z(0) = 1, z(1) = 0; z = 1 for
// D <= 0. Without branches (both sides of the select are computed).
inline double softening_curve(double damage) {
  constexpr double a = 0.63, b = 1.8, c = 6.0;
  const double d = std::min(damage, 1.0), r = 1.0 - d, r2 = r * r;
  const double z = (1.0 - (a + b - 1.0) / (a + b) *
                              joint_law_detail::softening_exp(d * (a + c * b) / ((a + b) * (1.0 - a - b)))) *
                   (a * r + b * r2 * r2 * r2);  // (1 - D)^c with c = 6
  return damage <= 0.0 ? 1.0 : z;
}
// Its area on [0, 1] (0.3863): the softening branch dissipates f * delta * this.
double softening_curve_area();

struct PointTraction {
  double normal = 0, shear = 0;  // Pa, on the first triangle's face (tension positive)
  double damage = 0;             // D of the current opening and slip, before the history
};

// Helpers of cohesive_traction, which is inline: the force kernel calls it three times per
// joint and step.
namespace joint_law_detail {
// The pre-peak shape of Fig. 2a, b: 2r - r^2 up to the peak, 1 beyond.
inline double hardening(double r) { return r < 1.0 ? r * (2.0 - r) : 1.0; }

// Softening length from peak to zero stress that makes the total work per unit area equal
// the fracture energy: (2/3) f delta_p before the peak plus area(z) f delta_t after it.
// A fracture energy smaller than the pre-peak work (possible for the mode II strength under
// high compression) keeps a minimal softening length instead.
// (curve_area: softening_curve_area(), which a vectorised caller passes in.)
inline double softening_length(double fracture_energy, double strength, double peak,
                               double curve_area = softening_curve_area()) {
  const double t = (fracture_energy - 2.0 / 3.0 * strength * peak) / (curve_area * strength);
  return std::max(t, 1e-3 * peak);
}
}  // namespace joint_law_detail

// What the traction law needs of a joint that is the same at its three points and over a
// step: the slope of both branches k = p / h0 (Pa per m), the joint's strengths (its
// strength_factor times the material's f_t and c: strength heterogeneity; the fracture
// energies stay the material's) and the opening at the tensile peak o_p = 2 h0 f_t / p
// (Fig. 2a). The force kernel makes it once per joint and step, not once per point.
struct JointStrength {
  double k = 0, tensile = 0, cohesion = 0, peak_opening = 0;
};
inline JointStrength joint_strength(const MaterialModel& m, double strength_factor, double h0) {
  JointStrength j;
  j.k = m.penalty / h0;
  j.tensile = strength_factor * m.tensile_strength;
  j.cohesion = strength_factor * m.cohesion;
  j.peak_opening = 2.0 * j.tensile / j.k;
  return j;
}

// The compression (Pa) of a point with normal opening o on a joint of slope k (JointStrength):
// the linear penalty k o where the faces overlap, 0 where they are open.
inline double point_compression(double k, double o) { return o < 0.0 ? -k * o : 0.0; }

// Traction at a joint point with normal opening o and slip s (m), given the point's
// committed damage. Pre-peak up to o_p, then z(D) f_t with
// D = sqrt(((o - o_p)/o_t)^2 + ((|s| - s_p)/s_t)^2) (Fig. 2c), the softening lengths chosen so
// that pre-peak plus softening work is exactly gf_I (gf_II) per unit area. Mode II strength
// c + sigma_n tan(phi) under compression (Fig. 2b). Compression is a linear penalty p o / h0.
// In a material that is not breakable the joint is the linear penalty in both directions.
inline PointTraction cohesive_traction(const MaterialModel& m, const JointStrength& j, double o, double s,
                                       double committed_damage) {
  const double k = j.k;
  if (!m.breakable) return {k * o, k * s, 0.0};

  PointTraction t;
  const double ft = j.tensile, op = j.peak_opening;
  const double compression = point_compression(k, o);
  const double fs = j.cohesion + compression * m.tan_friction;  // Fig. 2b
  const double abs_s = std::fabs(s);
  // Softening lengths only past a peak: most joints, most of the time, are before both.
  const double dn = o > op ? (o - op) / joint_law_detail::softening_length(m.gf_I, ft, op) : 0.0;
  double ds = 0.0, sp = 0.0;
  if (fs > 0.0) {
    sp = 2.0 * fs / k;
    if (abs_s > sp) ds = (abs_s - sp) / joint_law_detail::softening_length(m.gf_II, fs, sp);
  }
  if (dn > 0.0 || ds > 0.0) t.damage = std::min(1.0, std::sqrt(dn * dn + ds * ds));  // Fig. 2c: failure at D = 1
  const double z = softening_curve(std::max(t.damage, committed_damage));
  t.normal = o < 0.0 ? -compression : joint_law_detail::hardening(o / op) * z * ft;
  if (fs > 0.0) t.shear = std::copysign(joint_law_detail::hardening(abs_s / sp) * z * fs, s);
  return t;
}

// cohesive_traction at an undamaged point before both peaks, bit for bit, without branches:
// the force kernel evaluates it for a whole chunk of joints at once, in vector registers, and
// takes cohesive_traction instead wherever `past_peak` is set (a peak passed, or no shear
// strength). The material must be breakable.
struct PrePeakTraction {
  double normal, shear;  // Pa, as in PointTraction
  double past_peak;      // 1 past a peak, else 0 (a double, so that the kernel vectorises)
};
inline PrePeakTraction pre_peak_traction(const JointStrength& j, double tan_friction, double o, double s) {
  const double compression = point_compression(j.k, o);
  const double fs = j.cohesion + compression * tan_friction;  // Fig. 2b
  const double sp = 2.0 * fs / j.k, abs_s = std::fabs(s);
  PrePeakTraction t;
  t.normal = o < 0.0 ? -compression : joint_law_detail::hardening(o / j.peak_opening) * j.tensile;
  t.shear = std::copysign(joint_law_detail::hardening(abs_s / sp) * fs, s);
  t.past_peak = o > j.peak_opening || !(fs > 0.0) || abs_s > sp ? 1.0 : 0.0;
  return t;
}

// cohesive_traction at any point, bit for bit, without branches: the force kernel evaluates
// it in vector registers for the damaged joints and those past a peak, and takes
// cohesive_traction instead wherever `needs_full_law` is set (the point has no shear
// strength, whose lengths the law leaves undefined). The material must be breakable;
// curve_area is softening_curve_area().
struct SoftenedTraction {
  double normal, shear;   // Pa, as in PointTraction
  double needs_full_law;  // > 0 or 0 (a double, so that the kernel vectorises)
};
struct SofteningConstants {  // the material's, for softened_traction
  double tan_friction, gf_I, gf_II, curve_area;
};
inline SoftenedTraction softened_traction(const JointStrength& j, const SofteningConstants& m, double o, double s,
                                          double committed_damage) {
  using joint_law_detail::hardening;
  using joint_law_detail::softening_length;
  const double k = j.k, ft = j.tensile, op = j.peak_opening;
  const double compression = point_compression(k, o);
  const double fs = j.cohesion + compression * m.tan_friction;  // Fig. 2b
  const double abs_s = std::fabs(s);
  // Both branches of every choice are computed (a select, no jump; the dropped one may be
  // inf). dn and ds are 0 or positive, so D = 0 where both are 0, as the full law has it. A
  // point without shear strength (fs <= 0) is left to the full law.
  const double dn = o > op ? (o - op) / softening_length(m.gf_I, ft, op, m.curve_area) : 0.0;
  const double sp = 2.0 * fs / k;
  const double ds = abs_s > sp ? (abs_s - sp) / softening_length(m.gf_II, fs, sp, m.curve_area) : 0.0;
  const double damage = std::min(1.0, std::sqrt(dn * dn + ds * ds));  // Fig. 2c
  const double z = softening_curve(std::max(damage, committed_damage));
  SoftenedTraction t;
  t.needs_full_law = fs > 0.0 ? 0.0 : 1.0;
  t.normal = o < 0.0 ? -compression : hardening(o / op) * z * ft;
  t.shear = std::copysign(hardening(abs_s / sp) * z * fs, s);
  return t;
}

// The same at a joint of initial length h0 and the given strength factor.
inline PointTraction cohesive_traction(const MaterialModel& m, double strength_factor, double h0, double o,
                                       double s, double committed_damage) {
  return cohesive_traction(m, joint_strength(m, strength_factor, h0), o, s, committed_damage);
}

// A joint's three integration points: the two ends and the middle, with Simpson weights of
// the initial length, and the share of end 0 (nodes 0, 3) in each point's opening and slip.
constexpr double kJointPointWeight[3] = {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0};
constexpr double kJointPointShareOfEnd0[3] = {1.0, 0.5, 0.0};

// A joint's current axis and the separations of its two node pairs, from the x and y of its
// nodes 0..3: end 0 is node 0 minus node 3, end 1 node 1 minus node 2.
struct JointFrame {
  double length;          // current, m
  double tx, ty, nx, ny;  // unit axis, from end 0 to end 1, and unit normal into the first triangle
  double d0x, d0y, d1x, d1y;
};
inline JointFrame joint_frame(double x0, double x1, double x2, double x3, double y0, double y1, double y2,
                              double y3) {
  JointFrame f;
  const double ex = 0.5 * (x1 + x2 - x0 - x3), ey = 0.5 * (y1 + y2 - y0 - y3);
  f.length = std::sqrt(ex * ex + ey * ey);  // not std::hypot: it cost a sixth of a step
  f.tx = ex / f.length;
  f.ty = ey / f.length;
  f.nx = -f.ty;
  f.ny = f.tx;
  f.d0x = x0 - x3, f.d0y = y0 - y3, f.d1x = x1 - x2, f.d1y = y1 - y2;
  return f;
}

// Normal opening o and slip s (m) at integration point p: the ends' separations weighted by
// kJointPointShareOfEnd0, on the joint's axes.
inline void point_opening_slip(const JointFrame& f, int p, double& o, double& s) {
  const double a = kJointPointShareOfEnd0[p], b = 1.0 - a;
  const double dx = a * f.d0x + b * f.d1x, dy = a * f.d0y + b * f.d1y;
  o = dx * f.nx + dy * f.ny;
  s = dx * f.tx + dy * f.ty;
}

// Opening and slip (m) at the joint's two ends: end 0 pairs nodes 0 and 3, end 1 nodes 1 and 2.
// The normal points into the first triangle, so a positive opening separates the faces.
struct JointKinematics {
  double opening[2], slip[2];
  double length;  // current, m
  double nx, ny;  // unit normal, into the first triangle
};
JointKinematics joint_kinematics(const Nodes& nodes, const index_t* joint_nodes);

}  // namespace ydry
