// The contacts linearised for the Newton equilibrium solver: a link for each pair that carries
// a corner's contact (two within the taper of a junction), or for the edge a free corner lies
// nearest, active or not, whose stiffness and force enter the solver's piecewise-linear model
// of the step
// (doc/solver.md "Quasi-static equilibrium"; doc/physics.md "Contact and friction").
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// A corner against one edge, linearised about the edge as it lies: the gap changes by B du,
// B = [n, -a n, -b n] over the corner and the edge's ends (n the edge's outward normal, a and
// b the shares of its ends at the projection), and an active link pushes with the penalty
// -stiffness (gap + B du) along B, plus its friction: a spring along the tangent while it
// sticks, the force it has while it slides.
struct ContactLink {
  index_t receivers[3];
  double share[3];
  double tx, ty;            // the edge's unit tangent; the normal is (ty, -tx)
  double stiffness;         // N/m
  double gap;               // m, negative inside
  double length;            // the edge's, m
  double force[6];          // the pair's force now (zero where it does not press)
  bool pressing, sticks;
};

// The link of each corner that presses through an edge (contact_forces made the forces at
// these positions), or else lies within `reach` of one outside it, as the force kernel would
// see it (facing it, projecting inside it): the edge it lies nearest.
std::vector<ContactLink> contact_links(const Nodes& nodes, const Triangles& triangles, const Mechanics& mechanics,
                                       const Contact& contact, double reach);

// Whether each link starts active: pressing, or lying on its edge (a conforming interface
// at rest, which would otherwise give a body that only contact holds no stiffness).
std::vector<std::uint8_t> links_in_contact(const std::vector<ContactLink>& links);

// The active links' stiffness, and explicit zeros for the others so that the pattern is the
// same whichever are active: the penalty along B and, where the link sticks, the friction
// spring along the edge. A sliding link's friction, which follows the normal force, and the
// turn of the edge are left out (the model stays symmetric). Appends the entries between unknowns (`unknown`: [2 * nodes] ->
// unknown or kNoIndex).
void add_link_stiffness(const std::vector<ContactLink>& links, const std::vector<std::uint8_t>& active,
                        const std::vector<index_t>& unknown, std::vector<Eigen::Triplet<double>>& entries);

// The out-of-balance force of the model at du = 0: `rhs` holds the forces as they are; each
// link's own is replaced by the model's (-stiffness gap along B and its friction where
// active, nothing where not).
void model_link_forces(const std::vector<ContactLink>& links, const std::vector<std::uint8_t>& active,
                       const std::vector<index_t>& unknown, Eigen::VectorXd& rhs);

// Sets each link active where the step du closes its gap, and counts in `changes` how often
// each link's state has changed over a step's rounds. A link whose state changes a second time
// alternates (a penalty's model is no M-matrix, and a corner that rests on its edge with next
// to no force closes in one round's model and opens in the next's): it is held from then on as
// the force kernel has it, active where it presses. Returns how many links changed.
std::size_t update_active_links(const std::vector<ContactLink>& links, const Eigen::VectorXd& du,
                                const std::vector<index_t>& unknown, std::vector<std::uint8_t>& changes,
                                std::vector<std::uint8_t>& active);

}  // namespace ydry
