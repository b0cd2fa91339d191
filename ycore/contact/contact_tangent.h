// The contacts' stiffness for the Newton equilibrium solver (ycore/solid/tangent.h;
// doc/physics.md "Contact and friction").
#pragma once

#include <Eigen/SparseCore>

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// K = -df/dx of the pair each corner presses through (contact_forces made the forces at these
// positions), or of the first edge it lies on without pressing,
// linearised about the edge as it lies: the penalty p B B^T along the edge's normal and, for
// a pair that sticks, along its tangent (the elastic slip), B the corner's motion less the
// edge's at the projection. A sliding pair's friction, which follows the normal force, and the
// turn of the edge are left out: the line search of the solver takes up what they change.
// Appends the entries between unknowns (`unknown`: [2 * nodes] -> unknown or kNoIndex).
void add_contact_tangent(const Nodes& nodes, const Triangles& triangles, const Mechanics& mechanics,
                         const Contact& contact, const std::vector<index_t>& unknown,
                         std::vector<Eigen::Triplet<double>>& entries);

}  // namespace ydry
