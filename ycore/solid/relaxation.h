// Bringing the solid to equilibrium after each step of the moisture clock (relaxation.cpp;
// doc/solver.md "Quasi-static equilibrium" and "Dynamic integration", doc/architecture.md
// "A coupling step").
//
// relax and move_dynamically are phases, not kernels: each runs the element, joint and contact
// kernels over the whole solid many times, and writes the nodes (positions, velocities,
// forces), the triangles' stresses, the joints' forces and work, the contact's pairs, forces,
// slips and work, the mechanics' motion start, step counts, residual and gravity work, the
// boundaries' reactions and work, and the stage clock (State::wall). They read the materials,
// the ownership table, and the time and material names for the messages of a numerical failure.
#pragma once

#include <cstdint>
#include <functional>

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// Told, after every Newton step and every kRelaxationReportSteps explicit steps of a
// relaxation that runs on, its step count (force evaluations) and out-of-balance ratio (the
// progress line says a long relaxation is still at work).
using RelaxationReport = std::function<void(std::int64_t steps, double residual)>;
constexpr std::int64_t kRelaxationReportSteps = 1000;

struct RelaxationControls {
  double tolerance = RelaxationDefaults::tolerance;         // out-of-balance force ratio that ends it
  std::int64_t max_steps = RelaxationDefaults::max_steps;  // step cap
  RelaxationMethod method = RelaxationDefaults::method;
  std::int64_t slide_after = RelaxationDefaults::slide_after;  // steps after which the friction slides at every step; 0: never
  RelaxationReport report = nullptr;  // none: no reports
};

struct RelaxationResult {
  std::int64_t steps = 0;
  double residual = 0;   // ||net force on free components|| / ||element forces||
  bool capped = false;   // stopped by the step cap
  std::size_t joints_broken = 0;  // move_dynamically: joints its steps broke (damage committed at each)
};

// One quasi-static step of the solid over `coupling_dt` seconds of the moisture clock:
// driven nodes move by velocity x coupling_dt, then Newton iterations (FIRE where they stop)
// or explicit central-difference steps, damped by adaptive mass-proportional damping or
// steered by FIRE (controls.method), run until the out-of-balance ratio is below the
// tolerance. Velocities are left as displacement /
// coupling_dt (physical), reactions and boundary and gravity work are booked. Throws
// NumericalFailure (numerical_failure.h) for a non-finite or runaway solid.
RelaxationResult relax(State& state, const RelaxationControls& controls, double coupling_dt);

// The dynamic alternative (solver.integration = "dynamic"): the solid moves for coupling_dt
// seconds of real time in undamped central-difference steps no longer than the stable one,
// velocities carried over from the last call; driven nodes move at their velocity. Books the
// reactions and the work like relax.
RelaxationResult move_dynamically(State& state, double coupling_dt);

}  // namespace ydry
