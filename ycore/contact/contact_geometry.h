// The narrow phase of contact (contact_forces.h): a surface corner against one surface edge.
#pragma once

#include <cmath>

#include "ycore/state/state.h"

namespace ydry {

// A corner against one edge: where it projects (0..1 from the edge's first corner) and how
// far it lies outside (negative: inside the edge's triangle), with the edge's unit tangent.
struct EdgeProjection {
  double along = 0, gap = 0, length = 0, tx = 0, ty = 0;
};

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

}  // namespace ydry
