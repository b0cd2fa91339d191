// Constant-strain triangles, co-rotational (DESIGN section 4, fdem-notes section 2).
//
// F = [x1-x0 | x2-x0] inv0 is split as F = R U (polar); Hooke's law acts on the Biot strain
// U - I in the rotated frame, minus the shrinkage stress 3 K* eps_sh (Eq. 19):
//   T = lambda tr(U - I) I + 2 mu (U - I) - 3 K* eps_sh I,   P = R T (first Piola-Kirchhoff).
// A rigid rotation gives U = I and no stress; at small strain T is the linear-elastic stress.
// The shrinkage case of paper 4.3 is exact in this law (the strain is linear in the stretch),
// and P F^T = R T U R^T is symmetric because T is a polynomial in U, so the nodal forces
// conserve angular as well as linear momentum.
#include <cmath>

#include "ycore/corotational.h"
#include "ycore/mechanics.h"

namespace ydry {

void element_forces(State& s) {
  Nodes& n = s.nodes;
  Triangles& tri = s.triangles;
  const double thickness = s.mechanics.thickness_m;
  const double gx = s.mechanics.gravity_x, gy = s.mechanics.gravity_y;
  for_each_owned(s.ownership.triangle_begin, tri.size(), [&](std::size_t e) {
    const MaterialModel& m = s.materials[tri.material[e]];
    const index_t i = corner_node(index_t(e), 0);
    double f[6] = {0, 0, 0, 0, 0, 0};  // x, y of corners 0, 1, 2
    if (m.mechanical) {
      const CorotationalState k = corotational_state(n, tri, m, std::size_t(e));
      const double c = k.c, sn = k.s, T00 = k.T00, T11 = k.T11, T01 = k.T01;
      const double* inv = &tri.inv0[4 * e];
      const double P00 = c * T00 - sn * T01, P01 = c * T01 - sn * T11;
      const double P10 = sn * T00 + c * T01, P11 = sn * T01 + c * T11;
      // Rotated stress R T R^T: the stress of the law in the current axes (Cauchy at small strain).
      tri.sxx[e] = P00 * c - P01 * sn;
      tri.syy[e] = P10 * sn + P11 * c;
      tri.sxy[e] = P00 * sn + P01 * c;
      // Internal work A0 t P : dF; dF/dx of corners 1, 2 through the columns of inv0^T.
      const double v = tri.area0[e] * thickness;
      const double G00 = v * (P00 * inv[0] + P01 * inv[1]), G01 = v * (P00 * inv[2] + P01 * inv[3]);
      const double G10 = v * (P10 * inv[0] + P11 * inv[1]), G11 = v * (P10 * inv[2] + P11 * inv[3]);
      f[2] = -G00, f[3] = -G10, f[4] = -G01, f[5] = -G11;
      f[0] = G00 + G01, f[1] = G10 + G11;
      const double weight = tri.mass_kg[e] / 3.0;
      for (int a = 0; a < 3; ++a) f[2 * a] += weight * gx, f[2 * a + 1] += weight * gy;
    }
    for (int a = 0; a < 3; ++a) {
      n.fx[i + a] = f[2 * a];
      n.fy[i + a] = f[2 * a + 1];
    }
  });
}

}  // namespace ydry
