// The integration step of the quasi-static relaxation (ycore/solid/relaxation.cpp): one
// pseudo-step of every free node component, v = scale (keep v + (step + steer) f / m),
// x += v step. Damped central differences and FIRE differ only in keep, steer and scale.
#pragma once

#include "ycore/state/state.h"

namespace ydry {

struct VelocityUpdate {
  double keep = 1.0, steer = 0.0, scale = 1.0, step = 0.0;
};

// A sum over nodes in four running sums, node i's term into lane i % 4: the additions do not
// wait on each other, and nodes added in ascending order give the same bits however the
// range was cut into calls.
struct PowerLanes {
  double lane[4] = {0.0, 0.0, 0.0, 0.0};
  double total() const { return (lane[0] + lane[1]) + (lane[2] + lane[3]); }
};

// Moves every component of nodes [begin, end) that is not prescribed (Nodes::constraint); the
// others keep their velocity and position. Adds to `power` each moved component's new velocity
// times the force that made it, v_new . f: the adaptive damping's Rayleigh quotient needs it
// (ycore/solid/relaxation.cpp), and here the force is read anyway. A relaxation step moves each
// triangle's nodes just before its element forces (ycore/solid/element_forces.h).
void integrate_node_range(Nodes& nodes, std::size_t begin, std::size_t end, const VelocityUpdate& update,
                          PowerLanes& power);

}  // namespace ydry
