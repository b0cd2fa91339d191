// Quasi-static relaxation of the solid (doc/solver.md "Quasi-static equilibrium"; a step of
// the coupling loop, doc/architecture.md "A coupling step").
//
// From the equilibrium extrapolated along the last relaxation's motion (predict_equilibrium),
// the solid is brought to rest by one of the methods of solver.relaxation (the default is the
// deck's, RelaxationDefaults in ycore/input/deck.h: "newton"). The explicit ones step central
// differences in pseudo-time (symplectic Euler: v += dt f / m, x += dt v):
//
// - "viscous": mass-proportional damping c = 2 omega, omega^2 the Rayleigh quotient
//   -v.(f_new - f_old) / (dt v.M v) of the last step's motion (Underwood's adaptive dynamic
//   relaxation, with the step's velocity in place of the total displacement: a boundary that
//   moved the solid rigidly does not fool it into no damping). As the fast modes die out the
//   damping tends to critical for the slowest mode the load excites. Near a limit point (a
//   softening crack tip, a block rocking on its contacts) the slowest mode is so slow that
//   most of the Peron relaxations stop at their cap.
// - "fire": the Fast Inertial Relaxation Engine (Bitzek, Koskinen, Gähler, Moseler, Gumbsch,
//   Phys. Rev. Lett. 97, 170201, 2006). The motion is undamped, but the velocity is turned
//   towards the force, v <- (1 - alpha) v + alpha |v| f^, while the power f.v stays
//   positive, alpha decaying from 0.1 by 0.99 a step after 5 such steps; when the power turns
//   negative (the solid has passed a minimum along its path) every node stops and alpha
//   starts again. The norms and the direction are taken in mass-weighted coordinates
//   (sqrt(m) v and f / sqrt(m)), so the scaled masses change the metric, not the method.
//   The pseudo-step grows by 1.1 a step (after the same 5) up to the stable one and halves
//   at each restart. It reaches the tolerance in many relaxations where the damping stops
//   at the cap, in fewer steps.
// - "newton" (default): Newton iterations on the out-of-balance force (newton.h), FIRE where
//   they stop.
//
// Only the equilibrium reached means anything; the path in pseudo-time does not. The state
// with history is committed from the equilibrium alone: the joints' damage
// (commit_joint_damage, joint_damage.h) and the friction's slip
// (FrictionUpdate::at_equilibrium), so the methods find the same equilibria where they
// converge.
#include "ycore/solid/relaxation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "ycore/contact/contact_forces.h"
#include "ycore/solid/element_forces.h"
#include "ycore/solid/joint_damage.h"
#include "ycore/solid/newton.h"
#include "ycore/solid/numerical_failure.h"
#include "ycore/solid/solid_forces.h"
#include "ycore/solid/substrate.h"
#include "ycore/state/blocked_sum.h"
#include "ycore/state/stage_timing.h"

namespace ydry {
namespace {

// Central differences with damping c (centred: (1 - c dt/2) v_old, / (1 + c dt/2)); c = 0:
// undamped.
VelocityUpdate viscous_update(double damping, double dt) {
  return {1.0 - 0.5 * damping * dt, 0.0, 1.0 / (1.0 + 0.5 * damping * dt), dt};
}

// FIRE (the comment at the top): the mixing, restarts and pseudo-step, from the power and
// norms of the forces and velocities the last force evaluation measured.
class FireSteering {
 public:
  explicit FireSteering(double max_step) : max_step_(max_step), step_(max_step) {}

  VelocityUpdate next(const ForceMeasures& m) {
    if (!(m.power > 0.0)) {
      // Stop, halve the step and start turning again. A restart makes the next step one of
      // steepest descent, x += step^2 f / m, which is stable only below 1/sqrt(2) of the
      // central-difference limit: a full-length step would reverse the stiffest mode at
      // every step and restart for ever (the soil resting on the base does).
      alpha_ = kAlphaStart;
      positive_steps_ = 0;
      step_ = std::max(step_ * kStepDecrease, kMinStepFraction * max_step_);
      return {0.0, 0.0, 1.0, step_};
    }
    if (++positive_steps_ > kDelaySteps) {
      alpha_ *= kAlphaDecay;
      step_ = std::min(step_ * kStepIncrease, max_step_);
    }
    // (1 - alpha) v + alpha |sqrt(m) v| / |f / sqrt(m)| f / m
    const double steer = m.force2_over_mass > 0.0 ? alpha_ * std::sqrt(m.twice_kinetic / m.force2_over_mass) : 0.0;
    return {1.0 - alpha_, steer, 1.0, step_};
  }

