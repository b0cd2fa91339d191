// The Newton equilibrium solver (ycore/solid/newton.h, tangent.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "tests/test_support.h"
#include "ycore/contact/contact_tangent.h"
#include "ycore/driver/coupling.h"
#include "ycore/driver/setup.h"
#include "ycore/solid/joint_law.h"
#include "ycore/solid/newton.h"
#include "ycore/solid/relaxation.h"
#include "ycore/solid/solid_forces.h"
#include "ycore/solid/stiffness_model.h"
#include "ycore/solid/tangent.h"

using namespace ydry;

namespace {

// The shrinkage block of paper section 4.3 (verification/shrinkage) as a new user would write
// it: the deck format's defaults for every solver control (penalty 1000 E, tolerance 1e-7),
// drying from its top at a constant rate, so that the solid relaxes after each of many
// moisture steps.
Deck drying_block(const std::vector<std::string>& sets) {
  std::vector<std::string> all = {"mesh.element_size=0.004", "run.end_time=2000", "run.output_interval=1000", "solver.max_coupling_step=50",
                                  "materials.soil.initial_moisture=1.0",
                                  "moisture.boundary=[{on = \"top\", type = \"flux\", rate = -1e-4}]"};
  all.insert(all.end(), sets.begin(), sets.end());
  return load_deck(YDRY_SOURCE_DIR "/verification/shrinkage/shrinkage.toml", all);
}

}  // namespace

TEST_CASE("Newton brings a drying elastic block to equilibrium in a few iterations a relaxation, "
          "at the damped relaxation's equilibrium", "[newton]") {
  State results[2];
  for (const char* method : {"viscous", "newton"}) {
    INFO(method);
    const Deck deck = drying_block({std::string("solver.relaxation=\"") + method + "\""});
    State& s = results[method[0] == 'n'];
    s = setup_state(deck);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    REQUIRE(s.coupling_steps > 10);
    CHECK(s.mechanics.capped_relaxations == 0);
    CHECK(s.mechanics.worst_residual <= 1e-7);
  }
  const State& newton = results[1];
  const double relaxations = double(newton.coupling_steps + 1);  // and the initial equilibrium
  CHECK(double(newton.mechanics.steps) <= 20.0 * relaxations);
  CHECK(newton.mechanics.newton_fallbacks == 0);
  // The same equilibrium: the displacements agree to 1e-4 of the largest. Both end where the
  // out-of-balance force is at most ten times what the coordinates' round-off makes through the
  // 1000 E joint penalties (the round-off floor); measured 9.5e-6.
  const Nodes& a = results[0].nodes;
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, std::hypot(a.x[i] - a.x0[i], a.y[i] - a.y0[i]));
    difference = std::max(difference, std::hypot(a.x[i] - newton.nodes.x[i], a.y[i] - newton.nodes.y[i]));
  }
  CHECK(difference <= 1e-4 * largest);
}

TEST_CASE("the tangent is the derivative of the element and joint forces: K du predicts the change of force",
          "[newton]") {
  // A deformed, cracking layer (joints on every branch of their law): from its state, a small
  // move du of every free component changes the element and joint forces by -K du, up to
  // terms of second order in du and to what symmetrising K leaves out (the shear strength's
  // rise with compression, tan(phi) of the normal stiffness at joints sheared near their
  // peak). So the relative error e(du) = |change + K du| / |K du| falls as du halves, and
  // extrapolated to du -> 0 (2 e(du/2) - e(du)) it is the asymmetric part alone, a small
  // share of K. Measured: 1.5e-2 and 0.91e-2 at du and du/2, so 3.6e-3 at du -> 0.
  const Deck deck = load_deck(ydry_test::kPeronDeck, ydry_test::kCrackingLayer);
  State s = setup_state(deck);
  advance_to(s, deck, 2000.0, coupling_step_limit(s, deck));
  const FreeComponents free = free_components(s.nodes, s.triangles, s.materials);
  const Eigen::SparseMatrix<double> K = tangent_stiffness(s.nodes, s.triangles, s.joints, s.mechanics, s.materials, free,
                                                                JointFrictionTangent::derived);
  // The forces of the elements and joints alone, at the free components.
  const auto forces = [&](const State& at) {
    State t = at;
    t.contact.penalty_pa = 0.0;  // contact is not in the tangent
    t.mechanics.gravity_x = t.mechanics.gravity_y = 0.0;
    compute_forces(t);
    Eigen::VectorXd f(Eigen::Index(free.size()));
    for (std::size_t u = 0; u < free.size(); ++u) {
      const index_t c = free.component[u];
      f[Eigen::Index(u)] = c % 2 == 0 ? t.nodes.fx[c / 2] : t.nodes.fy[c / 2];
    }
    return f;
  };
  Eigen::VectorXd du(Eigen::Index(free.size()));
  for (std::size_t u = 0; u < free.size(); ++u) du[Eigen::Index(u)] = 1e-9 * std::sin(0.7 * double(u));
  double error[2];
  for (const double scale : {1.0, 0.5}) {
    State moved = s;
    for (std::size_t u = 0; u < free.size(); ++u) {
      const index_t c = free.component[u];
      (c % 2 == 0 ? moved.nodes.x : moved.nodes.y)[c / 2] += scale * du[Eigen::Index(u)];
    }
    const Eigen::VectorXd change = forces(moved) - forces(s);
    const Eigen::VectorXd predicted = -(K * (scale * du));
    error[scale < 1.0] = (change - predicted).norm() / predicted.norm();
  }
  CHECK(error[1] < error[0]);
  CHECK(2.0 * error[1] - error[0] <= 1e-2);
}

