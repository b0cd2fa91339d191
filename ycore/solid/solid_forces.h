// One evaluation of the solid's forces: elements, joints and contact, gathered into the
// nodes' net force with the measures the equilibrium solvers steer by (relaxation.cpp,
// newton.cpp; doc/solver.md "Quasi-static equilibrium").
#pragma once

#include <cmath>

#include "ycore/contact/contact_forces.h"
#include "ycore/solid/node_integration.h"
#include "ycore/state/state.h"

namespace ydry {

struct ForceMeasures {
  double net2 = 0;       // |net force|^2 over free components
  double reference2 = 0; // |element forces and gravity|^2 over all nodes
  double rayleigh_numerator = 0; // -v.(f - f_previous) over free components, v the last step's
                                 // velocity and f_previous the force that made it
  double twice_kinetic = 0;      // v.M v over free components
  double power = 0;              // f.v over free components
  double force2_over_mass = 0;   // f.M^-1 f over free components
  double ratio() const { return reference2 > 0.0 ? std::sqrt(net2 / reference2) : (net2 > 0.0 ? INFINITY : 0.0); }
};

// The net force of every node into nodes.fx, fy: element forces and gravity, then the joint and
// contact forces gathered, with the measures. `dt` is the pseudo-step the joints and contacts
// book their work over (0: none). A phase: it writes the nodes' forces (and with move_first
// their positions and velocities), the joints' forces and work, the contact's pairs, forces,
// slips and work, and the stage clock.
// FIRE's measures (power, f.M^-1 f) only with fire_measures. With move_first, the nodes are
// first moved by that pseudo-step (in the element kernel's pass), which sums v.f_previous of
// the Rayleigh numerator where it reads f_previous: so no node keeps its force of the step
// before (8 % of the bytes a step moves on a large mesh: bench/RESULTS.md).
ForceMeasures compute_forces(State& s, double dt, FrictionUpdate friction, bool fire_measures = false,
                             const VelocityUpdate* move_first = nullptr);

}  // namespace ydry