 private:
  // Bitzek et al. 2006; the step never exceeds the stable one (solver.mechanics_safety).
  static constexpr double kAlphaStart = 0.1, kAlphaDecay = 0.99;
  static constexpr double kStepIncrease = 1.1, kStepDecrease = 0.5, kMinStepFraction = 0.02;
  static constexpr int kDelaySteps = 5;
  double max_step_, step_;
  double alpha_ = kAlphaStart;
  int positive_steps_ = 0;
};

// Moves the driven nodes by velocity x coupling_dt.
void move_driven_nodes(const Mechanics& mech, Nodes& n, double coupling_dt, double dt) {
  for (std::size_t k = 0; k < mech.driven_node.size(); ++k) {
    const index_t i = mech.driven_node[k];
    n.x[i] += mech.driven_vx[k] * coupling_dt;
    n.y[i] += mech.driven_vy[k] * coupling_dt;
    // Seen as a velocity by one joint-force evaluation, so the joints book the jump's work.
    n.vx[i] = mech.driven_vx[k] * coupling_dt / dt;
    n.vy[i] = mech.driven_vy[k] * coupling_dt / dt;
  }
}

// Reactions: the force each support exerts, -(net internal force), summed per boundary, and
// the work done through each boundary since the last equilibrium: the trapezoid of the
// reactions at the two equilibria times the boundary's displacement (the quasi-static
// external work, exact for a linear solid; what the damping takes out of the jump between
// them is not work done on the solid's equilibrium path).
void update_reactions(const Nodes& n, std::vector<MechanicsBoundary>& boundaries, double coupling_dt) {
  for (MechanicsBoundary& b : boundaries) {
    double rx = 0, ry = 0;
    for (const index_t i : b.nodes) {
      if (b.fix_x) rx -= n.fx[i];
      if (b.fix_y) ry -= n.fy[i];
    }
    b.work_J += 0.5 * ((b.reaction_x + rx) * b.vx + (b.reaction_y + ry) * b.vy) * coupling_dt;
    b.reaction_x = rx;
    b.reaction_y = ry;
  }
}

// Remembers where the solid starts from (for the gravity work and the velocities).
void start_motion(const Nodes& n, const Ownership& ownership, Mechanics& mech) {
  for_each_owned(ownership.node_begin, n.size(), [&](std::size_t i) {
    mech.x_start[i] = n.x[i];
    mech.y_start[i] = n.y[i];
  });
}

// Moves the free nodes on along the last coupling step's motion (the velocities relax leaves
// behind): drying changes the eigenstrain smoothly, so the extrapolated equilibrium leaves
// the relaxation only the curvature of the path to remove. The joint damage and the friction
// slip are committed from the relaxed state only, so a prediction that overshoots leaves no
// trace. (A friction that slid at every pseudo-step would keep it: a block that slid in one
// relaxation would be carried on by the next prediction and held where it was put, a ratchet
// that walks a block on after the drying has stopped; doc/solver.md "Quasi-static
// equilibrium".) Like the driven nodes' jump, the prediction is seen as a velocity by one force
// evaluation, so the joints and contacts book its work; prescribed components start at rest.
//
// A node's jump is at most the contact buffer (a tenth of the shortest edge). Drying moves a
// node microns between relaxations; a node that moved farther is not drifting but falling or
// snapping (a fragment come loose, a crack that opened), and its motion does not go on. Carried
// on unbounded, such a motion grows from one relaxation to the next, and a jump longer than the
// buffer can take a node past a contact surface the broad phase never saw it near (a loose
// triangle of the Peron deck would fall through the rigid base). Within the buffer the
// relaxation's own pseudo-steps meet the surface.
void predict_equilibrium(const Contact& contact, const Ownership& ownership, Nodes& n, double coupling_dt, double dt) {
  const double limit = contact.buffer_m;
  for_each_owned(ownership.node_begin, n.size(), [&](std::size_t i) {
    double jump_x = n.constraint[i] & kFixX ? 0.0 : n.vx[i] * coupling_dt;
    double jump_y = n.constraint[i] & kFixY ? 0.0 : n.vy[i] * coupling_dt;
    const double length = std::sqrt(jump_x * jump_x + jump_y * jump_y);
    if (length > limit) {
      jump_x *= limit / length;
      jump_y *= limit / length;
    }
    n.x[i] += jump_x;
    n.y[i] += jump_y;
    n.vx[i] = jump_x / dt;
    n.vy[i] = jump_y / dt;
  });
}

// A node that moved farther than the whole mesh is wide since start_motion has run away
// (an unstable step, an inverted element): the run stops (exit 3) rather than go on with a
// state that is finite but meaningless.
void stop_runaway(const State& s) {
  const Nodes& n = s.nodes;
  const Mechanics& mech = s.mechanics;
  const double limit2 = mech.mesh_diagonal_m * mech.mesh_diagonal_m;
  if (!(limit2 > 0.0)) return;  // a state init_mechanics has not set up (unit tests)
  for (index_t i = 0; i < n.size(); ++i) {
    const double dx = n.x[i] - mech.x_start[i], dy = n.y[i] - mech.y_start[i];
    if (dx * dx + dy * dy <= limit2) continue;
    std::ostringstream m;
    m << "numerical failure at t = " << s.time_s << " s: " << describe_node(s, i) << " moved "
      << std::sqrt(dx * dx + dy * dy) << " m in one relaxation, more than the mesh is wide ("
      << mech.mesh_diagonal_m << " m): " << kNumericalFailureCauses;
    throw NumericalFailure(m.str());
  }
}

// Books the reactions, the work of the supports and of gravity since start_motion, and the
// step count; makes the element stresses of the state reached.
void finish_motion(State& s, const RelaxationResult& result, double coupling_dt) {
  stop_runaway(s);
  element_stresses(s.nodes, s.ownership, s.materials, s.triangles);
  const Nodes& n = s.nodes;
  Mechanics& mech = s.mechanics;
  update_reactions(n, s.mechanics_boundaries, coupling_dt);
  const auto gravity = blocked_sum<1>(n.size(), [&](std::size_t i, std::array<double, 1>& sum) {
    const double weight = s.triangles.mass_kg[triangle_of(index_t(i))] / 3.0;
    sum[0] += weight * (mech.gravity_x * (n.x[i] - mech.x_start[i]) + mech.gravity_y * (n.y[i] - mech.y_start[i]));
  }, s.ownership.node_begin);
  mech.gravity_work_J += gravity[0];
  mech.steps += std::uint64_t(result.steps);
  mech.last_residual = result.residual;
  if (result.capped) ++mech.capped_relaxations;
}

}  // namespace

RelaxationResult relax(State& s, const RelaxationControls& controls, double coupling_dt) {
  Nodes& n = s.nodes;
  Mechanics& mech = s.mechanics;
  const double dt = mech.step_s;
  start_motion(n, s.ownership, mech);
  const std::vector<double> joint_work =
      controls.method == RelaxationMethod::newton ? s.joints.work : std::vector<double>{};
  predict_equilibrium(s.contact, s.ownership, n, coupling_dt, dt);
  move_driven_nodes(mech, n, coupling_dt, dt);
  const bool fire_measures = controls.method != RelaxationMethod::viscous;
  // The friction slides only at the equilibrium reached (FrictionUpdate::at_equilibrium), until
  // a relaxation has taken controls.slide_after steps (doc/solver.md "Friction that stalls").
  FrictionUpdate friction = FrictionUpdate::at_equilibrium;
  ForcesBefore before;
  ForceMeasures measures = explicit_step(s, nullptr, dt, friction, fire_measures, before);
  if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "the start of a relaxation");
  std::fill(n.vx.begin(), n.vx.end(), 0.0);  // quasi-static: every relaxation starts at rest
  std::fill(n.vy.begin(), n.vy.end(), 0.0);
  // The measures of the jump's velocities, which are gone: FIRE steering with them would
  // start by kicking every node along f / m at a tenth of the jump's speed, and the stiff
  // joints' vibration would book work the law does not (the gf_I test shows it).
  measures.power = measures.twice_kinetic = measures.rayleigh_numerator = 0.0;

