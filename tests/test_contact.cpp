// Contact: two triangles whose common joint broke press on each other through their faces;
// with the joint intact they never touch.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>

#include "tests/test_support.h"
#include "ycore/contact/contact_forces.h"
#include "ycore/contact/contact_geometry.h"
#include "ycore/contact/contact_setup.h"
#include "ycore/solid/relaxation.h"
#include "ycore/solid/solid_forces.h"
#include "ycore/driver/coupling.h"
#include "ycore/driver/setup.h"
#include "ycrack/node_sharing.h"

using namespace ydry;

namespace {

constexpr double kPenalty = 1.0e7, kThickness = 0.5;  // as two_triangles sets them

// One 1 mm cell cut by its diagonal: two triangles tied by one joint, no gravity.
State two_triangles(ydry_test::TempDir& dir) {
  State s = setup_state(ydry_test::block_deck(
      dir, "right", {"mesh.size=[0.001, 0.001]", "run.thickness=0.5", "contact.penalty=1.0e7",
                     "contact.friction.soil_soil=30.0"}));
  REQUIRE(s.joints.size() == 1);
  return s;
}

void break_joint(State& s) {
  s.joints.broken[0] = 1;
  tie_corners(s.joints, s.nodes);
  refresh_contact_surfaces(s.nodes, s.joints, s.contact);
}

// The joint's face on its first triangle: from node 0 to node 1, outward normal (ty, -tx).
struct Face { double tx, ty, length; };
Face first_face(const State& s) {
  const index_t a = s.joints.node[0], b = s.joints.node[1];
  const double ex = s.nodes.x[b] - s.nodes.x[a], ey = s.nodes.y[b] - s.nodes.y[a];
  const double length = std::hypot(ex, ey);
  return {ex / length, ey / length, length};
}

// Moves the second triangle (nodes 2 and 3 of the joint are two of its corners) by (dx, dy).
void move_second_triangle(State& s, double dx, double dy) {
  const index_t t = triangle_of(s.joints.node[2]);
  for (int a = 0; a < 3; ++a) {
    s.nodes.x[corner_node(t, a)] += dx;
    s.nodes.y[corner_node(t, a)] += dy;
  }
}

// The force on `corner` from its own contact (slot 0 of its active pair), as (normal to
// the face, along the face).
std::pair<double, double> pressed_corner_force(const State& s, index_t corner, const Face& face) {
  const Contact& c = s.contact;
  double fx = 0, fy = 0;
  for (std::size_t p = 0; p < c.pair_node.size(); ++p)
    if (c.pair_node[p] == corner) fx += c.pair_force[6 * p], fy += c.pair_force[6 * p + 1];
  return {fx * face.ty - fy * face.tx, fx * face.tx + fy * face.ty};
}

// The joint broken, the second triangle slid 10 % along the face and pressed `depth` into the
// first: its corner at the face's start (joint node 3) lies inside the first triangle's face.
Face press_through_broken_joint(State& s, double depth) {
  break_joint(s);
  const Face face = first_face(s);
  move_second_triangle(s, 0.1 * face.length * face.tx - depth * face.ty, 0.1 * face.length * face.ty + depth * face.tx);
  return face;
}

// Contact force on every node (the gather of the relaxation, contact only).
std::vector<double> contact_force_on_nodes(const State& s) {
  const Contact& c = s.contact;
  std::vector<double> f(2 * s.nodes.size(), 0.0);
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    for (index_t k = c.gather_offset[i]; k < c.gather_offset[i + 1]; ++k)
      for (int d = 0; d < 2; ++d) f[2 * i + d] += c.pair_force[2 * std::size_t(c.gather_entry[k]) + d];
  return f;
}

// The contact's phases as an explicit step takes them (explicit_step, ycore/solid/solid_forces.h):
// the pairs, the slip advanced over dt, the forces, the work over dt, and the slip committed
// unless it slides only at equilibrium.
void contact_step(State& s, Contact& c, double dt, FrictionUpdate friction = FrictionUpdate::every_step) {
  update_contact_pairs(s.nodes, s.ownership, c);
  std::vector<double> before;
  keep_contact_forces(c, before);
  advance_friction_slip(s.nodes, dt, c);
  contact_forces(s.nodes, s.triangles, s.mechanics, c, s.material_names.size(), c.pair_force);
  book_contact_work(s.nodes, before, dt, c);
  if (friction == FrictionUpdate::every_step)
    commit_friction_slip(s.nodes, s.triangles, s.mechanics, s.material_names.size(), c);
}

}  // namespace

