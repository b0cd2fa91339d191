// Cohesive joint forces (doc/physics.md "Joints").
//
// Tractions are integrated at the two ends and the middle (Simpson weights 1/6, 2/3, 1/6 of
// the initial length). The nodal forces are the exact derivative of the joint's virtual work
// sum w (sigma do + tau ds), including the turn of the joint's axis with the nodes: that term
// (q below) makes the forces conserve angular momentum, which the usual "traction along n and
// t on each node pair" misses at finite opening.
//
// Most joints, most of the time, are intact and before both peaks of the law at all three
// points. The kernel takes each thread's joints (ycore/state/ownership.h) of a material with mechanics
// (Joints::mechanical_runs; a rigid material's joints carry nothing, ever) in chunks of
// kJointChunk, sorted into passes: the node coordinates and constants of the undamaged joints
// are copied into arrays, over which the pre-peak law (pre_peak_traction) runs in vector
// registers; the damaged joints, and those the pre-peak law finds past a peak at some point,
// are copied into a second set of arrays, over which the whole law (softened_traction, with
// ydry's own exp in z(D)) runs in vector registers; each joint that neither could take (its
// material cannot break; a point has no shear strength) is done with the scalar law
// (joint_nodal_forces), broken joints are zeroed, and every joint's forces are stored.
// The vector laws do the same operations in the same order as the full law where they apply,
// and this file is compiled without FMA contraction (CMakeLists.txt), so the result is the full
// law's, bit for bit (tests/test_mechanics.cpp).
#include "ycore/solid/joint_forces.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ycore/solid/joint_law.h"
#include "ycore/solid/vector_clones.h"

