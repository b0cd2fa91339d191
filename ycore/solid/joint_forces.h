// The joint kernel: the forces of the cohesive joints on their nodes and the work done on them
// (joint_forces.cpp; doc/physics.md "Joints").
#pragma once

#include <cstddef>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Joints per pass of the joint kernel's vectorised pre-peak law (joint_forces.cpp).
constexpr int kJointChunk = 256;

// Joint forces into joints.force, and the work done on them over the last step (the
// trapezoid of the forces before and after it, times velocities x dt) into joints.work.
// Broken joints carry nothing: their faces meet through contact (ycore/contact/contact_forces.h).
// Reads the mechanics' thickness.
void joint_forces(const Nodes& nodes, const Mechanics& mechanics, const Ownership& ownership,
                  const std::vector<MaterialModel>& materials, Joints& joints, double dt);

// The forces of joint j on its nodes 0..3 (x, y) with the full traction law at its three
// points, as joint_forces stores them: zero for a broken joint.
void joint_nodal_forces(const Nodes& nodes, const Joints& joints, const Mechanics& mechanics,
                        const std::vector<MaterialModel>& materials, std::size_t j, double out[8]);
// The same with its nodes 0..3 at x, y (the equilibrium solver's tangent, tangent.h).
void joint_nodal_forces_at(const Joints& joints, const Mechanics& mechanics,
                           const std::vector<MaterialModel>& materials, std::size_t j, const double x[4],
                           const double y[4], double out[8]);

}  // namespace ydry
