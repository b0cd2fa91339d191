// Triangles renumbered along a Hilbert curve through their centroids (doc/threading.md
// "Ownership slots").
//
// A mesh generator's numbering need not be local: in the Peron mesh from Gmsh, the two
// triangles of a joint lie a median 835 places apart. Each thread owns a contiguous range of
// triangles (ycore/state/ownership.h), so with such a numbering a quarter of the joints tie one
// thread's triangles to the other's, and their node and force data cross between the cores'
// caches at every step. Along a Hilbert curve, triangles close in the numbering are close in
// space, and a contiguous range is a compact patch of the mesh.
#include <algorithm>
#include <cstdint>
#include <numeric>

#include "ycore/state/mesh_order.h"

namespace ydry {
namespace {

constexpr int kHilbertOrder = 16;  // a 65536 x 65536 grid over the mesh's bounding square

// Distance along the Hilbert curve of order kHilbertOrder to cell (x, y): the cell's
// quadrant at each scale from the largest down, with the quadrant rotated so that the curve
// enters and leaves it as its neighbours need.
std::uint64_t hilbert_distance(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << (kHilbertOrder - 1); s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant (only the bits below s are read from here on)
      if (rx == 1) x ^= s - 1, y ^= s - 1;
      std::swap(x, y);
    }
  }
  return d;
}

}  // namespace

void order_triangles_along_hilbert_curve(MeshInput& mesh) {
  const std::size_t nt = mesh.triangle_count();
  if (nt == 0) return;
  const auto [x_min, x_max] = std::minmax_element(mesh.vx.begin(), mesh.vx.end());
  const auto [y_min, y_max] = std::minmax_element(mesh.vy.begin(), mesh.vy.end());
  const double side = std::max(*x_max - *x_min, *y_max - *y_min);
  const double cells = double((1u << kHilbertOrder) - 1);
  const double scale = side > 0.0 ? cells / side : 0.0;
  std::vector<std::uint64_t> key(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    double cx = 0, cy = 0;
    for (int a = 0; a < 3; ++a) cx += mesh.vx[mesh.tri[3 * t + a]], cy += mesh.vy[mesh.tri[3 * t + a]];
    const auto cell = [&](double c, double lo) {
      return std::uint32_t(std::clamp((c / 3.0 - lo) * scale, 0.0, cells));
    };
    key[t] = hilbert_distance(cell(cx, *x_min), cell(cy, *y_min));
  }
  std::vector<std::size_t> order(nt);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  std::vector<index_t> tri(3 * nt);
  std::vector<std::string> material(nt);
  for (std::size_t k = 0; k < nt; ++k) {
    for (int a = 0; a < 3; ++a) tri[3 * k + a] = mesh.tri[3 * order[k] + a];
    material[k] = std::move(mesh.tri_material[order[k]]);
  }
  mesh.tri = std::move(tri);
  mesh.tri_material = std::move(material);
}

}  // namespace ydry
