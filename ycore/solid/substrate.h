// The substrate under a layer seen in plan view (doc/physics.md "Plan view"): an elastic shear
// traction on every node over its tributary area, capped at adhesion plus friction under the
// layer's weight, whose slide is committed at equilibrium as the contact friction's is.
#pragma once

#include <Eigen/SparseCore>

#include <vector>

#include "ycore/input/deck.h"
#include "ycore/solid/tangent.h"
#include "ycore/state/state.h"

namespace ydry {

// The substrate of a plan-view deck (empty otherwise): each node of a deformable material
// carries a third of its triangle's area A, so k = k_b A and cap = (c_b + tan(phi_b) rho g h) A,
// k_b the deck's or, where it gives none, G / h of the node's material (the layer's own shear
// through its thickness; doc/physics.md "Plan view").
void init_substrate(const Deck& deck, const Triangles& triangles, const std::vector<MaterialModel>& materials,
                    std::size_t node_count, Substrate& substrate);

// Adds each node's substrate traction to nodes.fx, fy: -k e with e = x - x0 - slide, its
// length capped at `cap` (the trial of a return mapping, not kept). Reads the positions.
void add_substrate_forces(const Substrate& substrate, const Ownership& ownership, Nodes& nodes);

// Slides every node whose traction passes its cap back to the cap: the end of a quasi-static
// relaxation, or every step of a dynamic run. Books the work each slide dissipates, the cap
// times the slide's length, in substrate.slide_work_J (exact where a node slides along a line).
void commit_substrate_slide(const Nodes& nodes, const Ownership& ownership, Substrate& substrate);

// The elastic energy the substrate's tractions store at the nodes' positions: 1/2 k |e|^2 with
// the stretch e capped at cap / k.
double substrate_elastic_energy(const Nodes& nodes, const Substrate& substrate);

// -d(substrate forces)/d(coordinates) over the free components: k I where the traction is within
// its cap, (cap / |e|)(I - e e^T / |e|^2) where it slides.
Eigen::SparseMatrix<double> substrate_tangent(const Nodes& nodes, const Substrate& substrate, const FreeComponents& free);

}  // namespace ydry
