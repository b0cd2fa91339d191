// The contact force kernel (contact_forces.h). One pass over the corners that have candidate
// pairs; each writes only its own pairs' forces and slips, so the result is the same on any
// number of threads (doc/threading.md "Gather, not scatter").
#include "ycore/contact/contact_forces.h"

#include <algorithm>
#include <cmath>

#include "ycore/contact/contact_geometry.h"
#include "ycore/contact/contact_search.h"
#include "ycore/state/blocked_sum.h"

namespace ydry {
namespace {

// Nothing to do at the corner: it is clearly outside every edge it is paired with, and no pair
// carries a force (whose work over the step would need booking) or a friction slip.
bool idle_corner(const Nodes& n, const Contact& c, index_t first, index_t last) {
  const index_t i = c.pair_node[first];
  for (index_t p = first; p < last; ++p) {
    if (c.pair_slip[p] != 0.0) return false;
    const double* force = &c.pair_force[6 * std::size_t(p)];
    for (int d = 0; d < 6; ++d)
      if (force[d] != 0.0) return false;
    if (!clearly_outside(n, i, c.pair_edge[p])) return false;
  }
  return true;
}

}  // namespace

void contact_forces(const Nodes& n, const Triangles& tri, const Mechanics& mech, const Ownership& ownership,
                    Contact& c, std::size_t material_count, double dt, FrictionUpdate friction) {
  if (c.penalty_pa <= 0.0) return;
  if (contact_pairs_stale(n, c)) build_contact_pairs(n, ownership, c);
  const double half_penalty = 0.5 * c.penalty_pa * mech.thickness_m;
  const double damping = 2.0 * c.damping_ratio;
  const std::size_t corners = c.node_pairs.size() - 1;
  // Blocks of 256 corners: the Peron deck has 3,528 contact corners, one block of the
  // default size, which one thread would do alone. Only the contacts' work is summed.
  const auto work = blocked_sum<1, 256>(corners, [&](std::size_t k, std::array<double, 1>& sum) {
    const index_t first = c.node_pairs[k], last = c.node_pairs[k + 1];
    // Most corners (seven in ten of the Peron deck's): the pass below would only find them apart
    // and book zero work; skipping them leaves every bit as it was.
    if (idle_corner(n, c, first, last)) return;
    const index_t i = c.pair_node[first];
    const ContactShares carrying = contact_shares(n, c, i, first, last);
    // Work done on the contacts over the step: the trapezoid of the forces before and after.
    const auto power = [&](index_t p) {
      const double* force = &c.pair_force[6 * std::size_t(p)];
      const index_t receivers[3] = {i, c.pair_edge[p], next_corner(c.pair_edge[p])};
      double sum_fv = 0.0;
      for (int k = 0; k < 3; ++k) sum_fv += force[2 * k] * n.vx[receivers[k]] + force[2 * k + 1] * n.vy[receivers[k]];
      return sum_fv;
    };
    // The friction slip is the corner's: when its contact passes from one edge to the next
    // (every corner of a conforming interface sits on a junction of two edges), the slip of
    // the pair it touched before passes to the pairs that take the contact over and have none,
    // projected on their edges. A corner out of contact has none.
    const auto carries = [&](index_t p) {
      return (carrying.count > 0 && carrying.pair[0] == p) || (carrying.count > 1 && carrying.pair[1] == p);
    };
    for (index_t p = first; p < last; ++p) {
      sum[0] -= 0.5 * power(p) * dt;
      for (int d = 0; d < 6; ++d) c.pair_force[6 * std::size_t(p) + d] = 0.0;
    }
    for (int k = 0; k < carrying.count; ++k) {
      if (c.pair_slip[carrying.pair[k]] != 0.0) continue;
      for (index_t p = first; p < last; ++p) {
        if (p == carrying.pair[k] || c.pair_slip[p] == 0.0) continue;
        const EdgeProjection before = project(n, i, c.pair_edge[p]);
        c.pair_slip[carrying.pair[k]] = c.pair_slip[p] * (before.tx * carrying.at[k].tx + before.ty * carrying.at[k].ty);
        break;
      }
    }
    for (index_t p = first; p < last; ++p)
      if (!carries(p)) c.pair_slip[p] = 0.0;

    const double stiffness_of_corner = corner_stiffness(c, half_penalty, i);
    for (int k = 0; k < carrying.count; ++k) {
      const index_t active = carrying.pair[k];
      const EdgeProjection& at = carrying.at[k];
      const index_t e = c.pair_edge[active], f = next_corner(e);
      const double stiffness = carrying.weight[k] * stiffness_of_corner;
      const double b = std::clamp(at.along, 0.0, 1.0), a = 1.0 - b;  // shares of e and f
      const double vx = n.vx[i] - a * n.vx[e] - b * n.vx[f], vy = n.vy[i] - a * n.vy[e] - b * n.vy[f];
      // Penalty plus a dashpot on the normal approach (a fraction of critical for the moving
      // side's mass), never pulling: it takes the bounce out of a contact that closes fast and
      // is zero at rest, so equilibria do not depend on it.
      const double mass = std::max(n.m[i], 0.5 * (n.m[e] + n.m[f]));
      const double approach = vx * at.ty - vy * at.tx;  // < 0: closing
      const double normal = std::max(0.0, -stiffness * at.gap - damping * std::sqrt(stiffness * mass) * approach);
      // Coulomb friction as an elastic slip: the spring stretches with the relative tangential
      // motion and pulls at most mu f_n; it slides, keeping the stretch at the cap, at every
      // step or only at equilibrium (FrictionUpdate).
      double& slip = c.pair_slip[active];
      slip += (vx * at.tx + vy * at.ty) * dt;
      const double cap = friction_coefficient(c, tri, material_count, i, e) * normal;
      double tangential = -stiffness * slip;
      if (!friction_sticks(tangential, cap)) {
        tangential = std::copysign(cap, tangential);
        if (friction == FrictionUpdate::every_step) slip = -tangential / stiffness;
      }
      const double fx = normal * at.ty + tangential * at.tx, fy = -normal * at.tx + tangential * at.ty;
      double* force = &c.pair_force[6 * std::size_t(active)];
      force[0] = fx, force[1] = fy;
      force[2] = -a * fx, force[3] = -a * fy;
      force[4] = -b * fx, force[5] = -b * fy;
      sum[0] -= 0.5 * power(active) * dt;
    }
  }, c.corner_owner_begin);
  c.work_J += work[0];
}

// A force evaluation of zero length: nothing moves, no work is booked, and every slip past its
// cap slides back to it.
void commit_friction_slip(const Nodes& n, const Triangles& tri, const Mechanics& mech, const Ownership& ownership,
                          Contact& c, std::size_t material_count) {
  contact_forces(n, tri, mech, ownership, c, material_count, 0.0, FrictionUpdate::every_step);
}

}  // namespace ydry
