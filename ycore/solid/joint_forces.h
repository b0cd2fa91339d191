// The joint kernel: the forces of the cohesive joints on their nodes (joint_forces.cpp;
// doc/physics.md "Joints"); the work done on them is booked by joint_work.h.
#pragma once

#include <cstddef>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Joints per pass of the joint kernel's vectorised pre-peak law (joint_forces.cpp).
constexpr int kJointChunk = 256;

// The joints' forces at the nodes' positions with their committed damage, into `force`
// (joints.force: [8 * joints]). Broken joints carry nothing: their faces meet through contact
// (ycore/contact/contact_forces.h). Only the joints of a material with mechanics are written
// (Joints::mechanical_runs); the others' forces are 0 for good. Reads the mechanics' thickness.
void joint_forces(const Nodes& nodes, const Mechanics& mechanics, const Ownership& ownership,
                  const std::vector<MaterialModel>& materials, const Joints& joints, std::vector<double>& force);

// The forces of joint j on its nodes 0..3 (x, y) with the full traction law at its three
// points, as joint_forces stores them: zero for a broken joint.
void joint_nodal_forces(const Nodes& nodes, const Joints& joints, const Mechanics& mechanics,
                        const std::vector<MaterialModel>& materials, std::size_t j, double out[8]);
// The same with its nodes 0..3 at x, y (the equilibrium solver's tangent, tangent.h). With
// held_compression, the mode II strength c + sigma_n tan(phi) of point p (Fig. 2b) takes its
// compression sigma_n (Pa) from held_compression[p] instead of from x, y.
void joint_nodal_forces_at(const Joints& joints, const Mechanics& mechanics,
                           const std::vector<MaterialModel>& materials, std::size_t j, const double x[4],
                           const double y[4], double out[8], const double* held_compression = nullptr);

// The compression (Pa, 0 where open) at joint j's three points with its nodes 0..3 at x, y.
void joint_point_compressions(const Joints& joints, const std::vector<MaterialModel>& materials, std::size_t j,
                              const double x[4], const double y[4], double compression[3]);

}  // namespace ydry
