#include "ycore/solid/newton.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "ycore/contact/contact_forces.h"
#include "ycore/solid/joint_work.h"
#include "ycore/solid/stiffness_model.h"
#include "ycore/solid/substrate.h"
#include "ycore/state/stage_timing.h"

namespace ydry {
namespace {

// A step is accepted when it lowers the energy by at least this share of what its first-order
// change promises (Armijo's rule), the energy's change measured by the trapezoid of its slopes
// -f.du at the two ends (exact where the energy is quadratic along du).
constexpr double kSufficientDecrease = 1e-4;
// Force evaluations after which Newton leaves the rest to FIRE (within solver.relaxation_max_steps).
constexpr std::int64_t kMaxEvaluations = 100;
// Cuts of a step along its direction before mu is raised: each to the minimum of the quadratic
// through the slopes at its ends, kept within [0.1, 0.5] of the step.
constexpr int kMaxCuts = 4;
// Solves of the model a step, at most, to settle its active contacts (a link that alternates is
// held after its second change: update_active_links).
constexpr int kMaxActiveSetRounds = 8;
// A relaxation's tangent holds the joints' mode II strength at each step's compression
// (JointFrictionTangent::held) until a step needs mu of this much or more; from the next step on
// it takes the strength's rise as derived (doc/solver.md "The joints' friction in the tangent").
constexpr double kDerivedFrictionMu = 1e-4;
// Chord steps (the factor of the matrix the last Newton relaxation converged with) a relaxation
// takes first, at most, each to lower the out-of-balance ratio to this share of the last's at
// least; where one does not, they are undone and Newton starts as without them.
constexpr int kChordSteps = 8;
constexpr double kChordContraction = 0.25;

// What a trial step changes beyond the positions, kept to undo a refused one: the joints'
// forces, and the contact's pairs, slips, forces and work.
struct Undo {
  std::vector<double> x, y, joint_force;
  Contact contact;
  Undo(const Nodes& n, const Joints& jt, const Contact& c) : x(n.x), y(n.y), joint_force(jt.force), contact(c) {}
  void restore(Nodes& n, Joints& jt, Contact& c) const { n.x = x, n.y = y, jt.force = joint_force, c = contact; }
};

// Moves the free components by du from `from`, as a velocity du over a unit pseudo-step: the
// friction slip advances by it (forces_after_move), and FIRE, where it takes over, steers
// from the measures of that velocity.
void move_by(const FreeComponents& free, const Eigen::VectorXd& du, const Undo& from, Nodes& n) {
  n.x = from.x, n.y = from.y;
  std::fill(n.vx.begin(), n.vx.end(), 0.0);
  std::fill(n.vy.begin(), n.vy.end(), 0.0);
  for (std::size_t u = 0; u < free.size(); ++u) {
    const index_t c = free.component[u], i = c / 2;
    if (c % 2 == 0)
      n.x[i] += du[Eigen::Index(u)], n.vx[i] = du[Eigen::Index(u)];
    else
      n.y[i] += du[Eigen::Index(u)], n.vy[i] = du[Eigen::Index(u)];
  }
}

// The forces where move_by left the nodes, in the phases of doc/solver.md "One evaluation, in
// phases": the contact pairs updated, the friction slip advanced over the step of dt (1 after
// move_by, 0 where nothing moved), the forces. The contact forces before it are left in
// contact_before, for the work booked over a step that is kept (book_contact_work); the
// joints' work is booked once the relaxation ends (book_joint_work).
ForceMeasures forces_after_move(State& s, double dt, std::vector<double>& contact_before) {
  StageClock clock;
  update_contact_pairs(s.nodes, s.ownership, s.contact);
  keep_contact_forces(s.contact, contact_before);
  advance_friction_slip(s.nodes, dt, s.contact);
  clock.lap(s.wall.contact);
  return compute_forces(s);
}

// The free components' mass and the trust region's unit (mean diag K / diag M).
struct Metric {
  Eigen::VectorXd mass;
  double scale = 0;
};

// The step to the minimum of the piecewise-linear model of the forces at mu: the links active
// where the step closes them, found by solving again until the set holds (a primal-dual
// active set); A is left the matrix last factorised. Empty where K_solid + links + mu M is not
// positive definite.
Eigen::VectorXd model_step(const Eigen::SparseMatrix<double>& K_solid, const std::vector<ContactLink>& links,
                           const FreeComponents& free, const Eigen::VectorXd& f, const Metric& metric, double mu,
                           std::vector<std::uint8_t>& active, StiffnessSolver& solver, Eigen::SparseMatrix<double>& A,
                           NewtonOutcome& out) {
  Eigen::VectorXd du;
  std::vector<std::uint8_t> changes(links.size(), 0);
  for (int round = 0; round < kMaxActiveSetRounds; ++round) {
    A = model_tangent(K_solid, links, active, free);
    A.diagonal() += mu * metric.scale * metric.mass;
    solver.factorize(A);
    ++out.factorisations;
    if (solver.info() != Eigen::Success || !(solver.vectorD().minCoeff() > 0.0)) return {};
    Eigen::VectorXd rhs = f;
    model_link_forces(links, active, free.unknown, rhs);
    du = solver.solve(rhs);
    if (update_active_links(links, du, free.unknown, changes, active) == 0) break;
  }
  return du;
}

// Tries du from the state `from` and cuts it back along its direction until the energy falls
// enough (kSufficientDecrease); true with the state moved and its forces in out.measures,
// false with the state as it was.
bool line_search(State& s, const FreeComponents& free, const Eigen::VectorXd& f, const Eigen::VectorXd& du,
                 const Undo& from, std::int64_t cap, double& step, NewtonOutcome& out) {
  const double slope0 = -f.dot(du);  // the energy's slope along du, < 0 for a descent direction
  step = 1.0;
  for (int cut = 0; cut < kMaxCuts && out.iterations < cap; ++cut) {
    move_by(free, step * du, from, s.nodes);
    std::vector<double> contact_before;
    const ForceMeasures trial = forces_after_move(s, 1.0, contact_before);
    ++out.iterations;
    const double slope = -out_of_balance(free, s.nodes).dot(du);
    if (std::isfinite(trial.net2) && 0.5 * (slope0 + slope) <= kSufficientDecrease * slope0) {
      book_contact_work(s.nodes, contact_before, 1.0, s.contact);
      out.measures = trial;
      return true;
    }
    from.restore(s.nodes, s.joints, s.contact);
    step *= std::clamp(std::isfinite(slope) ? slope0 / (slope0 - slope) : 0.0, 0.1, 0.5);
  }
  return false;
}

// Chord steps from the current state: du solves the chord matrix's factor against the
// out-of-balance force, taken whole where it lowers the energy (kSufficientDecrease), while each
// lowers the ratio to kChordContraction of the last's. True where they reach the tolerance;
// otherwise false with the state as it was, so that Newton goes on as without them.
bool chord_steps(State& s, const FreeComponents& free, const std::function<bool(const ForceMeasures&)>& balanced,
                 NewtonOutcome& out) {
  Mechanics& mech = s.mechanics;
  if (mech.chord_values.empty() || mech.chord_components != free.component) return false;
  StageClock factor_clock;
  const ChordFactor& factor = chord_factor(mech);
  factor_clock.lap(s.wall.solve);
  if (factor.solver.info() != Eigen::Success) return false;
  const Undo start(s.nodes, s.joints, s.contact);
  const std::vector<double> fx = s.nodes.fx, fy = s.nodes.fy;
  const ForceMeasures start_measures = out.measures;
  const auto give_up = [&] {
    start.restore(s.nodes, s.joints, s.contact);
    s.nodes.fx = fx, s.nodes.fy = fy, out.measures = start_measures;
    return false;
  };
  for (int k = 0; k < kChordSteps; ++k) {
    // The force passes of the line search book their own stages; the solve is "solve".
    StageClock clock;
    const double ratio = out.measures.ratio();
    const Eigen::VectorXd f = out_of_balance(free, s.nodes);
    Eigen::VectorXd du = factor.solver.solve(f);
    clock.lap(s.wall.solve);
    if (!(f.dot(du) > 0.0)) return give_up();
    limit_move(free, s.contact.buffer_m, du);
    std::optional<Undo> moved;  // the state a later step starts from (the first starts from `start`)
    if (k > 0) moved.emplace(s.nodes, s.joints, s.contact);
    double step = 1.0;
    if (!line_search(s, free, f, du, k > 0 ? *moved : start, out.iterations + 1, step, out)) return give_up();
    if (balanced(out.measures)) return true;
    if (!(out.measures.ratio() <= kChordContraction * ratio)) return give_up();
  }
  return give_up();
}

}  // namespace

NewtonOutcome newton_equilibrium(State& s, const RelaxationControls& controls, const std::vector<double>& joint_work) {
  Nodes& n = s.nodes;
  const FreeComponents free = free_components(n, s.triangles, s.materials);
  Metric metric;
  metric.mass = free_masses(free, n);
  const double damping = s.contact.damping_ratio;
  s.contact.damping_ratio = 0.0;  // the dashpot would read the steps as velocities
  const FillOrdering ordering = fill_ordering(s.triangles, s.joints, s.materials, free, s.mechanics);
  NewtonOutcome out;
  // The relaxation's first evaluation saw the predicted jump as a velocity over one pseudo-step,
  // and the contact's dashpot pushed against it: a force that no state at rest has, which the
  // model's links leave out (they push with the penalty alone), so that near the tolerance every
  // step looked uphill and the relaxation went to FIRE (doc/solver.md). The forces at rest:
  std::vector<double> contact_before;
  out.measures = forces_after_move(s, 0.0, contact_before);
  const auto balanced = [&](const ForceMeasures& m) {
    return m.net2 <= s.mechanics.roundoff_net2 || m.ratio() <= controls.tolerance;
  };
  // Newton's factor, handed to the chord steps where its step converges.
  const auto newton_factor = std::make_shared<ChordFactor>(ordering);
  StiffnessSolver& solver = newton_factor->solver;
  StiffnessPattern pattern;
  Eigen::SparseMatrix<double> factorised;  // the matrix of the last Newton step
  double mu = kMinMu;
  out.converged = balanced(out.measures) || chord_steps(s, free, balanced, out);
  const std::int64_t cap = std::min<std::int64_t>(kMaxEvaluations, controls.max_steps) + out.iterations;
  JointFrictionTangent joint_friction = JointFrictionTangent::held;
  while (!(out.converged = balanced(out.measures)) && out.iterations < cap && mu <= kMaxMu) {
    if (joint_friction == JointFrictionTangent::held && mu >= kDerivedFrictionMu) {
      joint_friction = JointFrictionTangent::derived;
      mu = kMinMu;
    }
    // The force passes of the line search book their own stages; the rest is "solve".
    StageClock model_clock;
    const Eigen::SparseMatrix<double> K_solid =
        tangent_stiffness(n, s.triangles, s.joints, s.mechanics, s.materials, free, joint_friction) +
        substrate_tangent(n, s.substrate, free);
    metric.scale = K_solid.diagonal().sum() / metric.mass.sum();
    const Eigen::VectorXd f = out_of_balance(free, n);
    const Undo undo(n, s.joints, s.contact);
    // Every corner within the contact buffer of an edge: no step moves a node farther.
    const std::vector<ContactLink> links = contact_links(n, s.triangles, s.mechanics, s.contact, s.contact.buffer_m);
    std::vector<std::uint8_t> active = links_in_contact(links);
    // The pattern is the same whichever links are active; the ordering is found again only
    // when it changes (a joint breaks, a pair comes near).
    pattern.analyse(model_tangent(K_solid, links, active, free), solver);
    model_clock.lap(s.wall.solve);
    bool accepted = false;
    while (!accepted && mu <= kMaxMu && out.iterations < cap) {
      StageClock step_clock;
      Eigen::VectorXd du = model_step(K_solid, links, free, f, metric, mu, active, solver, factorised, out);
      step_clock.lap(s.wall.solve);
      if (du.size() == 0 || !(f.dot(du) > 0.0)) {  // not positive definite, or uphill
        mu *= 10.0;
        continue;
      }
      limit_move(free, s.contact.buffer_m, du);
      double step = 1.0;
      accepted = line_search(s, free, f, du, undo, cap, step, out);
      if (!accepted) mu *= 10.0;
      else if (step == 1.0) mu = std::max(mu / 10.0, kMinMu);
    }
    if (!accepted) {  // the forces of the state kept
      std::vector<double> contact_before;
      out.measures = forces_after_move(s, 0.0, contact_before);
      break;
    }
    // A Newton step of a large mesh can take seconds: the progress line hears of each.
    if (controls.report && !balanced(out.measures)) controls.report(out.iterations, out.measures.ratio());
  }
  // A Newton step's matrix that brought the relaxation to its tolerance serves the next ones.
  if (out.converged && factorised.nonZeros() > 0) keep_chord_factor(factorised, free, newton_factor, s.mechanics);
  std::fill(n.vx.begin(), n.vx.end(), 0.0);
  std::fill(n.vy.begin(), n.vy.end(), 0.0);
  s.contact.damping_ratio = damping;
  StageClock booking_clock;
  s.joints.work = joint_work;
  book_joint_work(n, s.mechanics, s.materials, s.mechanics.x_start, s.mechanics.y_start, s.joints);
  booking_clock.lap(s.wall.solve);
  return out;
}

}  // namespace ydry