namespace ydry {
namespace {

// Sums the three points' tractions into the joint's nodal forces.
struct JointForceSum {
  double g0x = 0, g0y = 0, g1x = 0, g1y = 0, q = 0;
  // Point p with weight w (its share of length x thickness), tractions normal and shear at
  // opening o and slip s.
  void add(const JointFrame& f, int p, double w, double normal, double shear, double o, double s) {
    const double a = kJointPointShareOfEnd0[p], b = 1.0 - a;
    const double gx = w * (normal * f.nx + shear * f.tx), gy = w * (normal * f.ny + shear * f.ty);
    g0x += a * gx, g0y += a * gy, g1x += b * gx, g1y += b * gy;
    q += w * (shear * o - normal * s) / f.length;
  }
  // Node 0 (end 0, first face) is pulled back by -g0, its partner 3 by +g0; the axis term
  // acts along n with +q/2 on nodes 0, 3 and -q/2 on nodes 1, 2.
  void forces(const JointFrame& f, double out[8]) const {
    const double qx = 0.5 * q * f.nx, qy = 0.5 * q * f.ny;
    out[0] = -g0x + qx, out[1] = -g0y + qy, out[2] = -g1x - qx, out[3] = -g1y - qy;
    out[4] = g1x - qx, out[5] = g1y - qy, out[6] = g0x + qx, out[7] = g0y + qy;
  }
};

// How the kernel takes a joint of the chunk.
enum class JointPass : std::uint8_t {
  broken,    // carries nothing
  pre_peak,  // the pre-peak law, in vector registers
  softened,  // the whole law, in vector registers
  scalar     // neither vector law's (its material cannot break; a point without shear strength)
};

// Every joint of a chunk: its pass and its forces on nodes 0..3 (x, y).
struct ChunkForces {
  JointPass pass[kJointChunk];
  double fresh[8][kJointChunk];
};

// The chunk's intact joints of a breakable material without damage, as arrays over them, so
// that the pre-peak law vectorises.
struct PrePeakChunk {
  int count = 0;
  int joint[kJointChunk];                       // its index in the chunk
  double x[4][kJointChunk], y[4][kJointChunk];  // nodes 0..3
  double h0[kJointChunk], tan_friction[kJointChunk];
  // JointStrength:
  double k[kJointChunk], tensile[kJointChunk], cohesion[kJointChunk], peak_opening[kJointChunk];
  double past_peak[kJointChunk];  // > 0: a point past a peak, for the whole law
  double fresh[8][kJointChunk];
};

// The chunk's joints with damage and those the pre-peak law found past a peak, as arrays over
// them, so that the whole law vectorises.
struct SoftenedChunk {
  int count = 0;
  int joint[kJointChunk];                       // its index in the chunk
  double x[4][kJointChunk], y[4][kJointChunk];  // nodes 0..3
  double h0[kJointChunk];
  double k[kJointChunk], tensile[kJointChunk], cohesion[kJointChunk], peak_opening[kJointChunk];
  double tan_friction[kJointChunk], gf_I[kJointChunk], gf_II[kJointChunk];
  double damage[3][kJointChunk];     // committed, at the joint's three points
  double needs_full_law[kJointChunk];
  double fresh[8][kJointChunk];
};

// A joint's forces from the coordinates of its nodes, with traction(p, o, s) the law at point p
// (its normal and shear traction and a flag); returns the sum of the three points' flags.
// Always inlined: the vector passes vectorise only with it inside their loops, and GCC, left
// to itself, calls the softened law's copy (the larger one) out of line, in scalar code.
template <class Traction>
[[gnu::always_inline]] inline double joint_forces_with(const JointFrame& f, double h0, double thickness,
                                                       Traction traction, double out[8]) {
  JointForceSum sum;
  double flags = 0.0;
#pragma GCC unroll 3
  for (int p = 0; p < 3; ++p) {
    double o, sl;
    point_opening_slip(f, p, o, sl);
    double normal, shear;
    flags += traction(p, o, sl, normal, shear);
    sum.add(f, p, kJointPointWeight[p] * h0 * thickness, normal, shear, o, sl);
  }
  sum.forces(f, out);
  return flags;
}

// Joints are numbered with their first triangle, so a joint's second triangle lies ahead in
// the node arrays: on a mesh larger than the cache its nodes' lines are first touched here and
// in store_chunk, and the loads wait on memory unless they are asked for this many joints
// ahead (bench/RESULTS.md).
constexpr std::size_t kPrefetchJoints = 24;

// Joint i of the chunk, with the coordinates of its nodes 0..3 and its strength, into d.
void add_softened(SoftenedChunk& d, int i, const double x[4], const double y[4], const JointStrength& strength,
                  double h0, const MaterialModel& m, const double damage[3]) {
  const int l = d.count++;
  d.joint[l] = i;
  for (int k = 0; k < 4; ++k) d.x[k][l] = x[k], d.y[k][l] = y[k];
  d.h0[l] = h0;
  d.k[l] = strength.k, d.tensile[l] = strength.tensile, d.cohesion[l] = strength.cohesion;
  d.peak_opening[l] = strength.peak_opening;
  d.tan_friction[l] = m.tan_friction, d.gf_I[l] = m.gf_I, d.gf_II[l] = m.gf_II;
  for (int p = 0; p < 3; ++p) d.damage[p][l] = damage[p];
}

// Sorts the chunk's joints into their passes: the undamaged ones of a breakable material into
// c, the damaged ones into d.
void gather_chunk(const Nodes& n, const Joints& jt, const std::vector<MaterialModel>& materials, std::size_t first,
                  int count, ChunkForces& out, PrePeakChunk& c, SoftenedChunk& d) {
  c.count = d.count = 0;
  for (int i = 0; i < count; ++i) {
    const std::size_t j = first + std::size_t(i);
    if (j + kPrefetchJoints < jt.size()) {
      const index_t ahead = jt.node[4 * (j + kPrefetchJoints) + 2];
      for (const double* a : {&n.x[ahead], &n.y[ahead], &n.vx[ahead], &n.vy[ahead]}) __builtin_prefetch(a);
    }
    const MaterialModel& m = materials[jt.law[j]];
    if (jt.broken[j] || !m.breakable) {
      out.pass[i] = jt.broken[j] ? JointPass::broken : JointPass::scalar;
      continue;
    }
    const index_t* node = &jt.node[4 * j];
    double x[4], y[4];
    for (int k = 0; k < 4; ++k) x[k] = n.x[node[k]], y[k] = n.y[node[k]];
    const JointStrength strength = joint_strength(m, jt.strength_factor[j], jt.length0[j]);
    const double* damage = &jt.damage[3 * j];
    if (damage[0] > 0.0 || damage[1] > 0.0 || damage[2] > 0.0) {
      out.pass[i] = JointPass::softened;
      add_softened(d, i, x, y, strength, jt.length0[j], m, damage);
      continue;
    }
    out.pass[i] = JointPass::pre_peak;
    const int p = c.count++;
    c.joint[p] = i;
    for (int k = 0; k < 4; ++k) c.x[k][p] = x[k], c.y[k][p] = y[k];
    c.h0[p] = jt.length0[j];
    c.tan_friction[p] = m.tan_friction;
    c.k[p] = strength.k, c.tensile[p] = strength.tensile, c.cohesion[p] = strength.cohesion;
    c.peak_opening[p] = strength.peak_opening;
  }
}

// The pre-peak law at every joint of c; flags the joints past a peak.
YDRY_AVX2_CLONE void pre_peak_forces(PrePeakChunk& c, double thickness) {
  const int count = c.count;
  for (int i = 0; i < count; ++i) {
    const JointFrame f = joint_frame(c.x[0][i], c.x[1][i], c.x[2][i], c.x[3][i], c.y[0][i], c.y[1][i],
                                     c.y[2][i], c.y[3][i]);
    const JointStrength strength{c.k[i], c.tensile[i], c.cohesion[i], c.peak_opening[i]};
    const double tan_friction = c.tan_friction[i];
    double out[8];
    c.past_peak[i] = joint_forces_with(f, c.h0[i], thickness, [&](int, double o, double sl, double& normal, double& shear) {
      const PrePeakTraction t = pre_peak_traction(strength, tan_friction, o, sl);
      normal = t.normal, shear = t.shear;
      return t.past_peak;
    }, out);
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) c.fresh[k][i] = out[k];
  }
}

// The pre-peak law's forces into the chunk, or, for a joint past a peak, the joint into d.
void take_pre_peak(const Joints& jt, const std::vector<MaterialModel>& materials, std::size_t first,
                   const PrePeakChunk& c, ChunkForces& out, SoftenedChunk& d) {
  for (int p = 0; p < c.count; ++p) {
    const int i = c.joint[p];
    if (c.past_peak[p] > 0.0) {
      const std::size_t j = first + std::size_t(i);
      const double x[4] = {c.x[0][p], c.x[1][p], c.x[2][p], c.x[3][p]};
      const double y[4] = {c.y[0][p], c.y[1][p], c.y[2][p], c.y[3][p]};
      const JointStrength strength{c.k[p], c.tensile[p], c.cohesion[p], c.peak_opening[p]};
      out.pass[i] = JointPass::softened;
      add_softened(d, i, x, y, strength, c.h0[p], materials[jt.law[j]], &jt.damage[3 * j]);
      continue;
    }
    for (int k = 0; k < 8; ++k) out.fresh[k][i] = c.fresh[k][p];
  }
}

// The whole law at every joint of d; flags the joints with a point without shear strength.
YDRY_AVX2_CLONE void softened_forces(SoftenedChunk& d, double thickness, double curve_area) {
  const int count = d.count;
  for (int l = 0; l < count; ++l) {
    const JointFrame f = joint_frame(d.x[0][l], d.x[1][l], d.x[2][l], d.x[3][l], d.y[0][l], d.y[1][l],
                                     d.y[2][l], d.y[3][l]);
    const JointStrength strength{d.k[l], d.tensile[l], d.cohesion[l], d.peak_opening[l]};
    const SofteningConstants constants{d.tan_friction[l], d.gf_I[l], d.gf_II[l], curve_area};
    const double damage[3] = {d.damage[0][l], d.damage[1][l], d.damage[2][l]};
    double out[8];
    d.needs_full_law[l] = joint_forces_with(f, d.h0[l], thickness, [&](int p, double o, double sl, double& normal, double& shear) {
      const SoftenedTraction t = softened_traction(strength, constants, o, sl, damage[p]);
      normal = t.normal, shear = t.shear;
      return t.needs_full_law;
    }, out);
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) d.fresh[k][l] = out[k];
  }
}

