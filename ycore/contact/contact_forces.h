// Penalty contact with Coulomb friction between the surfaces of the solid: the force kernel
// (contact_forces.cpp; doc/physics.md "Contact and friction").
//
// Surfaces are the triangle edges with no joint (the mesh boundary, faces between two
// materials) and both faces of every broken joint. Each surface corner is tested against
// each surface edge near it (node to edge, and so both ways round: two faces pressed together
// push on each other symmetrically), except the edges of its own triangle and edges with an
// end in its own tie group, so corners still held by intact joints never touch; a corner that
// cannot move, on a straight side of its body (the rigid base's flat top), is only a receiver
// (contact_setup.cpp, fixed_flat_corners). A corner pressed a depth g into an edge is pushed
// out along the edge's normal by p_n t g / 2 per surface edge of its own, and the reaction
// goes to the edge's ends by the linear weights of its projection, so every contact conserves
// linear momentum. Friction is an elastic slip,
// stiffness that of the normal penalty, capped at mu f_n (mu per material pair); the slip is
// the corner's, and passes with its contact from one surface edge to the next. In a
// quasi-static run the slip slides only at equilibrium, as the joints' damage is committed
// only there (FrictionUpdate). The candidate pairs come from the broad phase
// (contact_search.h).
#pragma once

#include <cstddef>

#include "ycore/state/state.h"

namespace ydry {

// When the friction's elastic slip slides (is held at the cap mu f_n / stiffness).
enum class FrictionUpdate {
  // At every step it would pull harder than the cap: the history of a dynamic run.
  every_step,
  // Only by commit_friction_slip, once a quasi-static relaxation has reached equilibrium.
  // Between, the slip since the last equilibrium is a trial: the force is capped, the slip
  // not, so the friction is an elastic-perfectly-plastic spring whose stretch is measured
  // from the last equilibrium (the return mapping of a load step, as implicit codes do it).
  // The equilibrium found is then the minimum of a convex energy, whatever path the
  // relaxation took to it: a block moved too far by the extrapolated start, or by a
  // relaxation's overshoot, is pulled back to where the drying puts it instead of being held
  // where it was carried.
  at_equilibrium,
};

// Contact forces at the current positions into contact.pair_force (gathered per node through
// contact.gather_offset/gather_entry), the friction slip advanced by the relative velocity
// x dt, and the work done on the contacts over the step into contact.work_J. Runs the broad
// phase first when a surface corner has moved more than the buffer (build_contact_pairs).
// Reads the nodes, the triangles' materials, the thickness (mechanics) and the ownership
// table; contact.tan_friction is [material_count^2].
void contact_forces(const Nodes& nodes, const Triangles& triangles, const Mechanics& mechanics,
                    const Ownership& ownership, Contact& contact, std::size_t material_count, double dt,
                    FrictionUpdate friction = FrictionUpdate::every_step);

// Slides every friction slip past its cap back to it, the caps those of the current positions
// and velocities: the end of a quasi-static relaxation. The arguments are contact_forces'.
void commit_friction_slip(const Nodes& nodes, const Triangles& triangles, const Mechanics& mechanics,
                          const Ownership& ownership, Contact& contact, std::size_t material_count);

}  // namespace ydry