TEST_CASE("two triangles pressed through a broken joint's faces: p_n t g per corner, momentum conserved",
          "[contact]") {
  ydry_test::TempDir dir;
  State s = two_triangles(dir);
  const double depth = 1.0e-6;
  const Face face = press_through_broken_joint(s, depth);
  contact_step(s, s.contact, 0.0);
  const std::vector<double> f = contact_force_on_nodes(s);

  double sum_x = 0, sum_y = 0, largest = 0;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    sum_x += f[2 * i], sum_y += f[2 * i + 1];
    largest = std::max(largest, std::hypot(f[2 * i], f[2 * i + 1]));
  }
  CHECK(largest > 0.0);
  CHECK(std::fabs(sum_x) <= 1e-12 * largest);
  CHECK(std::fabs(sum_y) <= 1e-12 * largest);
  // The pressed corner has two surface edges: p_n t / 2 each, pushing it out along the normal.
  // (The first triangle's corner at the face's end is pressed into the second's face too.)
  const auto [normal, tangential] = pressed_corner_force(s, s.joints.node[3], face);
  const double expected = kPenalty * kThickness * depth;
  CHECK(normal == Approx(expected).epsilon(1e-9));
  CHECK(std::fabs(tangential) <= 1e-12 * expected);  // no friction at rest
}

TEST_CASE("sliding faces: the friction force opposes the slip and stops at tan(phi) x the normal force",
          "[contact]") {
  ydry_test::TempDir dir;
  State s = two_triangles(dir);
  const double depth = 1.0e-6;
  const Face face = press_through_broken_joint(s, depth);
  // The second triangle slides along the face at 1 mm/s; each step of 1e-6 s slips 1 nm.
  const index_t t = triangle_of(s.joints.node[2]);
  for (int a = 0; a < 3; ++a) {
    s.nodes.vx[corner_node(t, a)] = 1e-3 * face.tx;
    s.nodes.vy[corner_node(t, a)] = 1e-3 * face.ty;
  }
  const index_t corner = s.joints.node[3];
  const double normal = kPenalty * kThickness * depth, cap = std::tan(30.0 * M_PI / 180.0) * normal;
  // One step: the elastic slip of 1 nm is below the cap.
  contact_step(s, s.contact, 1e-6);
  CHECK(pressed_corner_force(s, corner, face).second == Approx(-kPenalty * kThickness * 1e-9).epsilon(1e-6));
  for (int step = 0; step < 1000; ++step)  // 1 um more: sliding
    contact_step(s, s.contact, 1e-6);
  CHECK(pressed_corner_force(s, corner, face).second == Approx(-cap).epsilon(1e-9));
  CHECK(pressed_corner_force(s, corner, face).first == Approx(normal).epsilon(1e-9));
  CHECK(s.contact.work_J > 0.0);  // friction took work out of the sliding
}

