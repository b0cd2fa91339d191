// One evaluation of the solid's forces: elements, joints and contact, gathered into the
// nodes' net force with the measures the equilibrium solvers steer by (relaxation.cpp,
// newton.cpp; doc/solver.md "Quasi-static equilibrium").
#pragma once

#include <cmath>
#include <vector>

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

// The net force of every node at the current positions into nodes.fx, fy: element forces and
// gravity, the substrate's, then the joints' (with their committed damage) and the contacts'
// (on the pairs and trial slips the phases before it left: update_contact_pairs,
// advance_friction_slip) gathered, with the measures. The velocities enter only the contacts'
// dashpot and the measures. Writes only forces: nodes.fx, fy, joints.force,
// contact.pair_force, and the stage clock. FIRE's measures (power, f.M^-1 f) only with
// fire_measures.
ForceMeasures compute_forces(State& s, bool fire_measures = false);

// The forces of the last evaluation, kept by explicit_step for the work booked over a step.
struct ForcesBefore {
  std::vector<double> joint, contact;
};

// One step of an explicit solver (relaxation.cpp), in the phases of doc/solver.md "One
// evaluation, in phases": the nodes moved by `move` (in the element kernel's pass, which sums
// v.f_previous of the Rayleigh numerator where it reads f_previous: so no node keeps its force
// of the step before, 8 % of the bytes a step moves on a large mesh: bench/RESULTS.md), or
// without it the step of dt the nodes have already made at their velocities; the contact pairs
// updated; the friction slip advanced over dt; the forces (compute_forces); the work done on
// the joints and contacts over dt booked (book_joint_step_work, book_contact_work), and with
// FrictionUpdate::every_step the slip committed (commit_friction_slip). `before` is scratch
// the caller keeps from one step to the next.
ForceMeasures explicit_step(State& s, const VelocityUpdate* move, double dt, FrictionUpdate friction,
                            bool fire_measures, ForcesBefore& before);

}  // namespace ydry