// The softened pass's forces into the chunk, or the joint to the scalar law.
void take_softened(const SoftenedChunk& d, ChunkForces& out) {
  for (int l = 0; l < d.count; ++l) {
    const int i = d.joint[l];
    if (d.needs_full_law[l] > 0.0) {
      out.pass[i] = JointPass::scalar;
      continue;
    }
    for (int k = 0; k < 8; ++k) out.fresh[k][i] = d.fresh[k][l];
  }
}

// The chunk's forces into `force`, the full law where the chunk says so. Broken joints carry
// nothing.
void store_chunk(const Nodes& n, const Mechanics& mech, const std::vector<MaterialModel>& materials, const Joints& jt,
                 std::size_t first, int count, const ChunkForces& c, std::vector<double>& force) {
  for (int i = 0; i < count; ++i) {
    const std::size_t j = first + std::size_t(i);
    double* f = &force[8 * j];
    if (c.pass[i] == JointPass::broken)
      for (int k = 0; k < 8; ++k) f[k] = 0.0;
    else if (c.pass[i] == JointPass::scalar)
      joint_nodal_forces(n, jt, mech, materials, j, f);
    else
      for (int k = 0; k < 8; ++k) f[k] = c.fresh[k][i];
  }
}

}  // namespace

void joint_nodal_forces(const Nodes& n, const Joints& jt, const Mechanics& mech,
                        const std::vector<MaterialModel>& materials, std::size_t j, double out[8]) {
  const index_t* node = &jt.node[4 * j];
  const double x[4] = {n.x[node[0]], n.x[node[1]], n.x[node[2]], n.x[node[3]]};
  const double y[4] = {n.y[node[0]], n.y[node[1]], n.y[node[2]], n.y[node[3]]};
  joint_nodal_forces_at(jt, mech, materials, j, x, y, out);
}