// The block at rest on its base (verification/contact_rest) is meshed like the base, so the
// corners of its bottom sit on junctions of two base edges. Moved 3 nm to the right, each
// stuck corner's friction changes by its stiffness x 3 nm, whether or not its contact passed
// to the next base edge.
TEST_CASE("a corner's friction spring stretches with its slip, on one edge or shared by two at a junction", "[contact]") {
  State s = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  const Contact& c = s.contact;
  // Free corner -> its pairs with a force, against the base (two where it lies within the
  // taper of a junction of two edges).
  const auto carrying_pairs = [&] {
    std::map<index_t, std::vector<std::size_t>> carrying;
    for (std::size_t p = 0; p < c.pair_node.size(); ++p)
      if (!s.nodes.constraint[c.pair_node[p]] && (c.pair_force[6 * p] != 0.0 || c.pair_force[6 * p + 1] != 0.0))
        carrying[c.pair_node[p]].push_back(p);
    return carrying;
  };
  const auto along_base = [&](std::size_t p, double fx, double fy) {  // the base's top runs right to left
    const index_t e = c.pair_edge[p], f = next_corner(e);
    const double tx = s.nodes.x[f] - s.nodes.x[e], ty = s.nodes.y[f] - s.nodes.y[e];
    return (fx * tx + fy * ty) / std::hypot(tx, ty);
  };
  const auto tangential = [&](const std::vector<std::size_t>& pairs) {
    double sum = 0.0;
    for (const std::size_t p : pairs) sum += along_base(p, c.pair_force[6 * p], c.pair_force[6 * p + 1]);
    return sum;
  };
  const auto normal = [&](const std::vector<std::size_t>& pairs) {
    double sum = 0.0;
    for (const std::size_t p : pairs) sum += std::hypot(c.pair_force[6 * p], c.pair_force[6 * p + 1]);
    return sum;
  };
  contact_step(s, s.contact, 0.0, FrictionUpdate::at_equilibrium);
  const auto before = carrying_pairs();
  std::map<index_t, double> friction_before;
  for (const auto& [corner, pairs] : before) friction_before[corner] = tangential(pairs);

  constexpr double move = 3e-9, kStep = 1.0;  // m, s
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (!s.nodes.constraint[i]) s.nodes.x[i] += move, s.nodes.vx[i] = move / kStep;
  contact_step(s, s.contact, kStep, FrictionUpdate::at_equilibrium);
  const auto after = carrying_pairs();
  REQUIRE(after.size() == before.size());
  int checked = 0, shared = 0;
  for (const auto& [corner, pairs] : after) {
    const double stiffness =
        0.5 * c.penalty_pa * s.mechanics.thickness_m * (c.is_surface_edge[corner] + c.is_surface_edge[previous_corner(corner)]);
    // The slip along the edges grows by -move; the spring pulls against it.
    const double expected = friction_before[corner] + stiffness * move;
    const double tan_phi = c.tan_friction[s.triangles.material[triangle_of(corner)] * s.material_names.size() +
                                          s.triangles.material[triangle_of(c.pair_edge[pairs[0]])]];
    if (std::fabs(expected) > 0.9 * tan_phi * normal(pairs)) continue;  // near its cap: it may slide
    ++checked;
    shared += pairs.size() == 2;
    CHECK(tangential(pairs) == Approx(expected).epsilon(1e-6));
  }
  CHECK(checked > 10);
  CHECK(shared >= 2);  // corners at junctions, carried by two edges, were among the checked
}

// The base of verification/contact_rest is a rigid rectangle: its corners on the straight
// top and sides receive contact but do not make it (the block's corners do, and see one
// straight surface), while its four convex corners, which could press into the block's side,
// still test themselves against the block's edges; every surface corner of the block does.
TEST_CASE("a rigid body's corners on a straight side are only receivers of contact; its convex corners and every free corner are contactors",
          "[contact]") {
  const State s = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  const Nodes& n = s.nodes;
  const Contact& c = s.contact;
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (std::size_t i = 0; i < n.size(); ++i)
    if (n.constraint[i]) xmin = std::min(xmin, n.x0[i]), xmax = std::max(xmax, n.x0[i]),
                         ymin = std::min(ymin, n.y0[i]), ymax = std::max(ymax, n.y0[i]);
  const auto base_corner = [&](index_t i) {  // of the rectangle
    return (n.x0[i] == xmin || n.x0[i] == xmax) && (n.y0[i] == ymin || n.y0[i] == ymax);
  };
  int flat = 0, convex = 0, free = 0;
  for (index_t i = 0; i < index_t(n.size()); ++i) {
    if (!(c.is_surface_edge[i] || c.is_surface_edge[previous_corner(i)])) continue;
    const bool contactor = std::binary_search(c.surface_node.begin(), c.surface_node.end(), i);
    if (!n.constraint[i]) {
      ++free;
      CHECK(contactor);
    } else if (base_corner(i)) {
      ++convex;
      CHECK(contactor);
    } else {
      ++flat;
      CHECK_FALSE(contactor);
    }
  }
  CHECK(convex >= 4);
  CHECK(flat > 10);  // the top alone has 15 vertices between its ends
  CHECK(free > 10);
}