  RelaxationResult result;
  const auto balanced = [&](const ForceMeasures& m) {
    return m.net2 <= mech.roundoff_net2 || m.ratio() <= controls.tolerance;
  };
  result.residual = measures.ratio();
  if (controls.method == RelaxationMethod::newton) {
    const NewtonOutcome newton = newton_equilibrium(s, controls, joint_work);
    result.steps += newton.iterations;
    measures = newton.measures;
    result.residual = measures.ratio();
    if (!newton.converged) ++mech.newton_fallbacks;  // FIRE goes on from where Newton stopped
  }
  FireSteering fire(dt);
  double damping = 0.0;
  while (!balanced(measures) && result.steps < controls.max_steps) {
    if (controls.slide_after > 0 && result.steps >= controls.slide_after && friction == FrictionUpdate::at_equilibrium) {
      friction = FrictionUpdate::every_step;
      ++mech.friction_slide_relaxations;
    }
    const VelocityUpdate update = fire_measures ? fire.next(measures) : viscous_update(damping, dt);
    measures = explicit_step(s, &update, update.step, friction, fire_measures, before);
    ++result.steps;
    if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "relaxation step " + std::to_string(result.steps));
    if (measures.rayleigh_numerator > 0.0 && measures.twice_kinetic > 0.0)
      damping = std::min(2.0 * std::sqrt(measures.rayleigh_numerator / (dt * measures.twice_kinetic)), 2.0 / dt);
    result.residual = measures.ratio();
    if (controls.report && result.steps % kRelaxationReportSteps == 0 && !balanced(measures))
      controls.report(result.steps, result.residual);
  }
  result.capped = !balanced(measures);
  // At the round-off floor the ratio measures nothing (a solid at rest has no forces).
  if (measures.net2 > mech.roundoff_net2) mech.worst_residual = std::max(mech.worst_residual, result.residual);
  commit_friction_slip(s.nodes, s.triangles, s.mechanics, s.material_names.size(), s.contact);
  commit_substrate_slide(s.nodes, s.ownership, s.substrate);
  finish_motion(s, result, coupling_dt);
  // The velocities of the moisture clock: displacement over the coupling step.
  const double rate = coupling_dt > 0.0 ? 1.0 / coupling_dt : 0.0;
  for_each_owned(s.ownership.node_begin, n.size(), [&](std::size_t i) {
    n.vx[i] = (n.x[i] - mech.x_start[i]) * rate;
    n.vy[i] = (n.y[i] - mech.y_start[i]) * rate;
  });
  return result;
}