void joint_nodal_forces_at(const Joints& jt, const Mechanics& mech, const std::vector<MaterialModel>& materials,
                           std::size_t j, const double x[4], const double y[4], double out[8],
                           const double* held_compression) {
  const MaterialModel& m = materials[jt.law[j]];
  if (jt.broken[j] || !m.mechanical) {
    for (int k = 0; k < 8; ++k) out[k] = 0.0;
    return;
  }
  const JointFrame f = joint_frame(x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3]);
  const double h0 = jt.length0[j];
  const JointStrength strength = joint_strength(m, jt.strength_factor[j], h0);
  // Held, the law's friction angle moves into each point's cohesion, at the compression held
  // (the copy only then: the force kernel's scalar pass comes here too).
  std::optional<MaterialModel> held_law;
  if (held_compression) held_law.emplace(m).tan_friction = 0.0;
  const MaterialModel& law = held_law ? *held_law : m;
  joint_forces_with(f, h0, mech.thickness_m, [&](int p, double o, double sl, double& normal, double& shear) {
    JointStrength point = strength;
    if (held_compression) point.cohesion += held_compression[p] * m.tan_friction;
    const PointTraction t = cohesive_traction(law, point, o, sl, jt.damage[3 * j + p]);
    normal = t.normal, shear = t.shear;
    return 0.0;
  }, out);
}

void joint_point_compressions(const Joints& jt, const std::vector<MaterialModel>& materials, std::size_t j,
                              const double x[4], const double y[4], double compression[3]) {
  const JointFrame f = joint_frame(x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3]);
  const double k = joint_strength(materials[jt.law[j]], jt.strength_factor[j], jt.length0[j]).k;
  for (int p = 0; p < 3; ++p) {
    double o, s;
    point_opening_slip(f, p, o, s);
    compression[p] = point_compression(k, o);
  }
}

void joint_forces(const Nodes& n, const Mechanics& mech, const Ownership& ownership,
                  const std::vector<MaterialModel>& materials, const Joints& jt, std::vector<double>& force) {
  const double thickness = mech.thickness_m, curve_area = softening_curve_area();
  const std::size_t nj = jt.size();
  const std::vector<index_t>& runs = jt.mechanical_runs;
#pragma omp parallel if (nj > parallel_minimum)
  {
    // The thread's joints of a material with mechanics: its range cut by the runs (a few
    // hundred on the Peron mesh, one where no material is rigid) that begin before its end.
    const IndexRange owned = owned_range(ownership.joint_begin, nj);
    ChunkForces forces;
    PrePeakChunk pre_peak;
    SoftenedChunk softened;
    for (std::size_t r = 0; r < runs.size() && runs[r] < owned.end; r += 2) {
      const std::size_t begin = std::max<std::size_t>(runs[r], owned.begin);
      const std::size_t end = std::min<std::size_t>(runs[r + 1], owned.end);
      for (std::size_t first = begin; first < end; first += kJointChunk) {
        const int count = int(std::min<std::size_t>(kJointChunk, end - first));
        gather_chunk(n, jt, materials, first, count, forces, pre_peak, softened);
        pre_peak_forces(pre_peak, thickness);
        take_pre_peak(jt, materials, first, pre_peak, forces, softened);
        softened_forces(softened, thickness, curve_area);
        take_softened(softened, forces);
        store_chunk(n, mech, materials, jt, first, count, forces, force);
      }
    }
  }
}

}  // namespace ydry