TEST_CASE("the tangent holds a compressed joint's mode II strength, without the saddle that its derivative makes",
          "[newton]") {
  // A triangle of the block slid along a neighbour across their joint, pressed against it by
  // the joint's peak opening and sheared to 1.5 times its mode II peak slip: every point of the
  // joint past its peak under compression. Derived, the strength's rise with compression,
  // tan(phi) times the normal stiffness, stands in the shear row alone, and symmetrised it gives
  // the joint's nodes a negative stiffness of a few per cent of the penalty's; held, the block of
  // those nodes stays positive definite (the shear's softening past its peak is gentle).
  // Measured: the smallest eigenvalue over the largest, -0.0225 derived, +3.0e-4 held.
  State s = prepare_state(drying_block({"materials.soil.breakable=true", "materials.soil.tensile_strength=1000.0",
                                        "materials.soil.cohesion=2000.0", "materials.soil.friction_angle=30.0",
                                        "materials.soil.gf_I=1.0", "materials.soil.gf_II=10.0"}));
  const std::size_t j = s.joints.size() / 2;
  const index_t* node = &s.joints.node[4 * j];
  const MaterialModel& m = s.materials[s.joints.law[j]];
  const JointKinematics before = joint_kinematics(s.nodes, node);
  const double k = m.penalty / s.joints.length0[j], peak_opening = 2.0 * m.tensile_strength / k;
  const double compression = k * peak_opening, peak_slip = 2.0 * (m.cohesion + compression * m.tan_friction) / k;
  const double close = -peak_opening, slide = 1.5 * peak_slip;  // the first triangle's move along n and t
  const double tx = before.ny, ty = -before.nx;  // the joint's axis (joint_frame: n = (-t_y, t_x))
  const index_t first = triangle_of(node[0]);
  for (int c = 0; c < 3; ++c) {
    const index_t i = corner_node(first, c);
    s.nodes.x[i] += close * before.nx + slide * tx;
    s.nodes.y[i] += close * before.ny + slide * ty;
  }
  const JointKinematics moved = joint_kinematics(s.nodes, node);
  REQUIRE(std::fabs(moved.opening[0] - before.opening[0] - close) < 1e-3 * peak_opening);
  REQUIRE(std::fabs(std::fabs(moved.slip[0] - before.slip[0]) - slide) < 1e-3 * peak_slip);
  const FreeComponents free = free_components(s.nodes, s.triangles, s.materials);
  // The smallest eigenvalue of the block of the joint's free components over the largest.
  const auto smallest_over_largest = [&](JointFrictionTangent friction) {
    const Eigen::MatrixXd K(tangent_stiffness(s.nodes, s.triangles, s.joints, s.mechanics, s.materials, free, friction));
    std::vector<Eigen::Index> rows;
    for (int c = 0; c < 8; ++c)
      if (const index_t u = free.unknown[2 * std::size_t(node[c / 2]) + c % 2]; u != kNoIndex) rows.push_back(u);
    Eigen::MatrixXd block(rows.size(), rows.size());
    for (std::size_t a = 0; a < rows.size(); ++a)
      for (std::size_t b = 0; b < rows.size(); ++b) block(a, b) = K(rows[a], rows[b]);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(block).eigenvalues();
    return eigenvalues.minCoeff() / eigenvalues.maxCoeff();
  };
  const double derived = smallest_over_largest(JointFrictionTangent::derived);
  const double held = smallest_over_largest(JointFrictionTangent::held);
  INFO("derived " << derived << ", held " << held);
  CHECK(derived < -0.01);
  CHECK(held > -1e-4);
}

