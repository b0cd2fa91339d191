// Quasi-static relaxation of the solid (DESIGN section 4, step 3 of the coupling loop).
//
// Explicit central differences in pseudo-time with mass-proportional damping c = 2 omega,
// omega^2 the Rayleigh quotient -v.(f_new - f_old) / (dt v.M v) of the last step's motion
// (Underwood's adaptive dynamic relaxation, with the step's velocity in place of the total
// displacement: a boundary that moved the solid rigidly does not fool it into no damping).
// As the fast modes die out the motion is that of the slowest mode the load excites, and the
// damping tends to critical for it. Only the equilibrium reached means anything; the path
// in pseudo-time does not.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "ycore/blocked_sum.h"
#include "ycore/contact.h"
#include "ycore/joint_law.h"
#include "ycore/mechanics.h"
#include "ycore/numerical_failure.h"

namespace ydry {
namespace {

struct ForceMeasures {
  double net2 = 0;       // |net force|^2 over free components
  double reference2 = 0; // |element forces and gravity|^2 over all nodes
  double rayleigh_numerator = 0, rayleigh_denominator = 0;
  double ratio() const { return reference2 > 0.0 ? std::sqrt(net2 / reference2) : (net2 > 0.0 ? INFINITY : 0.0); }
};

// Adds the joint and contact forces to the node forces (through each node's joint slots and
// contact gather list) and measures.
ForceMeasures gather_interaction_forces(State& s) {
  Nodes& n = s.nodes;
  Mechanics& mech = s.mechanics;
  const std::vector<double>& jf = s.joints.force;
  const Contact& c = s.contact;
  const bool contact = !c.gather_offset.empty();
  const auto sums = blocked_sum<4>(n.size(), [&](std::size_t i, std::array<double, 4>& sum) {
    double fx = n.fx[i], fy = n.fy[i];
    sum[1] += fx * fx + fy * fy;
    for (int k = 0; k < 2; ++k) {
      const index_t slot = n.joint_slot[2 * i + k];
      if (slot == kNoIndex) continue;
      fx += jf[2 * std::size_t(slot)];
      fy += jf[2 * std::size_t(slot) + 1];
    }
    if (contact)
      for (index_t k = c.gather_offset[i]; k < c.gather_offset[i + 1]; ++k) {
        fx += c.pair_force[2 * std::size_t(c.gather_entry[k])];
        fy += c.pair_force[2 * std::size_t(c.gather_entry[k]) + 1];
      }
    n.fx[i] = fx;
    n.fy[i] = fy;
    if (!(n.constraint[i] & kFixX)) {
      const double u = n.vx[i];
      sum[0] += fx * fx;
      sum[2] -= u * (fx - mech.fx_previous[i]);
      sum[3] += n.m[i] * u * u;
    }
    if (!(n.constraint[i] & kFixY)) {
      const double u = n.vy[i];
      sum[0] += fy * fy;
      sum[2] -= u * (fy - mech.fy_previous[i]);
      sum[3] += n.m[i] * u * u;
    }
    mech.fx_previous[i] = fx;
    mech.fy_previous[i] = fy;
  }, s.ownership.node_begin);
  return {sums[0], sums[1], sums[2], sums[3]};
}

ForceMeasures compute_forces(State& s, double dt) {
  element_forces(s);
  joint_forces(s, dt);
  contact_forces(s, dt);
  return gather_interaction_forces(s);
}

// v += dt f / m with damping c (centred: (1 - c dt/2) v_old, / (1 + c dt/2)), x += v dt.
void integrate_nodes(State& s, double damping, double dt) {
  Nodes& n = s.nodes;
  const double keep = 1.0 - 0.5 * damping * dt, scale = 1.0 / (1.0 + 0.5 * damping * dt);
  for_each_owned(s.ownership.node_begin, n.size(), [&](std::size_t i) {
    if (!(n.constraint[i] & kFixX)) {
      n.vx[i] = (keep * n.vx[i] + dt * n.fx[i] / n.m[i]) * scale;
      n.x[i] += n.vx[i] * dt;
    }
    if (!(n.constraint[i] & kFixY)) {
      n.vy[i] = (keep * n.vy[i] + dt * n.fy[i] / n.m[i]) * scale;
      n.y[i] += n.vy[i] * dt;
    }
  });
}

// Moves the driven nodes by velocity x coupling_dt.
void move_driven_nodes(State& s, double coupling_dt, double dt) {
  Nodes& n = s.nodes;
  const Mechanics& mech = s.mechanics;
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
void update_reactions(State& s, double coupling_dt) {
  const Nodes& n = s.nodes;
  for (MechanicsBoundary& b : s.mechanics_boundaries) {
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
void start_motion(State& s) {
  Nodes& n = s.nodes;
  Mechanics& mech = s.mechanics;
  for_each_owned(s.ownership.node_begin, n.size(), [&](std::size_t i) {
    mech.x_start[i] = n.x[i];
    mech.y_start[i] = n.y[i];
  });
}

// Moves the free nodes on along the last coupling step's motion (the velocities relax leaves
// behind): drying changes the eigenstrain smoothly, so the extrapolated equilibrium leaves
// the relaxation only the curvature of the path to remove. The joint damage is committed
// from the relaxed state only, so a prediction that overshoots leaves no trace. Like the
// driven nodes' jump, the prediction is seen as a velocity by one force evaluation, so the
// joints and contacts book its work; prescribed components start at rest.
void predict_equilibrium(State& s, double coupling_dt, double dt) {
  Nodes& n = s.nodes;
  for_each_owned(s.ownership.node_begin, n.size(), [&](std::size_t i) {
    const double jump_x = n.constraint[i] & kFixX ? 0.0 : n.vx[i] * coupling_dt;
    const double jump_y = n.constraint[i] & kFixY ? 0.0 : n.vy[i] * coupling_dt;
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
// step count.
void finish_motion(State& s, const RelaxationResult& result, double coupling_dt) {
  stop_runaway(s);
  const Nodes& n = s.nodes;
  Mechanics& mech = s.mechanics;
  update_reactions(s, coupling_dt);
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
  start_motion(s);
  predict_equilibrium(s, coupling_dt, dt);
  move_driven_nodes(s, coupling_dt, dt);
  ForceMeasures measures = compute_forces(s, dt);
  if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "the start of a relaxation");
  std::fill(n.vx.begin(), n.vx.end(), 0.0);  // quasi-static: every relaxation starts at rest
  std::fill(n.vy.begin(), n.vy.end(), 0.0);
  mech.fx_previous = n.fx;
  mech.fy_previous = n.fy;

  RelaxationResult result;
  const auto balanced = [&](const ForceMeasures& m) {
    return m.net2 <= mech.roundoff_net2 || m.ratio() <= controls.tolerance;
  };
  result.residual = measures.ratio();
  double damping = 0.0;
  while (!balanced(measures) && result.steps < controls.max_steps) {
    integrate_nodes(s, damping, dt);
    measures = compute_forces(s, dt);
    ++result.steps;
    if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "relaxation step " + std::to_string(result.steps));
    if (measures.rayleigh_numerator > 0.0 && measures.rayleigh_denominator > 0.0)
      damping = std::min(2.0 * std::sqrt(measures.rayleigh_numerator / (dt * measures.rayleigh_denominator)), 2.0 / dt);
    result.residual = measures.ratio();
  }
  result.capped = !balanced(measures);
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
  const Mechanics& mech = s.mechanics;
  start_motion(s);
  RelaxationResult result;
  // Forces at the start (the eigenstrain has changed); no motion yet, so no work booked.
  ForceMeasures measures = compute_forces(s, 0.0);
  if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "the start of a dynamic step");
  const std::int64_t substeps = std::max<std::int64_t>(1, std::int64_t(std::ceil(coupling_dt / mech.step_s)));
  const double dt = coupling_dt / double(substeps);
  for (std::int64_t k = 0; k < substeps && coupling_dt > 0.0; ++k) {
    move_driven_nodes(s, dt, dt);
    integrate_nodes(s, 0.0, dt);
    measures = compute_forces(s, dt);
    ++result.steps;
    if (!std::isfinite(measures.net2)) report_non_finite_solid(s, "dynamic step " + std::to_string(result.steps));
  }
  result.residual = measures.ratio();
  finish_motion(s, result, coupling_dt);
  return result;
}

std::size_t commit_joint_damage(State& s) {
  Joints& jt = s.joints;
  const auto broke = blocked_sum<1>(jt.size(), [&](std::size_t j, std::array<double, 1>& sum) {
    const MaterialModel& m = s.materials[jt.material[j]];
    if (jt.broken[j] || !m.mechanical || !m.breakable) return;
    const JointKinematics k = joint_kinematics(s.nodes, &jt.node[4 * j]);
    int failed = 0;
    for (int p = 0; p < 3; ++p) {
      const double a = kJointPointShareOfEnd0[p], b = 1.0 - a;
      double& d = jt.damage[3 * j + p];
      const double o = a * k.opening[0] + b * k.opening[1], sl = a * k.slip[0] + b * k.slip[1];
      d = std::max(d, cohesive_traction(m, jt.strength_factor[j], jt.length0[j], o, sl, d).damage);
      failed += d >= 1.0;
    }
    if (failed >= 2) {
      jt.broken[j] = 1;
      sum[0] += 1.0;
    }
  }, s.ownership.joint_begin);
  return std::size_t(broke[0]);
}

}  // namespace ydry