TEST_CASE("no contact force between triangles still tied by an intact joint, however they overlap or slide along it",
          "[contact]") {
  // Pressed 10 um through each other, or slid 90 % of the joint's length along it (as a
  // softening mode II joint lets them): each triangle's corner then lies 0.1 mm inside the
  // other's side, past that side's end by nothing, which only the joint may carry.
  for (const auto& [slide, overlap] : {std::pair{0.1, 1e-5}, std::pair{0.9, 0.0}}) {
    ydry_test::TempDir dir;
    State s = two_triangles(dir);
    const Face face = first_face(s);
    move_second_triangle(s, slide * face.length * face.tx - overlap * face.ty, slide * face.length * face.ty + overlap * face.tx);
    contact_step(s, s.contact, 0.0);
    for (const double f : contact_force_on_nodes(s)) CHECK(f == 0.0);
    // Both triangles' corners are surface corners (three outer edges each), yet no pair
    // joins corners of one tie group.
    for (std::size_t p = 0; p < s.contact.pair_node.size(); ++p) {
      const index_t i = s.contact.pair_node[p], e = s.contact.pair_edge[p];
      CHECK(s.nodes.tie_group[i] != s.nodes.tie_group[e]);
      CHECK(s.nodes.tie_group[i] != s.nodes.tie_group[next_corner(e)]);
    }
  }
}

TEST_CASE("a block settling on a rigid base through contact is bitwise the same on 1 and 2 threads",
          "[contact][threads]") {
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {});
  std::vector<double> x[2], work(2);
  ydry_test::on_1_and_2_threads([&](int threads) {
    const State s = setup_state(deck);
    x[threads - 1] = s.nodes.y;
    work[threads - 1] = s.contact.work_J;
  });
  CHECK(x[0] == x[1]);
  CHECK(work[0] == work[1]);
  CHECK(work[0] > 0.0);  // the contacts did carry the block
}

// doc/solver.md "One evaluation, in phases": evaluating the forces of a configuration changes
// only the forces. The block at rest on its base (contacts pressing, friction stretched) is
// shaken by a micron with velocities: an evaluation leaves every field of the history,
// topology and totals as it was but the forces, and a second one gives the same forces.
TEST_CASE("compute_forces writes the forces only, and the same forces again", "[contact]") {
  State s = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  std::mt19937 rng(5);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    if (s.nodes.constraint[i]) continue;
    s.nodes.x[i] += 1e-6 * unit(rng), s.nodes.y[i] += 1e-6 * unit(rng);
    s.nodes.vx[i] = 1e-3 * unit(rng), s.nodes.vy[i] = 1e-3 * unit(rng);
  }
  update_contact_pairs(s.nodes, s.ownership, s.contact);
  advance_friction_slip(s.nodes, 1e-3, s.contact);
  ydry_test::Snapshot before = ydry_test::state_snapshot(s);
  compute_forces(s);
  ydry_test::Snapshot after = ydry_test::state_snapshot(s);
  const std::vector<double> joint_force = s.joints.force, pair_force = s.contact.pair_force, fx = s.nodes.fx;
  CHECK(std::count_if(pair_force.begin(), pair_force.end(), [](double f) { return f != 0.0; }) > 100);
  for (const char* force : {"joints.force", "contact.pair_force"}) before.erase(force), after.erase(force);
  CHECK(before == after);
  compute_forces(s);
  CHECK(ydry_test::same_bits(s.joints.force, joint_force));
  CHECK(ydry_test::same_bits(s.contact.pair_force, pair_force));
  CHECK(ydry_test::same_bits(s.nodes.fx, fx));
}

