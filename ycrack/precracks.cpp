#include "ycrack/precracks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ycore/input/input_error.h"

namespace ydry {
namespace {

// Distance from (px, py) to the segment a-b.
double distance_to_segment(double px, double py, const CrackSegmentDeck& c) {
  const double dx = c.to[0] - c.from[0], dy = c.to[1] - c.from[1];
  const double t = std::clamp(((px - c.from[0]) * dx + (py - c.from[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(px - c.from[0] - t * dx, py - c.from[1] - t * dy);
}

}  // namespace

void break_joints_along_cracks(const Nodes& n, const std::vector<CrackSegmentDeck>& cracks, Joints& joints) {
  for (const CrackSegmentDeck& crack : cracks) {
    const double length = std::hypot(crack.to[0] - crack.from[0], crack.to[1] - crack.from[1]);
    double covered = 0.0;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const index_t a = joints.node[4 * j], b = joints.node[4 * j + 1];
      const double h = std::hypot(n.x0[b] - n.x0[a], n.y0[b] - n.y0[a]);
      const double tolerance = 1e-6 * h;
      if (distance_to_segment(n.x0[a], n.y0[a], crack) > tolerance ||
          distance_to_segment(n.x0[b], n.y0[b], crack) > tolerance)
        continue;
      covered += h;
      joints.broken[j] = 1;
    }
    if (covered < (1.0 - 1e-6) * length) {
      std::ostringstream msg;
      msg << crack.where << ": the segment does not follow jointed mesh edges over its length (" << covered
          << " of " << length << " m found); put its ends on mesh vertices inside one material";
      throw InputError(msg.str());
    }
  }
}

}  // namespace ydry
