// The narrow phase of contact (contact_forces.h): a surface corner against one surface edge.
#pragma once

#include <algorithm>
#include <cmath>

#include "ycore/state/state.h"

namespace ydry {

// The penalty stiffness of corner i's contact, N/m: half_penalty = p_n t / 2 per surface edge
// of its own (contact_forces.h); the share of each edge that carries it multiplies it.
inline double corner_stiffness(const Contact& c, double half_penalty, index_t i) {
  return half_penalty * (c.is_surface_edge[i] + c.is_surface_edge[previous_corner(i)]);
}

// mu of corner i's material against edge e's (contact.tan_friction is [material_count^2]).
inline double friction_coefficient(const Contact& c, const Triangles& tri, std::size_t material_count, index_t i, index_t e) {
  return c.tan_friction[tri.material[triangle_of(i)] * material_count + tri.material[triangle_of(e)]];
}

// Whether a contact's friction sticks: the pull of its elastic slip, -stiffness x slip, is
// within the cap mu f_n (doc/physics.md "Contact and friction"). The force kernel slides the
// slip where it does not; the Newton links give it its spring where it does.
inline bool friction_sticks(double slip_pull, double cap) { return !(std::fabs(slip_pull) > cap); }

// Corner i against edge e -> next_corner(e) of a CCW triangle.
inline EdgeProjection project(const Nodes& n, index_t i, index_t e) {
  const index_t f = next_corner(e);
  EdgeProjection p;
  const double ex = n.x[f] - n.x[e], ey = n.y[f] - n.y[e];
  p.length = std::sqrt(ex * ex + ey * ey);
  p.tx = ex / p.length, p.ty = ey / p.length;
  const double dx = n.x[i] - n.x[e], dy = n.y[i] - n.y[e];
  p.along = (dx * p.tx + dy * p.ty) / p.length;
  p.gap = dx * p.ty - dy * p.tx;  // along the outward normal (ty, -tx) of a CCW edge
  return p;
}

// True only where project(n, i, e).gap > 0: the corner lies outside the edge's line by more
// than project()'s round-off. Its gap is the cross product below over the edge's length, both
// within a few units in the last place of |dx ey| + |dy ex| of exact; the margin here is 45 of
// them. Decided without project()'s square root and divisions; a corner on or inside the
// line, or too near it to tell, gets false.
inline bool clearly_outside(const Nodes& n, index_t i, index_t e) {
  const index_t f = next_corner(e);
  const double ex = n.x[f] - n.x[e], ey = n.y[f] - n.y[e];
  const double dx = n.x[i] - n.x[e], dy = n.y[i] - n.y[e];
  const double cross = dx * ey - dy * ex;
  return cross > 1e-14 * (std::fabs(dx * ey) + std::fabs(dy * ex));
}

// The share of the contact a corner projecting at `along` gives an edge: 1 on the edge but
// within kEndTaper of its length of an end, falling linearly to 0 at kEndTaper past it. A
// corner passing from an edge to the next across their junction so hands its force over
// without a jump (doc/physics.md "Contact and friction").
constexpr double kEndTaper = 0.05;
inline double end_weight(double along) {
  return std::clamp(std::min(along + kEndTaper, 1.0 + kEndTaper - along) / (2.0 * kEndTaper), 0.0, 1.0);
}

// Faces the edge, as contact sees it: the corner projects onto the edge (or its end's taper)
// and lies less than `reach` outside it (0: inside, in contact) and less than half the edge's
// length deep (deeper, it is a corner of the far side of a thin body), and one of its own
// surface edges faces the edge within 80 degrees of head-on. (A corner of a flat surface that a block's
// corner slides over lies, by the penalty's give, just inside the block's side too; its own
// surface is at right angles to that side, and the block's bottom, which it does face,
// carries the contact.)
inline bool faces_edge(const Nodes& n, const Contact& c, index_t i, const EdgeProjection& p, double reach) {
  constexpr double kFacing = 0.17;  // cos 80 degrees
  if (!(end_weight(p.along) > 0.0 && p.gap < reach && p.gap > -0.5 * p.length)) return false;
  for (const index_t e : {previous_corner(i), i}) {
    if (!c.is_surface_edge[e]) continue;
    const index_t f = next_corner(e);
    const double ex = n.x[f] - n.x[e], ey = n.y[f] - n.y[e];
    // Own outward normal (ey, -ex) / |e| against the edge's (ty, -tx).
    if (ey * p.ty + ex * p.tx < -kFacing * std::sqrt(ex * ex + ey * ey)) return true;
  }
  return false;
}

// The pairs that carry a corner's contact and their shares (ContactShares, state.h): of the
// edges it touches, the one it lies least deep in (the surface it came through); where the
// corner is within the taper of that edge's end, also the least deep other edge it touches
// nearer that edge's opposite end (the next edge across a junction). Shares over 1 together
// are scaled to 1.
inline ContactShares contact_shares(const Nodes& n, const Contact& c, index_t i, index_t first, index_t last) {
  ContactShares s;
  for (index_t p = first; p < last; ++p) {
    const EdgeProjection q = project(n, i, c.pair_edge[p]);
    if (faces_edge(n, c, i, q, 0.0) && (s.count == 0 || q.gap > s.at[0].gap)) s.count = 1, s.pair[0] = p, s.at[0] = q;
  }
  if (s.count == 0) return s;
  s.weight[0] = end_weight(s.at[0].along);
  if (s.weight[0] == 1.0) return s;
  const bool near_start = s.at[0].along < 0.5;
  for (index_t p = first; p < last; ++p) {
    if (p == s.pair[0]) continue;
    const EdgeProjection q = project(n, i, c.pair_edge[p]);
    if ((q.along < 0.5) != near_start && faces_edge(n, c, i, q, 0.0) &&
        (s.count == 1 || q.gap > s.at[1].gap))
      s.count = 2, s.pair[1] = p, s.at[1] = q;
  }
  if (s.count == 2) {
    s.weight[1] = end_weight(s.at[1].along);
    const double total = s.weight[0] + s.weight[1];
    if (total > 1.0) s.weight[0] /= total, s.weight[1] /= total;
  }
  return s;
}

}  // namespace ydry