// The ratchet of an extrapolated start (ycore/solid/relaxation.cpp, predict_equilibrium): the block
// at rest on its base is given a last motion of 0.1 mm to the right, which the relaxation
// extrapolates, so it starts 0.1 mm away with every contact slipped. Nothing drives it
// there: the friction, which slides only at equilibrium, pulls it back to where it rested.
// So it does with solver.relaxation_slide_after = 0 (never). With 1 (doc/solver.md "Friction
// that stalls") the friction slides from the first pseudo-step, nothing pulls the block back,
// and it stays nearly the whole carry away; that relaxation is counted.
TEST_CASE("a block carried off its rest by the extrapolated start is pulled back by its friction, "
          "unless the friction slides at every step past solver.relaxation_slide_after",
          "[contact][mechanics]") {
  const State rest = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  constexpr double kCarry = 1e-4, kCouplingStep = 1.0;  // m, s
  for (const RelaxationMethod method : {RelaxationMethod::viscous, RelaxationMethod::fire}) {
    for (const std::int64_t slide_after : {std::int64_t(20000), std::int64_t(0), std::int64_t(1)}) {
      INFO("relaxation " << (method == RelaxationMethod::fire ? "fire" : "viscous") << ", slide after " << slide_after);
      State s = rest;
      for (std::size_t i = 0; i < s.nodes.size(); ++i)
        if (!(s.nodes.constraint[i] & kFixX)) s.nodes.vx[i] = kCarry / kCouplingStep;
      const RelaxationResult result = relax(s, RelaxationControls{1e-9, 200000, method, slide_after}, kCouplingStep);
      REQUIRE_FALSE(result.capped);
      const bool slid = slide_after == 1;
      CHECK(s.mechanics.friction_slide_relaxations == rest.mechanics.friction_slide_relaxations + (slid ? 1 : 0));
      double nearest = kCarry, farthest = 0.0;  // of the free nodes, from their rest
      for (std::size_t i = 0; i < s.nodes.size(); ++i) {
        if (s.nodes.constraint[i] & kFixX) continue;
        nearest = std::min(nearest, std::fabs(s.nodes.x[i] - rest.nodes.x[i]));
        farthest = std::max(farthest, std::fabs(s.nodes.x[i] - rest.nodes.x[i]));
      }
      if (slid)
        CHECK(nearest > 0.99 * kCarry);
      else
        CHECK(farthest < 1e-3 * kCarry);
    }
  }
}

// A falling motion is not extrapolated past the contact buffer (ycore/solid/relaxation.cpp,
// predict_equilibrium): the block at rest on its base is given a last motion of 0.2 m down,
// four times the base's depth. Extrapolated whole, the jump would put the block below the
// base, which no contact would then hold, and it would fall on; limited to the buffer, it
// starts a buffer deep in the base and the contacts push it back onto the base's top. (Where
// along the top it comes to rest, within microns, is the friction's business.)
TEST_CASE("a block whose last motion was a fall is not carried through the rigid base it falls onto",
          "[contact][mechanics]") {
  const State rest = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  constexpr double kFall = 0.2, kCouplingStep = 1.0;  // m, s
  State s = rest;
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (!(s.nodes.constraint[i] & kFixY)) s.nodes.vy[i] = -kFall / kCouplingStep;
  const RelaxationResult result = relax(s, RelaxationControls{1e-9, 200000, RelaxationMethod::fire}, kCouplingStep);
  CHECK_FALSE(result.capped);  // a block that fell through would never balance
  double bottom = INFINITY, bottom_at_rest = INFINITY;
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (!(s.nodes.constraint[i] & kFixY)) {
      bottom = std::min(bottom, s.nodes.y[i]);
      bottom_at_rest = std::min(bottom_at_rest, rest.nodes.y[i]);
    }
  CHECK(std::fabs(bottom - bottom_at_rest) < 1e-3 * s.contact.buffer_m);
}

