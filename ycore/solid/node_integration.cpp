// The loop is written without branches (a prescribed component keeps its values by a select)
// over restrict pointers, so that it vectorises (ycore/solid/vector_clones.h); every free
// component's operations are the scalar ones, in the same order.
#include "ycore/solid/node_integration.h"

#include <algorithm>

#include "ycore/solid/vector_clones.h"

namespace ydry {
namespace {

// Nodes integrated at a time: the terms of the sum stay in the L1 cache.
constexpr std::size_t kMostNodesIntegrated = 2048;

// power[i - begin]: the free components' v_new . f of node i.
YDRY_AVX2_CLONE void integrate_range(std::size_t begin, std::size_t end, const std::uint8_t* __restrict constraint,
                                     const double* __restrict m, const double* __restrict fx,
                                     const double* __restrict fy, double* __restrict vx, double* __restrict vy,
                                     double* __restrict x, double* __restrict y, double* __restrict power,
                                     VelocityUpdate u) {
  const double push = u.step + u.steer, dt = u.step;
  for (std::size_t i = begin; i < end; ++i) {
    const bool free_x = !(constraint[i] & kFixX), free_y = !(constraint[i] & kFixY);
    const double vx_new = (u.keep * vx[i] + push * fx[i] / m[i]) * u.scale;
    const double vy_new = (u.keep * vy[i] + push * fy[i] / m[i]) * u.scale;
    x[i] = free_x ? x[i] + vx_new * dt : x[i];
    y[i] = free_y ? y[i] + vy_new * dt : y[i];
    vx[i] = free_x ? vx_new : vx[i];
    vy[i] = free_y ? vy_new : vy[i];
    power[i - begin] = (free_x ? vx_new * fx[i] : 0.0) + (free_y ? vy_new * fy[i] : 0.0);
  }
}

}  // namespace

void integrate_node_range(Nodes& n, std::size_t begin, std::size_t end, const VelocityUpdate& u, PowerLanes& sum) {
  double power[kMostNodesIntegrated];
  for (std::size_t first = begin, last; first < end; first = last) {
    last = std::min(end, first + kMostNodesIntegrated);
    integrate_range(first, last, n.constraint.data(), n.m.data(), n.fx.data(), n.fy.data(), n.vx.data(),
                    n.vy.data(), n.x.data(), n.y.data(), power, u);
    for (std::size_t i = first; i < last; ++i) sum.lane[i % 4] += power[i - first];
  }
}

}  // namespace ydry