RelaxationResult move_dynamically(State& s, double coupling_dt) {
  start_motion(s.nodes, s.ownership, s.mechanics);
  const Mechanics& mech = s.mechanics;
  RelaxationResult result;
  // Forces at the start (the eigenstrain has changed); no motion yet, so no work booked.
  ForcesBefore before;
  ForceMeasures measures = explicit_step(s, nullptr, 0.0, FrictionUpdate::every_step, false, before);
  if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "the start of a dynamic step");
  const std::int64_t substeps = std::max<std::int64_t>(1, std::int64_t(std::ceil(coupling_dt / mech.step_s)));
  const double dt = coupling_dt / double(substeps);
  for (std::int64_t k = 0; k < substeps && coupling_dt > 0.0; ++k) {
    move_driven_nodes(mech, s.nodes, dt, dt);
    const VelocityUpdate undamped = viscous_update(0.0, dt);
    measures = explicit_step(s, &undamped, dt, FrictionUpdate::every_step, false, before);
    ++result.steps;
    if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "dynamic step " + std::to_string(result.steps));
    // In real time every state is one the solid passes through: a joint that passes its peak
    // keeps the damage, though it unloads before the coupling step ends.
    StageClock cracking;
    result.joints_broken += commit_joint_damage(s.nodes, s.ownership, s.materials, s.joints);
    commit_substrate_slide(s.nodes, s.ownership, s.substrate);
    cracking.lap(s.wall.cracking);
  }
  result.residual = measures.ratio();
  finish_motion(s, result, coupling_dt);
  return result;
}

}  // namespace ydry
