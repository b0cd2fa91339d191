// The contact phases (contact_forces.h). Each is one pass over the corners that have candidate
// pairs; each corner writes only its own pairs, so the result is the same on any number of
// threads (doc/threading.md "Gather, not scatter").
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

// Calls visit(first pair, last pair, shares) for every corner update_contact_pairs found busy,
// in blocks of 256 corners (the Peron deck has 3,528 contact corners, one block of the default
// size, which one thread would do alone), and returns the sum the visits add to.
template <class Visit>
double for_each_busy_corner(const Contact& c, Visit&& visit) {
  if (c.corner_busy.empty()) return 0.0;  // no pairs
  const auto sum = blocked_sum<1, 256>(c.corner_busy.size(), [&](std::size_t k, std::array<double, 1>& s) {
    if (c.corner_busy[k]) visit(c.node_pairs[k], c.node_pairs[k + 1], c.corner_shares[k], s[0]);
  }, c.corner_owner_begin);
  return sum[0];
}

// Where the carrying pair k of a corner (contact_shares) meets its edge, as the shares a, b of
// the edge's ends e and f, and the corner's velocity relative to that point.
struct PairMotion {
  index_t i, e, f;
  double a, b, vx, vy;
};
PairMotion pair_motion(const Nodes& n, const Contact& c, const ContactShares& carrying, int k) {
  PairMotion m;
  m.i = c.pair_node[carrying.pair[k]], m.e = c.pair_edge[carrying.pair[k]], m.f = next_corner(m.e);
  m.b = std::clamp(carrying.at[k].along, 0.0, 1.0), m.a = 1.0 - m.b;
  m.vx = n.vx[m.i] - m.a * n.vx[m.e] - m.b * n.vx[m.f], m.vy = n.vy[m.i] - m.a * n.vy[m.e] - m.b * n.vy[m.f];
  return m;
}

// What the carrying pair k of corner i (contact_shares) pushes with: the penalty's normal
// force with the dashpot on its approach, the friction's cap mu f_n, and the pull of the elastic
// slip held within the cap.
struct PairTraction {
  double a = 0, b = 0;  // the corner's shares of the edge's ends e and f
  double stiffness = 0, normal = 0, cap = 0, tangential = 0;
  bool sticks = true;
};
PairTraction pair_traction(const Nodes& n, const Triangles& tri, const Contact& c, std::size_t material_count,
                           double half_penalty, const ContactShares& carrying, int k) {
  const EdgeProjection& at = carrying.at[k];
  const PairMotion m = pair_motion(n, c, carrying, k);
  const index_t i = m.i, e = m.e, f = m.f;
  PairTraction t;
  t.stiffness = carrying.weight[k] * corner_stiffness(c, half_penalty, i);
  t.a = m.a, t.b = m.b;
  const double vx = m.vx, vy = m.vy;
  // Penalty plus a dashpot on the normal approach (a fraction of critical for the moving
  // side's mass), never pulling: it takes the bounce out of a contact that closes fast and
  // is zero at rest, so equilibria do not depend on it.
  const double mass = std::max(n.m[i], 0.5 * (n.m[e] + n.m[f]));
  const double approach = vx * at.ty - vy * at.tx;  // < 0: closing
  const double damping = 2.0 * c.damping_ratio;
  t.normal = std::max(0.0, -t.stiffness * at.gap - damping * std::sqrt(t.stiffness * mass) * approach);
  // Coulomb friction as an elastic slip: the spring pulls at most mu f_n.
  t.cap = friction_coefficient(c, tri, material_count, i, e) * t.normal;
  t.tangential = -t.stiffness * c.pair_slip[carrying.pair[k]];
  t.sticks = friction_sticks(t.tangential, t.cap);
  if (!t.sticks) t.tangential = std::copysign(t.cap, t.tangential);
  return t;
}

// The power of pair p's forces on the velocities of its three nodes.
double pair_power(const Nodes& n, const Contact& c, const double* force, index_t p) {
  const index_t receivers[3] = {c.pair_node[p], c.pair_edge[p], next_corner(c.pair_edge[p])};
  double sum_fv = 0.0;
  for (int k = 0; k < 3; ++k) sum_fv += force[2 * k] * n.vx[receivers[k]] + force[2 * k + 1] * n.vy[receivers[k]];
  return sum_fv;
}

}  // namespace

