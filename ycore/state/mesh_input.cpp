#include "ycore/state/mesh_input.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "ycore/input/input_error.h"

namespace ydry {

void orient_counter_clockwise(MeshInput& m) {
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    index_t* v = &m.tri[3 * t];
    const double twice_area = (m.vx[v[1]] - m.vx[v[0]]) * (m.vy[v[2]] - m.vy[v[0]]) -
                              (m.vx[v[2]] - m.vx[v[0]]) * (m.vy[v[1]] - m.vy[v[0]]);
    if (twice_area == 0.0 || !std::isfinite(twice_area)) {
      std::ostringstream s;
      s << "triangle " << t << " (vertices " << v[0] << ", " << v[1] << ", " << v[2] << ") has "
        << (twice_area == 0.0 ? "zero area" : "an area too large for a double (coordinates near 1e154 or more)");
      throw InputError(s.str());
    }
    if (twice_area < 0) std::swap(v[1], v[2]);
  }
}

}  // namespace ydry