TEST_CASE("a cracking run relaxed by Newton ends in a bitwise identical state on 1 and 2 threads",
          "[newton][threads]") {
  std::vector<std::string> sets = ydry_test::kCrackingLayer;
  sets.push_back("solver.relaxation=\"newton\"");
  const Deck deck = load_deck(ydry_test::kPeronDeck, sets);
  ydry_test::Snapshot state[2];
  ydry_test::on_1_and_2_threads([&](int threads) {
    State s = setup_state(deck);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    state[threads - 1] = ydry_test::state_snapshot(s);
  });
  const std::vector<double>& broken = state[0]["joints.broken"];
  CHECK(std::count(broken.begin(), broken.end(), 1.0) >= 1);
  for (const auto& [name, values] : state[0]) {
    INFO(name);
    CHECK(ydry_test::same_bits(values, state[1][name]));
  }
}

// Newton keeps the matrix of the step that converged (mechanics.chord_*), and the relaxations
// after it start with chord steps on its factor (doc/solver.md "Quasi-static equilibrium"):
// the drying block's later relaxations need no new matrix, and reach the equilibrium that a
// Newton relaxation without the kept factor reaches.
TEST_CASE("a drying elastic block's later relaxations are served by the factor Newton kept, at the same equilibrium",
          "[newton]") {
  const Deck deck = drying_block({});
  State served = setup_state(deck);
  const double limit = coupling_step_limit(served, deck);
  advance_to(served, deck, 500.0, limit);
  REQUIRE_FALSE(served.mechanics.chord_values.empty());
  State fresh = served;  // the same state without the kept matrix
  for (auto* v : {&fresh.mechanics.chord_components, &fresh.mechanics.chord_outer, &fresh.mechanics.chord_inner})
    v->clear();
  fresh.mechanics.chord_values.clear();
  fresh.mechanics.chord_factor.reset();
  const std::vector<double> kept = served.mechanics.chord_values;
  const std::uint64_t steps_before = served.coupling_steps;
  advance_to(served, deck, 2000.0, limit);
  advance_to(fresh, deck, 2000.0, limit);
  REQUIRE(served.coupling_steps > steps_before + 10);
  CHECK(served.mechanics.chord_values == kept);  // no relaxation needed a Newton step
  for (const State* s : {&served, &fresh}) {
    CHECK(s->mechanics.newton_fallbacks == 0);
    CHECK(s->mechanics.capped_relaxations == 0);
    CHECK(s->mechanics.worst_residual <= 1e-7);
  }
  // Both balanced to the tolerance: the displacements agree to 1e-4 of the largest.
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < served.nodes.size(); ++i) {
    largest = std::max(largest, std::hypot(fresh.nodes.x[i] - fresh.nodes.x0[i], fresh.nodes.y[i] - fresh.nodes.y0[i]));
    difference = std::max(difference, std::hypot(served.nodes.x[i] - fresh.nodes.x[i], served.nodes.y[i] - fresh.nodes.y[i]));
  }
  CHECK(difference <= 1e-4 * largest);
}

TEST_CASE("the factorisations order by whichever of AMD and METIS fills the mesh's factor less, "
          "and either gives the same equilibrium", "[newton]") {
  // nnz(L) of the symbolic factor of the whole intact mesh's tangent (the elastic state as set
  // up: every joint intact), by the ordering.
  const auto fill = [](const State& s, const FreeComponents& free, auto ordering) {
    using Ordering = decltype(ordering);
    const Eigen::SparseMatrix<double> K = tangent_stiffness(s.nodes, s.triangles, s.joints, s.mechanics, s.materials, free,
                                                                JointFrictionTangent::derived);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Ordering> solver;
    solver.analyzePattern(K);
    return solver.matrixL().nestedExpression().nonZeros();
  };
  // A strip twice as long as high (the drying block) and a square of 4,356 triangles: AMD fills
  // the strip's factor less, METIS the square's (bench/bench_factorisation.cpp).
  for (const char* size : {"[0.1, 0.05]", "[0.1, 0.1]"}) {
    INFO(size);
    State s = prepare_state(drying_block({std::string("mesh.size=") + size, "mesh.element_size=0.003"}));
    const FreeComponents free = free_components(s.nodes, s.triangles, s.materials);
    const auto amd = fill(s, free, Eigen::AMDOrdering<int>()), metis = fill(s, free, Eigen::MetisOrdering<int>());
    REQUIRE(amd != metis);
    CHECK(fill_ordering(s.triangles, s.joints, s.materials, free, s.mechanics) ==
          (metis < amd ? FillOrdering::metis : FillOrdering::amd));
    CHECK(s.mechanics.fill_ordering == (metis < amd ? FillOrdering::metis : FillOrdering::amd));
  }
  // The drying block relaxed with each: the same equilibrium. Both end where the out-of-balance
  // force is within the tolerance of 1e-7 or the round-off floor; measured, the displacements
  // differ by 1.7e-10 of the largest.
  State results[2];
  for (const FillOrdering ordering : {FillOrdering::amd, FillOrdering::metis}) {
    const Deck deck = drying_block({"solver.relaxation=\"newton\""});
    State& s = results[ordering == FillOrdering::metis];
    s = prepare_state(deck);
    s.mechanics.fill_ordering = ordering;
    equilibrate_and_break(s, deck, 0.0);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    REQUIRE(s.mechanics.fill_ordering == ordering);
    CHECK(s.mechanics.newton_fallbacks == 0);
    CHECK(s.mechanics.worst_residual <= 1e-7);
  }
  const Nodes& a = results[0].nodes;
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, std::hypot(a.x[i] - a.x0[i], a.y[i] - a.y0[i]));
    difference = std::max(difference, std::hypot(a.x[i] - results[1].nodes.x[i], a.y[i] - results[1].nodes.y[i]));
  }
  CHECK(difference <= 1e-8 * largest);
}

