// The FDEM solid (DESIGN section 4): constant-strain triangles with a co-rotational law,
// cohesive joints, gravity, fixed and driven boundaries, and the quasi-static relaxation that
// brings it to equilibrium after each step of the moisture clock.
#pragma once

#include <vector>

#include <cstdint>

#include "ycore/input/deck.h"
#include "ycore/solid/node_integration.h"
#include "ycore/state/state.h"

namespace ydry {

// Material constants, masses, reference geometry, joint data and boundary constraints from
// the deck; state.mechanics.step_s from the stability bound. Throws InputError for a key the
// solid needs and the deck lacks, or for contradictory boundary conditions.
void init_mechanics(State& state, const Deck& deck);

// Per node, an upper bound of the row sum of its element, joint and contact stiffness, N/m
// (Gershgorin); 0 for a node that is fixed in both directions or not mechanical.
std::vector<double> node_stiffness_bound(const State& state);

// The largest stable step of the central-difference integration times `safety`: per node,
// omega^2 <= node_stiffness_bound / mass.
double stable_mechanics_step(const State& state, double safety);

// Quasi-static runs: only the equilibrium matters, so the inertia of each node is free
// (fdem-notes section 4). Nodes stiffer for their mass than the median node (small elements
// at a refined boundary, notch teeth) are made heavier until they are stable at the median
// node's step, so the few smallest elements no longer set the step of all. (Making the
// softer nodes lighter too, Underwood's fictitious masses, saves 12 % of the Peron steps
// before cracking but changed which late cracks open from the top: while relaxations stop
// at their cap during cracking, the pattern depends on the pseudo-dynamics; see
// inputs/peron/README.md.)
void scale_node_masses_to_common_step(State& state);

// Cuts triangles, nodes and joints into `slots` ranges of about equal work (ownership.h):
// a rigid triangle is counted as a tenth of a deformable one (it has no element or joint
// forces, only its nodes' passes).
Ownership partition_for_threads(const State& state, std::size_t slots);

// Element internal forces and gravity: overwrites fx, fy of every node (each triangle owns
// its three nodes). With move_first, each triangle's nodes are first moved by that pseudo-step
// (integrate_node_range), in the same pass, and the return is the moved components' sum of
// v_new . f with the forces that moved them (0 without), the same on any number of threads.
double element_forces(State& state, const VelocityUpdate* move_first = nullptr);

// The element stress (Triangles::sxx, syy, sxy) at the current positions. The forces do not
// need it: relaxations make it once, at the equilibrium reached.
void element_stresses(State& state);

// Joints per pass of the joint kernel's vectorised pre-peak law (joint_forces.cpp).
constexpr int kJointChunk = 256;

// Joint forces into joints.force, and the work done on them over the last step (the
// trapezoid of the forces before and after it, times velocities x dt) into joints.work.
// Broken joints carry nothing: their faces meet through contact (ycore/contact/contact.h).
void joint_forces(State& state, double dt);

// The forces of joint j on its nodes 0..3 (x, y) with the full traction law at its three
// points, as joint_forces stores them: zero for a broken joint.
void joint_nodal_forces(const State& state, std::size_t j, double out[8]);

struct RelaxationControls {
  double tolerance = 1e-7;          // out-of-balance force ratio that ends it
  std::int64_t max_steps = 200000;  // step cap
  RelaxationMethod method = RelaxationMethod::viscous;
};

struct RelaxationResult {
  std::int64_t steps = 0;
  double residual = 0;   // ||net force on free components|| / ||element forces||
  bool capped = false;   // stopped by the step cap
};

// One quasi-static step of the solid over `coupling_dt` seconds of the moisture clock:
// driven nodes move by velocity x coupling_dt, then explicit central-difference steps, damped
// by adaptive mass-proportional damping or steered by FIRE (controls.method), run until the
// out-of-balance ratio is below the tolerance. Velocities are left as displacement / coupling_dt (physical), reactions and
// boundary and gravity work are booked.
RelaxationResult relax(State& state, const RelaxationControls& controls, double coupling_dt);

// The dynamic alternative (solver.integration = "dynamic"): the solid moves for coupling_dt
// seconds of real time in undamped central-difference steps no longer than the stable one,
// velocities carried over from the last call; driven nodes move at their velocity. Books the
// reactions and the work like relax.
RelaxationResult move_dynamically(State& state, double coupling_dt);

// Commits each joint point's damage (maximum over time) and breaks, for good, every joint
// with two of its three points at D = 1. Returns the number of joints that broke.
std::size_t commit_joint_damage(State& state);

struct Energies {
  double kinetic_J = 0;      // physical masses and velocities
  double elastic_J = 0;      // strain energy of the triangles
  double joint_work_J = 0;   // work done on all joints since t = 0
  double fracture_J = 0;     // work done on the joints that broke (all of it dissipated)
  double contact_work_J = 0; // work done on the contacts: friction and the normal dashpot
                             // dissipate it, the penalty stores some of it
  double external_work_J = 0;  // through fixed and driven boundaries
  double gravity_work_J = 0;
};
Energies energies(const State& state);

}  // namespace ydry
