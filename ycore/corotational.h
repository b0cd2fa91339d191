// The co-rotational kinematics and stress of one constant-strain triangle, shared by the
// force kernel and the energy bookkeeping. See element_forces.cpp for the law.
#pragma once

#include <cmath>

#include "ycore/state.h"

namespace ydry {

struct CorotationalState {
  double c, s;              // rotation R = [c -s; s c] of F = R U
  double e00, e11, e01;     // Biot strain U - I
  double T00, T11, T01;     // stress in the rotated frame, Pa (shrinkage included)
};

inline CorotationalState corotational_state(const Nodes& n, const Triangles& tri, const MaterialModel& m,
                                            std::size_t e) {
  const index_t i = corner_node(index_t(e), 0);
  const double* inv = &tri.inv0[4 * e];
  const double ax = n.x[i + 1] - n.x[i], bx = n.x[i + 2] - n.x[i];
  const double ay = n.y[i + 1] - n.y[i], by = n.y[i + 2] - n.y[i];
  const double F00 = ax * inv[0] + bx * inv[2], F01 = ax * inv[1] + bx * inv[3];
  const double F10 = ay * inv[0] + by * inv[2], F11 = ay * inv[1] + by * inv[3];
  CorotationalState k;
  const double r = std::sqrt((F00 + F11) * (F00 + F11) + (F10 - F01) * (F10 - F01));
  k.c = (F00 + F11) / r;
  k.s = (F10 - F01) / r;
  k.e00 = k.c * F00 + k.s * F10 - 1.0;  // U = R^T F
  k.e11 = -k.s * F01 + k.c * F11 - 1.0;
  k.e01 = 0.5 * ((k.c * F01 + k.s * F11) + (-k.s * F00 + k.c * F10));
  const double iso = m.lambda * (k.e00 + k.e11) - m.bulk3 * tri.shrinkage_strain[e];  // Eq. 19
  k.T00 = iso + 2.0 * m.mu * k.e00;
  k.T11 = iso + 2.0 * m.mu * k.e11;
  k.T01 = 2.0 * m.mu * k.e01;
  return k;
}

}  // namespace ydry