TEST_CASE("a contact link whose state alternates in the active set's rounds is held as the force kernel has it",
          "[newton]") {
  // A corner (node 0) over the middle of an edge from node 1 to node 2 along x, whose outward
  // normal is -y: a step that moves the corner up by more than its gap closes the link.
  ContactLink link{};
  link.receivers[0] = 0, link.receivers[1] = 1, link.receivers[2] = 2;
  link.share[0] = 1.0, link.share[1] = -0.5, link.share[2] = -0.5;
  link.tx = 1.0, link.ty = 0.0, link.stiffness = 1e6, link.length = 1e-3;
  const std::vector<index_t> unknown = {0, 1, 2, 3, 4, 5};
  Eigen::VectorXd closing = Eigen::VectorXd::Zero(6), opening = Eigen::VectorXd::Zero(6);
  closing[1] = 1e-9, opening[1] = -1e-9;
  // The rounds' steps close, open and close again the link of a corner 1e-10 m outside its edge
  // (no force: it rests on it), then open, close and open that of a corner pressing 1e-10 m.
  for (const bool pressing : {false, true}) {
    INFO("pressing " << pressing);
    link.gap = pressing ? -1e-10 : 1e-10, link.pressing = pressing;
    const std::vector<ContactLink> links = {link};
    std::vector<std::uint8_t> active = {std::uint8_t(pressing)}, changes = {0};
    const Eigen::VectorXd& first = pressing ? opening : closing;
    const Eigen::VectorXd& second = pressing ? closing : opening;
    CHECK(update_active_links(links, first, unknown, changes, active) == 1);  // the step's choice
    CHECK(active[0] == std::uint8_t(!pressing));
    CHECK(update_active_links(links, second, unknown, changes, active) == 1);  // a second change: held
    CHECK(active[0] == std::uint8_t(pressing));
    CHECK(update_active_links(links, first, unknown, changes, active) == 0);  // held as it presses
    CHECK(active[0] == std::uint8_t(pressing));
  }
}

TEST_CASE("Newton judges the state at rest: the dashpot's push against a predicted jump does not unbalance a "
          "balanced block", "[newton]") {
  // The block of verification/contact_rest, balanced on its base by the initial equilibrium.
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {});
  State s = setup_state(deck);
  const RelaxationControls controls{deck.relaxation_tolerance, deck.relaxation_max_steps, RelaxationMethod::newton,
                                    deck.relaxation_slide_after, nullptr};
  // Balanced as Newton and the relaxations judge it: to the tolerance, or to the round-off floor.
  const auto balanced = [&](const ForceMeasures& m) {
    return m.net2 <= s.mechanics.roundoff_net2 || m.ratio() <= controls.tolerance;
  };
  REQUIRE(balanced(compute_forces(s)));
  // A relaxation's first evaluation sees the predicted jump as a velocity: the block falling at
  // 1 mm/s onto its base, which the contact's dashpot resists.
  const FreeComponents free = free_components(s.nodes, s.triangles, s.materials);
  for (const index_t c : free.component)
    if (c % 2 == 1) s.nodes.vy[std::size_t(c / 2)] = -1e-3;
  const ForceMeasures pushed = compute_forces(s);
  REQUIRE(pushed.net2 > 100.0 * s.mechanics.roundoff_net2);
  REQUIRE(pushed.ratio() > 100.0 * controls.tolerance);
  std::fill(s.nodes.vy.begin(), s.nodes.vy.end(), 0.0);  // relax() starts Newton at rest
  const NewtonOutcome outcome = newton_equilibrium(s, controls, s.joints.work);
  CHECK(outcome.converged);
  CHECK(outcome.iterations == 0);
}
