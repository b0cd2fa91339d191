// Penalty contact with Coulomb friction between the surfaces of the solid: its phases
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
#include <vector>

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

// The phases of contact in one evaluation (doc/solver.md "One evaluation, in phases"), in the
// order the solvers call them. Each reads the nodes' positions (and velocities where it says),
// the triangles' materials, the thickness (mechanics) and contact.tan_friction,
// [material_count^2].

// The pairs at the current positions: the broad phase where a surface corner has moved more
// than the buffer since the last (build_contact_pairs; the pairs that continue keep their slip
// and last force), then each corner's carrying pairs (contact.corner_busy, corner_shares),
// which the phases below read. A corner clearly outside every edge it is paired with, with no
// force or slip on its pairs (seven in ten of the Peron deck's), is idle: no phase takes it.
void update_contact_pairs(const Nodes& nodes, const Ownership& ownership, Contact& contact);

// The pair forces book_contact_work reads (those of the corners not idle) into force_before,
// before the forces change.
void keep_contact_forces(const Contact& contact, std::vector<double>& force_before);

// The trial slip along the solver's path: each carrying pair's slip stretched by the corner's
// relative tangential velocity x dt, and handed over from pair to pair with the contact.
void advance_friction_slip(const Nodes& nodes, double dt, Contact& contact);

// The contact forces at the current positions, velocities (the dashpot) and slips into
// pair_force (contact.pair_force; gathered per node through contact.gather_offset and
// gather_entry). The friction's pull is capped at mu f_n; the slip is not changed.
void contact_forces(const Nodes& nodes, const Triangles& triangles, const Mechanics& mechanics,
                    const Contact& contact, std::size_t material_count, std::vector<double>& pair_force);

// The work done on the contacts over a step of dt at the nodes' velocities, the trapezoid of
// force_before (keep_contact_forces) and contact.pair_force, into contact.work_J.
void book_contact_work(const Nodes& nodes, const std::vector<double>& force_before, double dt, Contact& contact);

// Slides every friction slip past its cap back to it, the caps those of the current positions
// and velocities: at the end of a quasi-static relaxation, or after every step of a dynamic
// run (FrictionUpdate).
void commit_friction_slip(const Nodes& nodes, const Triangles& triangles, const Mechanics& mechanics,
                          std::size_t material_count, Contact& contact);

}  // namespace ydry
