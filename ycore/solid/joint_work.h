// The joints' work booked between two configurations (doc/solver.md "Quasi-static
// equilibrium"): a phase of its own, called by the equilibrium solvers once a relaxation ends.
#pragma once

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Adds to joints.work the work done on each intact joint of a material with mechanics along the
// straight path of its nodes from (x_from, y_from) to where they are, by 8-point
// Gauss-Legendre quadrature of the joint's forces with its committed damage held. Reads the
// nodes' positions, the thickness and the materials.
void book_joint_work(const Nodes& nodes, const Mechanics& mechanics, const std::vector<MaterialModel>& materials,
                     const std::vector<double>& x_from, const std::vector<double>& y_from, Joints& joints);

}  // namespace ydry
