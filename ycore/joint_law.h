// The cohesive joint (DESIGN section 4, fdem-notes section 1): Munjiza's traction law at a
// point of a 4-node joint, and the joint's kinematics, shared by the force kernel, the
// damage commit and the crack statistics.
#pragma once

#include <cmath>

#include "ycore/state.h"

namespace ydry {

// Munjiza's softening curve z(D) (a = 0.63, b = 1.8, c = 6): z(0) = 1, z(1) = 0.
double softening_curve(double damage);
// Its area on [0, 1] (0.3863): the softening branch dissipates f * delta * this.
double softening_curve_area();

struct PointTraction {
  double normal = 0, shear = 0;  // Pa, on the first triangle's face (tension positive)
  double damage = 0;             // D of the current opening and slip, before the history
};

// Traction at a joint point of initial length h0 with normal opening o and slip s (m), given
// the point's committed damage. The joint's strength_factor multiplies the material's f_t and
// c (strength heterogeneity; the fracture energies stay the material's). Pre-peak
// o_p = 2 h0 f_t / p (Fig. 2a), then z(D) f_t with
// D = sqrt(((o - o_p)/o_t)^2 + ((|s| - s_p)/s_t)^2) (Fig. 2c), the softening lengths chosen so
// that pre-peak plus softening work is exactly gf_I (gf_II) per unit area. Mode II strength
// c + sigma_n tan(phi) under compression (Fig. 2b). Compression is a linear penalty p o / h0.
// In a material that is not breakable the joint is the linear penalty in both directions.
PointTraction cohesive_traction(const MaterialModel& m, double strength_factor, double h0, double o,
                                double s, double committed_damage);

// A joint's three integration points: the two ends and the middle, with Simpson weights of
// the initial length, and the share of end 0 (nodes 0, 3) in each point's opening and slip.
constexpr double kJointPointWeight[3] = {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0};
constexpr double kJointPointShareOfEnd0[3] = {1.0, 0.5, 0.0};

// Opening and slip (m) at the joint's two ends: end 0 pairs nodes 0 and 3, end 1 nodes 1 and 2.
// The normal points into the first triangle, so a positive opening separates the faces.
struct JointKinematics {
  double opening[2], slip[2];
  double length;  // current, m
  double nx, ny;  // unit normal, into the first triangle
};
JointKinematics joint_kinematics(const Nodes& nodes, const index_t* joint_nodes);

}  // namespace ydry
