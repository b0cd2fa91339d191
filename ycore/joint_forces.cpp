// Cohesive joint forces (DESIGN section 4, fdem-notes section 1).
//
// Tractions are integrated at the two ends and the middle (Simpson weights 1/6, 2/3, 1/6 of
// the initial length). The nodal forces are the exact derivative of the joint's virtual work
// sum w (sigma do + tau ds), including the turn of the joint's axis with the nodes: that term
// (q below) makes the forces conserve angular momentum, which the usual "traction along n and
// t on each node pair" misses at finite opening.
#include <cmath>

#include "ycore/joint_law.h"
#include "ycore/blocked_sum.h"
#include "ycore/mechanics.h"

namespace ydry {

void joint_forces(State& s, double dt) {
  const Nodes& n = s.nodes;
  Joints& jt = s.joints;
  const double thickness = s.mechanics.thickness_m;
  const std::int64_t nj = std::int64_t(jt.size());
#pragma omp parallel for schedule(static, kInterleavedChunk) if (std::size_t(nj) > parallel_minimum)
  for (std::int64_t j = 0; j < nj; ++j) {
    double* f = &jt.force[8 * j];  // x, y of nodes 0..3
    const MaterialModel& m = s.materials[jt.material[j]];
    if (jt.broken[j] || !m.mechanical) {
      for (int k = 0; k < 8; ++k) f[k] = 0.0;
      continue;
    }
    const index_t* node = &jt.node[4 * j];
    const double ex = 0.5 * (n.x[node[1]] + n.x[node[2]] - n.x[node[0]] - n.x[node[3]]);
    const double ey = 0.5 * (n.y[node[1]] + n.y[node[2]] - n.y[node[0]] - n.y[node[3]]);
    const double h = std::sqrt(ex * ex + ey * ey);  // not std::hypot: it cost a sixth of a step
    const double tx = ex / h, ty = ey / h, nx = -ty, ny = tx;
    const double d0x = n.x[node[0]] - n.x[node[3]], d0y = n.y[node[0]] - n.y[node[3]];
    const double d1x = n.x[node[1]] - n.x[node[2]], d1y = n.y[node[1]] - n.y[node[2]];
    const double h0 = jt.length0[j];
    const JointStrength strength = joint_strength(m, jt.strength_factor[j], h0);
    double g0x = 0, g0y = 0, g1x = 0, g1y = 0, q = 0;
    for (int p = 0; p < 3; ++p) {
      const double a = kJointPointShareOfEnd0[p], b = 1.0 - a;
      const double dx = a * d0x + b * d1x, dy = a * d0y + b * d1y;
      const double o = dx * nx + dy * ny, sl = dx * tx + dy * ty;
      const PointTraction tr = cohesive_traction(m, strength, o, sl, jt.damage[3 * j + p]);
      const double w = kJointPointWeight[p] * h0 * thickness;
      const double gx = w * (tr.normal * nx + tr.shear * tx), gy = w * (tr.normal * ny + tr.shear * ty);
      g0x += a * gx, g0y += a * gy, g1x += b * gx, g1y += b * gy;
      q += w * (tr.shear * o - tr.normal * sl) / h;
    }
    // Node 0 (end 0, first face) is pulled back by -g0, its partner 3 by +g0; the axis term
    // acts along n with +q/2 on nodes 0, 3 and -q/2 on nodes 1, 2.
    const double qx = 0.5 * q * nx, qy = 0.5 * q * ny;
    const double fresh[8] = {-g0x + qx, -g0y + qy, -g1x - qx, -g1y - qy,
                             g1x - qx,  g1y - qy,  g0x + qx,  g0y + qy};
    // Work over the step by the trapezoid of the forces before and after it: exact for a
    // linear spring, so a vibrating joint books no spurious work.
    double power = 0.0;
    for (int k = 0; k < 4; ++k)
      power += 0.5 * ((f[2 * k] + fresh[2 * k]) * n.vx[node[k]] + (f[2 * k + 1] + fresh[2 * k + 1]) * n.vy[node[k]]);
    jt.work[j] -= power * dt;
    for (int k = 0; k < 8; ++k) f[k] = fresh[k];
  }
}

}  // namespace ydry