// A relaxation that runs on tells its step count and ratio every kRelaxationReportSteps steps
// (the progress line shows them), and telling changes nothing: the falling block above, with
// and without a listener, reaches the same positions bit for bit.
TEST_CASE("a long relaxation reports its steps and ratio every kRelaxationReportSteps explicit steps and after every Newton step, and the reports change nothing",
          "[contact][mechanics]") {
  State quiet = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  for (std::size_t i = 0; i < quiet.nodes.size(); ++i)
    if (!(quiet.nodes.constraint[i] & kFixY)) quiet.nodes.vy[i] = -0.2;
  State told = quiet;
  RelaxationControls controls{1e-9, 200000, RelaxationMethod::fire};
  const RelaxationResult unreported = relax(quiet, controls, 1.0);
  std::vector<std::pair<std::int64_t, double>> reports;
  controls.report = [&](std::int64_t steps, double residual) { reports.emplace_back(steps, residual); };
  const RelaxationResult reported = relax(told, controls, 1.0);
  REQUIRE(reported.steps >= 2 * kRelaxationReportSteps);  // long enough to report
  CHECK(reported.steps == unreported.steps);
  CHECK(told.nodes.x == quiet.nodes.x);
  CHECK(told.nodes.y == quiet.nodes.y);
  REQUIRE(reports.size() == std::size_t(reported.steps / kRelaxationReportSteps));
  for (std::size_t k = 0; k < reports.size(); ++k) {
    CHECK(reports[k].first == std::int64_t(k + 1) * kRelaxationReportSteps);
    CHECK(reports[k].second > controls.tolerance);  // still out of balance when it told
  }
  // Newton reports after each of its steps that leaves a relaxation out of balance: the mode I
  // bar pulled apart, whose softening relaxations take several.
  const Deck bar = load_deck(YDRY_SOURCE_DIR "/verification/fracture_modeI/fracture_modeI.toml", {});
  State bar_quiet = setup_state(bar), bar_told = bar_quiet;
  advance_to(bar_quiet, bar, bar.end_time_s, coupling_step_limit(bar_quiet, bar));
  reports.clear();
  advance_to(bar_told, bar, bar.end_time_s, coupling_step_limit(bar_told, bar), nullptr, controls.report);
  CHECK(bar_told.nodes.x == bar_quiet.nodes.x);
  CHECK(bar_told.mechanics.steps == bar_quiet.mechanics.steps);
  CHECK(reports.size() >= 10);
  for (const auto& [steps, residual] : reports) CHECK(residual > bar.relaxation_tolerance);
}

// The contact kernel skips a corner that clearly_outside finds outside all its edges
// (contact_forces.cpp, idle_corner), which leaves the forces bit for bit as they were only if
// project() would have found it outside too (gap > 0, so no touch). Corners on the line of an
// edge and from 1e-19 to 1e-6 of its length either side, edges of 1 um to 10 cm at any angle
// and anywhere in a 30 cm domain: the shortcut never says outside where project() does not,
// and it does say outside for every corner more than 1e-9 of the edge's length out (the
// coordinates' own round-off, 0.3 m x 1.1e-16, is 3e-11 of a 1 um edge: nearer than that the
// corner's side of the line is not known to either).
TEST_CASE("a corner the contact kernel skips as clearly outside its edge is outside by the projection too",
          "[contact]") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Nodes n;
  n.x.assign(6, 0.0);
  n.y.assign(6, 0.0);
  constexpr index_t kEdge = 0, kCorner = 3;  // edge 0 -> 1 of triangle 0, a corner of triangle 1
  int skipped = 0, inside_or_on = 0, unsure = 0;
  for (int sample = 0; sample < 400000; ++sample) {
    const double length = std::pow(10.0, -6.0 + 5.0 * unit(rng)), angle = 2.0 * M_PI * unit(rng);
    const double tx = std::cos(angle), ty = std::sin(angle);
    n.x[0] = 0.3 * unit(rng), n.y[0] = -0.01 + 0.03 * unit(rng);
    n.x[1] = n.x[0] + length * tx, n.y[1] = n.y[0] + length * ty;
    const double along = -0.5 + 2.0 * unit(rng);
    const double depth = sample % 4 == 0 ? 0.0 : std::copysign(length * std::pow(10.0, -19.0 + 13.0 * unit(rng)), unit(rng) - 0.5);
    n.x[kCorner] = n.x[0] + along * length * tx + depth * ty;  // outward normal (ty, -tx)
    n.y[kCorner] = n.y[0] + along * length * ty - depth * tx;
    const bool outside = clearly_outside(n, kCorner, kEdge);
    const double gap = project(n, kCorner, kEdge).gap;
    if (outside) {
      ++skipped;
      if (!(gap > 0.0)) FAIL("corner at depth " << depth << " of an edge " << length << " m long: gap " << gap);
    } else if (depth > 1e-9 * length) {
      ++unsure;
    } else {
      ++inside_or_on;
    }
  }
  CHECK(unsure == 0);
  CHECK(skipped > 100000);
  CHECK(inside_or_on > 100000);
}