void update_contact_pairs(const Nodes& n, const Ownership& ownership, Contact& c) {
  if (c.penalty_pa <= 0.0) return;
  if (contact_pairs_stale(n, c)) build_contact_pairs(n, ownership, c);
  const std::size_t corners = c.node_pairs.size() - 1;
  c.corner_busy.resize(corners);
  c.corner_shares.resize(corners);
  // Most corners (seven in ten of the Peron deck's) are idle: the phases would only find them
  // apart, with nothing to carry, book or commit.
  for_each_owned(c.corner_owner_begin, corners, [&](std::size_t k) {
    const index_t first = c.node_pairs[k], last = c.node_pairs[k + 1];
    c.corner_busy[k] = !idle_corner(n, c, first, last);
    if (c.corner_busy[k]) c.corner_shares[k] = contact_shares(n, c, c.pair_node[first], first, last);
  });
}

void advance_friction_slip(const Nodes& n, double dt, Contact& c) {
  if (c.penalty_pa <= 0.0) return;
  for_each_busy_corner(c, [&](index_t first, index_t last, const ContactShares& carrying, double&) {
    const index_t i = c.pair_node[first];
    const auto carries = [&](index_t p) {
      return (carrying.count > 0 && carrying.pair[0] == p) || (carrying.count > 1 && carrying.pair[1] == p);
    };
    // The friction slip is the corner's: when its contact passes from one edge to the next
    // (every corner of a conforming interface sits on a junction of two edges), the slip of
    // the pair it touched before passes to the pairs that take the contact over and have none,
    // projected on their edges. A corner out of contact has none.
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
    // The slip stretches with the relative tangential motion.
    for (int k = 0; k < carrying.count; ++k) {
      const PairMotion m = pair_motion(n, c, carrying, k);
      c.pair_slip[carrying.pair[k]] += (m.vx * carrying.at[k].tx + m.vy * carrying.at[k].ty) * dt;
    }
  });
}

void contact_forces(const Nodes& n, const Triangles& tri, const Mechanics& mech, const Contact& c,
                    std::size_t material_count, std::vector<double>& pair_force) {
  if (c.penalty_pa <= 0.0) return;
  const double half_penalty = 0.5 * c.penalty_pa * mech.thickness_m;
  for_each_busy_corner(c, [&](index_t first, index_t last, const ContactShares& carrying, double&) {
    std::fill(&pair_force[6 * std::size_t(first)], &pair_force[6 * std::size_t(last)], 0.0);
    for (int k = 0; k < carrying.count; ++k) {
      const EdgeProjection& at = carrying.at[k];
      const PairTraction t = pair_traction(n, tri, c, material_count, half_penalty, carrying, k);
      const double fx = t.normal * at.ty + t.tangential * at.tx, fy = -t.normal * at.tx + t.tangential * at.ty;
      double* force = &pair_force[6 * std::size_t(carrying.pair[k])];
      force[0] = fx, force[1] = fy;
      force[2] = -t.a * fx, force[3] = -t.a * fy;
      force[4] = -t.b * fx, force[5] = -t.b * fy;
    }
  });
}

void keep_contact_forces(const Contact& c, std::vector<double>& force_before) {
  force_before.resize(c.pair_force.size());
  for_each_busy_corner(c, [&](index_t first, index_t last, const ContactShares&, double&) {
    std::copy(&c.pair_force[6 * std::size_t(first)], &c.pair_force[6 * std::size_t(last)],
              &force_before[6 * std::size_t(first)]);
  });
}

void book_contact_work(const Nodes& n, const std::vector<double>& force_before, double dt, Contact& c) {
  if (c.penalty_pa <= 0.0 || dt == 0.0) return;
  // The trapezoid of the forces before and after the step: the terms of the forces before in
  // pair order, then those after in the carrying pairs' (the sum's bits follow its order).
  c.work_J += for_each_busy_corner(c, [&](index_t first, index_t last, const ContactShares& carrying, double& work) {
    for (index_t p = first; p < last; ++p) work -= 0.5 * pair_power(n, c, &force_before[6 * std::size_t(p)], p) * dt;
    for (int k = 0; k < carrying.count; ++k)
      work -= 0.5 * pair_power(n, c, &c.pair_force[6 * std::size_t(carrying.pair[k])], carrying.pair[k]) * dt;
  });
}

void commit_friction_slip(const Nodes& n, const Triangles& tri, const Mechanics& mech, std::size_t material_count,
                          Contact& c) {
  if (c.penalty_pa <= 0.0) return;
  const double half_penalty = 0.5 * c.penalty_pa * mech.thickness_m;
  for_each_busy_corner(c, [&](index_t, index_t, const ContactShares& carrying, double&) {
    for (int k = 0; k < carrying.count; ++k) {
      const PairTraction t = pair_traction(n, tri, c, material_count, half_penalty, carrying, k);
      if (!t.sticks) c.pair_slip[carrying.pair[k]] = -t.tangential / t.stiffness;
    }
  });
}

}  // namespace ydry
