// The joints' damage history (joint_damage.cpp; doc/physics.md "Joints").
#pragma once

#include <cstddef>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// Commits each joint point's damage (maximum over time) at the current positions and breaks,
// for good, every joint with two of its three points at D = 1: writes joints.damage and
// joints.broken. Returns the number of joints that broke. Called at each equilibrium of a
// quasi-static run and at every step of a dynamic one (doc/solver.md "Quasi-static
// equilibrium", "Dynamic integration").
std::size_t commit_joint_damage(const Nodes& nodes, const Ownership& ownership,
                                const std::vector<MaterialModel>& materials, Joints& joints);

}  // namespace ydry
