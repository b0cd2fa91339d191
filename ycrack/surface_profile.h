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
// them). A point is a mesh vertex of the surface, or one side of it where a crack reaches it:
// the vertex's surface corners that nodes.tie_group keeps together (tie_corners must be up to
// date). Surface edges join points into segments, so the two sides of a crack lie on
// different segments. Ordered by x0, then y0, then segment; segments are numbered in the
// order of their first point, so at a crack the left side (lower segment) comes first.
std::vector<SurfacePoint> surface_profile(const State& state, const std::vector<index_t>& edges);

struct SurfaceCsv {
  std::string path;
  std::string rows;  // every row so far, as written
};

// Appends a row per point at time_s and rewrites the whole file atomically, header first:
// time_s, x0_m, y0_m, ux_m, uy_m, segment.
void append_surface_csv(SurfaceCsv& csv, double time_s, const std::vector<SurfacePoint>& points);

// Writes the file with the rows so far (a restart's).
void write_surface_csv(const SurfaceCsv& csv);

}  // namespace ydry
