#include "ycrack/surface_profile.h"

#include <algorithm>
#include <numeric>

#include "ycore/output/output_files.h"
#include "ycrack/union_find.h"

namespace ydry {

std::vector<SurfacePoint> surface_profile(const Nodes& n, const std::vector<index_t>& edges) {
  std::vector<index_t> corners(edges);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  // One point per tie group: corners tied by intact joints are one material point, so a
  // vertex is one point until a broken joint separates its two surface corners.
  std::vector<index_t> groups(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k) groups[k] = n.tie_group[corners[k]];
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  const auto point_of = [&](index_t corner) {
    return index_t(std::lower_bound(groups.begin(), groups.end(), n.tie_group[corner]) - groups.begin());
  };

  std::vector<SurfacePoint> points(groups.size());
  std::vector<int> count(groups.size(), 0);
  for (const index_t c : corners) {
    SurfacePoint& p = points[point_of(c)];
    p.x0_m = n.x0[c];
    p.y0_m = n.y0[c];
    p.ux_m += n.x[c] - n.x0[c];
    p.uy_m += n.y[c] - n.y0[c];
    ++count[point_of(c)];
  }
  std::vector<index_t> parent(points.size());
  std::iota(parent.begin(), parent.end(), index_t(0));
  for (std::size_t e = 0; e < edges.size(); e += 2) unite(parent, point_of(edges[e]), point_of(edges[e + 1]));

  std::vector<index_t> order(points.size());
  std::iota(order.begin(), order.end(), index_t(0));
  const auto by_position = [&](index_t a, index_t b) {
    return points[a].x0_m != points[b].x0_m ? points[a].x0_m < points[b].x0_m : points[a].y0_m < points[b].y0_m;
  };
  std::stable_sort(order.begin(), order.end(), by_position);
  std::vector<int> segment_of_root(points.size(), -1);
  int segments = 0;
  for (const index_t k : order) {
    int& segment = segment_of_root[find_root(parent, k)];
    if (segment < 0) segment = segments++;
    points[k].segment = segment;
    points[k].ux_m /= count[k];
    points[k].uy_m /= count[k];
  }
  std::stable_sort(order.begin(), order.end(), [&](index_t a, index_t b) {
    return by_position(a, b) || (!by_position(b, a) && points[a].segment < points[b].segment);
  });
  std::vector<SurfacePoint> sorted;
  sorted.reserve(points.size());
  for (const index_t k : order) sorted.push_back(points[k]);
  return sorted;
}

const char* const kSurfaceCsvHeader = "time_s,x0_m,y0_m,ux_m,uy_m,segment";

std::string surface_csv_rows(double time_s, const std::vector<SurfacePoint>& points) {
  std::string rows;
  for (const SurfacePoint& p : points)
    rows += format_double(time_s) + "," + format_double(p.x0_m) + "," + format_double(p.y0_m) + "," +
            format_double(p.ux_m) + "," + format_double(p.uy_m) + "," + std::to_string(p.segment) + "\n";
  return rows;
}

}  // namespace ydry
