// The joints' work, booked by phases of their own (doc/solver.md "One evaluation, in phases"):
// over an explicit step from the forces at its two ends, or along the straight path between two
// configurations once a Newton relaxation ends.
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

// Adds to joints.work the work done on each intact joint of a material with mechanics over a
// step of dt at the nodes' velocities: the trapezoid of force_before (its forces before the
// step) and joints.force (after it), exact for a linear spring, so that a vibrating joint books
// no spurious work.
void book_joint_step_work(const Nodes& nodes, const std::vector<MaterialModel>& materials,
                          const std::vector<double>& force_before, double dt, Joints& joints);

}  // namespace ydry
