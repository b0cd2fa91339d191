// The co-rotational kinematics and stress of one constant-strain triangle, shared by the
// force kernel and the energy bookkeeping. See element_forces.cpp for the law.
#pragma once

#include <cmath>

#include "ycore/state/state.h"

namespace ydry {

struct CorotationalState {
  double c, s;              // rotation R = [c -s; s c] of F = R U
  double e00, e11, e01;     // Biot strain U - I
  double T00, T11, T01;     // stress in the rotated frame, Pa (shrinkage included)
};

// From the triangle's corners x[0..2], y[0..2], its inverse initial edge matrix, the
// material's Lame constants and 3 K*, and its shrinkage strain.
inline CorotationalState corotational_state(const double* x, const double* y, const double* inv, double lambda,
                                            double mu, double bulk3, double shrinkage_strain) {
  const double ax = x[1] - x[0], bx = x[2] - x[0];
  const double ay = y[1] - y[0], by = y[2] - y[0];
  const double F00 = ax * inv[0] + bx * inv[2], F01 = ax * inv[1] + bx * inv[3];
  const double F10 = ay * inv[0] + by * inv[2], F11 = ay * inv[1] + by * inv[3];
  CorotationalState k;
  const double r = std::sqrt((F00 + F11) * (F00 + F11) + (F10 - F01) * (F10 - F01));
  k.c = (F00 + F11) / r;
  k.s = (F10 - F01) / r;
  k.e00 = k.c * F00 + k.s * F10 - 1.0;  // U = R^T F
  k.e11 = -k.s * F01 + k.c * F11 - 1.0;
  k.e01 = 0.5 * ((k.c * F01 + k.s * F11) + (-k.s * F00 + k.c * F10));
  const double iso = lambda * (k.e00 + k.e11) - bulk3 * shrinkage_strain;  // Eq. 19
  k.T00 = iso + 2.0 * mu * k.e00;
  k.T11 = iso + 2.0 * mu * k.e11;
  k.T01 = 2.0 * mu * k.e01;
  return k;
}

// The first Piola-Kirchhoff stress P = R T of the law.
struct FirstPiola {
  double P00, P01, P10, P11;
};
inline FirstPiola first_piola(const CorotationalState& k) {
  const double c = k.c, sn = k.s, T00 = k.T00, T11 = k.T11, T01 = k.T01;
  return {c * T00 - sn * T01, c * T01 - sn * T11, sn * T00 + c * T01, sn * T01 + c * T11};
}

// The internal forces A0 t P : dF/dx of corners 1 and 2 (G00, G10 on corner 1, G01, G11 on
// corner 2, each with a minus sign), through the columns of inv0^T; corner 0 takes the sum.
// `volume` is A0 t.
struct CornerForces {
  double G00, G01, G10, G11;
};
inline CornerForces corner_forces(const FirstPiola& p, const double* inv, double volume) {
  const double v = volume;
  return {v * (p.P00 * inv[0] + p.P01 * inv[1]), v * (p.P00 * inv[2] + p.P01 * inv[3]),
          v * (p.P10 * inv[0] + p.P11 * inv[1]), v * (p.P10 * inv[2] + p.P11 * inv[3])};
}

// The same for triangle e of the state.
inline CorotationalState corotational_state(const Nodes& n, const Triangles& tri, const MaterialModel& m,
                                            std::size_t e) {
  const index_t i = corner_node(index_t(e), 0);
  return corotational_state(&n.x[i], &n.y[i], &tri.inv0[4 * e], m.lambda, m.mu, m.bulk3, tri.shrinkage_strain[e]);
}

}  // namespace ydry
