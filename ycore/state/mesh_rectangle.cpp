// The built-in structured rectangle mesh.
#include "ycore/state/mesh_rectangle.h"

#include <algorithm>
#include <cmath>

#include "ycore/input/mesh_size.h"

namespace ydry {

MeshInput generate_rectangle(double lx, double ly, double element_size,
                             const std::string& pattern, const std::string& material) {
  const bool cross = pattern == "cross";
  const auto cells = rectangle_cells(lx, ly, element_size);  // within kMaxTriangles: the deck checks
  const index_t nx = static_cast<index_t>(cells[0]), ny = static_cast<index_t>(cells[1]);
  MeshInput m;
  const auto corner = [&](index_t i, index_t j) { return j * (nx + 1) + i; };
  for (index_t j = 0; j <= ny; ++j)
    for (index_t i = 0; i <= nx; ++i) {
      m.vx.push_back(lx * i / nx);
      m.vy.push_back(ly * j / ny);
    }
  const auto add = [&](index_t a, index_t b, index_t c) {
    m.tri.insert(m.tri.end(), {a, b, c});
    m.tri_material.push_back(material);
  };
  for (index_t j = 0; j < ny; ++j)
    for (index_t i = 0; i < nx; ++i) {
      const index_t sw = corner(i, j), se = corner(i + 1, j), nw = corner(i, j + 1), ne = corner(i + 1, j + 1);
      if (cross) {
        const index_t c = static_cast<index_t>(m.vx.size());
        m.vx.push_back(lx * (i + 0.5) / nx);
        m.vy.push_back(ly * (j + 0.5) / ny);
        add(sw, se, c), add(se, ne, c), add(ne, nw, c), add(nw, sw, c);
      } else if (pattern == "right") {  // diagonal sw-ne
        add(sw, se, ne), add(sw, ne, nw);
      } else {                          // "left": diagonal se-nw
        add(sw, se, nw), add(se, ne, nw);
      }
    }
  auto& left = m.boundaries["left"];
  auto& right = m.boundaries["right"];
  for (index_t j = 0; j < ny; ++j) {
    left.insert(left.end(), {corner(0, j), corner(0, j + 1)});
    right.insert(right.end(), {corner(nx, j), corner(nx, j + 1)});
  }
  auto& bottom = m.boundaries["bottom"];
  auto& top = m.boundaries["top"];
  for (index_t i = 0; i < nx; ++i) {
    bottom.insert(bottom.end(), {corner(i, 0), corner(i + 1, 0)});
    top.insert(top.end(), {corner(i, ny), corner(i + 1, ny)});
  }
  return m;
}

}  // namespace ydry
