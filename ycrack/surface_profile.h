// The profile of a named surface (the soil's top) for surface.csv: the displacement of each
// of its points, with the two sides of every crack that reaches it told apart (paper Fig. 22).
#pragma once

#include <string>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

struct SurfacePoint {
  double x0_m = 0, y0_m = 0;  // initial position
  double ux_m = 0, uy_m = 0;  // displacement: the mean of the point's corners on the surface
  int segment = 0;            // the unbroken stretch of surface it lies on
};

// The points of the surface made of `edges` (corner pairs, as State::boundary_edges holds
// them), from the nodes' initial and current positions. A point is a mesh vertex of the
// surface, or one side of it where a crack reaches it: the vertex's surface corners that
// nodes.tie_group keeps together (tie_corners must be up to date). Surface edges join points
// into segments, so the two sides of a crack lie on different segments. Ordered by x0, then
// y0, then segment; segments are numbered in the order of their first point, so at a crack
// the left side (lower segment) comes first.
std::vector<SurfacePoint> surface_profile(const Nodes& nodes, const std::vector<index_t>& edges);

extern const char* const kSurfaceCsvHeader;

// The rows of surface.csv at time_s, one per point: time_s, x0_m, y0_m, ux_m, uy_m, segment.
std::string surface_csv_rows(double time_s, const std::vector<SurfacePoint>& points);

}  // namespace ydry
