// The integration step of the quasi-static relaxation (ycore/relaxation.cpp): one
// pseudo-step of every free node component, v = scale (keep v + (step + steer) f / m),
// x += v step. Damped central differences and FIRE differ only in keep, steer and scale.
#pragma once

#include "ycore/state.h"

namespace ydry {

struct VelocityUpdate {
  double keep = 1.0, steer = 0.0, scale = 1.0, step = 0.0;
};

// Moves every component of nodes [begin, end) that is not prescribed (Nodes::constraint); the
// others keep their velocity and position. A relaxation step moves each triangle's nodes just
// before its element forces (element_forces, ycore/mechanics.h).
void integrate_node_range(State& state, std::size_t begin, std::size_t end, const VelocityUpdate& update);

}  // namespace ydry
