// The stable step of the explicit integration, and the node masses of a quasi-static run
// (stable_step.cpp; doc/solver.md "Quasi-static equilibrium" and "Dynamic integration").
//
// Each function reads the initial geometry, constraints and joint slots of the nodes, the
// triangles' materials and areas, the materials' constants, the thickness (mechanics) and the
// contact penalty.
#pragma once

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Per node, an upper bound of the row sum of its element, joint and contact stiffness, N/m
// (Gershgorin); 0 for a node that is fixed in both directions or not mechanical.
std::vector<double> node_stiffness_bound(const Nodes& nodes, const Triangles& triangles, const Joints& joints,
                                         const Mechanics& mechanics, const Contact& contact, const Substrate& substrate,
                                         const std::vector<MaterialModel>& materials);

// The largest stable step of the central-difference integration times `safety`: per node,
// omega^2 <= node_stiffness_bound / nodes.m.
double stable_mechanics_step(const Nodes& nodes, const Triangles& triangles, const Joints& joints, const Mechanics& mechanics,
                             const Contact& contact, const Substrate& substrate, const std::vector<MaterialModel>& materials,
                             double safety);

// Quasi-static runs (solver.node_mass_scaling): only the equilibrium matters, so the inertia
// of each node is free. Nodes stiffer for their mass than the median node (small elements at
// a refined boundary, notch teeth) are made heavier until they are stable at the median node's
// step, so the few smallest elements do not set the step of all; writes nodes.m. The softer
// nodes are not made lighter (Underwood's fictitious masses): that saves 12 % of the Peron
// steps before cracking, but while relaxations stop at their cap during cracking the crack
// pattern depends on the pseudo-dynamics, and it changes which late cracks open from the top.
void scale_node_masses_to_common_step(const Triangles& triangles, const Joints& joints, const Mechanics& mechanics,
                                      const Contact& contact, const Substrate& substrate,
                                      const std::vector<MaterialModel>& materials, Nodes& nodes);

}  // namespace ydry