TEST_CASE("a corner sliding across the junction of two edges hands its force from one to the other without a jump",
          "[contact]") {
  State s = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/contact_rest/contact_rest.toml", {}));
  Contact& c = s.contact;
  contact_step(s, c, 0.0);
  // A free corner pressing the base's flat top: the block at rest.
  std::size_t pressing = c.pair_node.size();
  for (std::size_t p = 0; p < c.pair_node.size() && pressing == c.pair_node.size(); ++p)
    if (!s.nodes.constraint[c.pair_node[p]] && c.pair_force[6 * p + 1] > 0.0) pressing = p;
  REQUIRE(pressing < c.pair_node.size());
  const index_t corner = c.pair_node[pressing], e = c.pair_edge[pressing];
  const double length = std::hypot(s.nodes.x[next_corner(e)] - s.nodes.x[e], s.nodes.y[next_corner(e)] - s.nodes.y[e]);
  REQUIRE(std::fabs(s.nodes.y[next_corner(e)] - s.nodes.y[e]) < 1e-12 * length);  // flat
  // Pressed 1 um deep, it slides from 10 % of the edge's length before the junction at the
  // edge's left end (the base's top runs right to left) to 10 % past it, in steps of 0.5 %.
  const double depth = 1e-6, junction = std::min(s.nodes.x[e], s.nodes.x[next_corner(e)]);
  const double stiffness = 0.5 * c.penalty_pa * s.mechanics.thickness_m *
                           (c.is_surface_edge[corner] + c.is_surface_edge[previous_corner(corner)]);
  s.nodes.y[corner] = s.nodes.y[e] - depth;
  // Its friction spring stretched to a third of its cap; it is moved without a velocity, so
  // the slip stays and must pass whole from edge to edge.
  const double tan_phi = c.tan_friction[s.triangles.material[triangle_of(corner)] * s.material_names.size() +
                                        s.triangles.material[triangle_of(e)]];
  for (std::size_t p = 0; p < c.pair_node.size(); ++p) c.pair_slip[p] = p == pressing ? tan_phi * depth / 3.0 : 0.0;
  constexpr int kSteps = 40;
  const double dx = 0.2 * length / kSteps;
  std::map<index_t, std::array<double, 2>> before;
  int shared = 0;
  for (int k = 0; k <= kSteps; ++k) {
    s.nodes.x[corner] = junction + 0.1 * length - k * dx;
    contact_step(s, c, 0.0);
    std::map<index_t, std::array<double, 2>> received;  // force on each node of the base
    double normal = 0.0, friction = 0.0;  // on the corner
    int carrying = 0;
    for (std::size_t p = 0; p < c.pair_node.size(); ++p) {
      if (c.pair_node[p] != corner || c.pair_force[6 * p + 1] == 0.0) continue;
      ++carrying;
      friction += c.pair_force[6 * p], normal += c.pair_force[6 * p + 1];
      for (int end = 0; end < 2; ++end)
        for (int axis = 0; axis < 2; ++axis)
          received[end == 0 ? c.pair_edge[p] : next_corner(c.pair_edge[p])][axis] += c.pair_force[6 * p + 2 + 2 * end + axis];
    }
    INFO("position " << k << " carrying " << carrying);
    shared += carrying == 2;
    // The two edges' shares add to 1: the corner feels the whole penalty force and the whole
    // stretched spring throughout (the base's top runs right to left: the slip pulls right).
    CHECK(normal == Approx(stiffness * depth).epsilon(1e-9));
    CHECK(friction == Approx(stiffness * tan_phi * depth / 3.0).epsilon(1e-9));
    // A base node's share changes by at most the taper's slope times the step.
    if (k > 0) {
      std::map<index_t, std::array<double, 2>> change = received;
      for (const auto& [node, f] : before) change[node][0] -= f[0], change[node][1] -= f[1];
      for (const auto& [node, f] : change)
        CHECK(std::hypot(f[0], f[1]) <=
              std::hypot(1.0, tan_phi / 3.0) * stiffness * depth * (dx / length) / (2.0 * kEndTaper) * (1.0 + 1e-6));
    }
    before = received;
  }
  // Within 5 % of the junction on either side: 19 of the positions, 21 if round-off leaves a
  // share of order 1e-16 at the taper's two ends.
  CHECK(shared >= 19);
  CHECK(shared <= 21);
}
