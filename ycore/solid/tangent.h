// The tangent stiffness of the solid for the Newton equilibrium solver (newton.cpp;
// doc/solver.md "Quasi-static equilibrium").
#pragma once

#include <Eigen/SparseCore>

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// The unknowns of the equilibrium: every force component of a node of a mechanical material
// that is not prescribed (fixed or driven), numbered in node order, x before y.
struct FreeComponents {
  std::vector<index_t> unknown;    // [2 * nodes]: 2 i + axis -> its unknown, kNoIndex if none
  std::vector<index_t> component;  // [unknowns]: unknown -> 2 i + axis
  std::size_t size() const { return component.size(); }
};
FreeComponents free_components(const Nodes& nodes, const Triangles& triangles,
                               const std::vector<MaterialModel>& materials);

// How the tangent takes the rise of a joint point's mode II strength c + sigma_n tan(phi) with
// its compression (Fig. 2b; doc/solver.md "The joints' friction in the tangent"):
// - held: the strength held at the compression of the positions given, as a friction cap
//   is between Newton steps (no saddle where a compressed point slides on its plateau);
// - derived: differentiated with the rest and symmetrised.
enum class JointFrictionTangent { held, derived };

// K = -df/dx of the element and intact-joint forces on the free components, symmetrised, by
// central differences of each triangle's and joint's own forces in its own coordinates, so
// that it is the derivative of exactly the forces the kernels compute, on every branch of the
// joint law, the joints' friction taken as `friction` says. The same bits on any number of
// threads.
Eigen::SparseMatrix<double> tangent_stiffness(const Nodes& nodes, const Triangles& triangles, const Joints& joints,
                                              const Mechanics& mechanics, const std::vector<MaterialModel>& materials,
                                              const FreeComponents& free, JointFrictionTangent friction);

}  // namespace ydry
