// The Newton equilibrium solver of the quasi-static solid (solver.relaxation = "newton";
// doc/solver.md "Quasi-static equilibrium").
#pragma once

#include <cstdint>

#include "ycore/solid/relaxation.h"
#include "ycore/solid/solid_forces.h"
#include "ycore/state/state.h"

namespace ydry {

// The trust region's mu, relative to the mean of diag K / diag M: from this small start (a
// Newton step where K is positive definite), times 10 on each refusal, divided by 10 after
// each accepted step, given up above kMaxMu (the step is then a thousandth of a free fall's).
// The start also bounds how far a body that no support holds drifts: round-off's net force
// on it moves it by that force / (mu scale m) a step (a free block shrinking by 1 mm drifts
// 3 nm at 1e-8, 0.3 um at 1e-10: tests/test_surface.cpp).
constexpr double kMinMu = 1e-8, kMaxMu = 1e6;

struct NewtonOutcome {
  bool converged = false;
  std::int64_t iterations = 0;      // force evaluations of trial states
  std::int64_t factorisations = 0;
  ForceMeasures measures;           // of the state reached
};

// From the current positions, at rest, to equilibrium by Newton
// iterations on the out-of-balance force: (K + K_c + mu M) du = f with K the tangent of the
// element and joint forces (tangent.h), K_c the penalty of the contact links the step closes
// (contact_tangent.h: an active set found by solving again) and M the nodes' masses. Each step
// is cut back along du until the energy falls (its slope -f.du measured at both ends); mu is
// raised where K + K_c + mu M is not positive definite or no cut lowers the energy (a trust
// region in the metric of M, which also holds a body that only contact keeps in place), and
// lowered after each full step. Each accepted step moves the contacts' friction slip with the
// displacement and books the contacts' work by the trapezoid over it. The joints' work is
// booked between equilibria: from `joint_work`, the joints' work when the relaxation began,
// along the straight path from mechanics.x_start, y_start to the state reached. It writes the
// positions, the forces, the contact's pairs, slips and work, and the joints' work. Stops
// unconverged after 100 force evaluations (or controls.max_steps) or when mu grows beyond any
// use; the caller then relaxes on from the state reached. It starts from the forces of the
// positions as they are at rest: the relaxation's first evaluation saw the predicted jump as a
// velocity, and the contact's dashpot with it.
NewtonOutcome newton_equilibrium(State& state, const RelaxationControls& controls, const std::vector<double>& joint_work);

}  // namespace ydry
