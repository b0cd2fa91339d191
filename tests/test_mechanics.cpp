// The solid: co-rotational triangles, cohesive joints, the stable step, momentum, and a bar
// under its own weight against its linear-elastic answer.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <utility>

#include "tests/test_support.h"
#include "ycore/state/blocked_sum.h"
#include "ycore/input/input_error.h"
#include "ycore/solid/joint_law.h"
#include "ycore/solid/element_forces.h"
#include "ycore/solid/energies.h"
#include "ycore/solid/joint_forces.h"
#include "ycore/solid/node_integration.h"
#include "ycore/solid/numerical_failure.h"
#include "ycore/solid/relaxation.h"
#include "ycore/solid/stable_step.h"
#include "ycore/driver/setup.h"
#include "ycore/driver/coupling.h"

using namespace ydry;

namespace {

constexpr double kYoung = 1.0e6, kDensity = 1000.0;


// Net nodal forces: elements and gravity, then the joints through each node's slots; and the
// element stresses.
void net_forces(State& s) {
  element_forces(s.triangles, s.mechanics, s.ownership, s.materials, s.nodes);
  element_stresses(s.nodes, s.ownership, s.materials, s.triangles);
  joint_forces(s.nodes, s.mechanics, s.ownership, s.materials, s.joints, s.joints.force);
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      const index_t slot = s.nodes.joint_slot[2 * i + k];
      if (slot == kNoIndex) continue;
      s.nodes.fx[i] += s.joints.force[2 * std::size_t(slot)];
      s.nodes.fy[i] += s.joints.force[2 * std::size_t(slot) + 1];
    }
}

// Two soils for the traction law's tests: one with cohesion, and one without (no shear strength
// outside compression).
std::pair<MaterialModel, MaterialModel> soils_with_and_without_cohesion() {
  MaterialModel soil;
  soil.mechanical = true;
  soil.penalty = 1.0e8, soil.tensile_strength = 1.0e4, soil.cohesion = 2.0e4, soil.tan_friction = 0.5;
  soil.gf_I = 1.0, soil.gf_II = 3.0;
  MaterialModel cohesionless = soil;
  cohesionless.cohesion = 0.0;
  return {soil, cohesionless};
}

}  // namespace

TEST_CASE("a rigid rotation of a triangle by 90 degrees gives zero stress and force", "[mechanics]") {
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "right"));
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {  // (x, y) -> (-y, x) about the origin
    s.nodes.x[i] = -s.nodes.y0[i];
    s.nodes.y[i] = s.nodes.x0[i];
  }
  net_forces(s);
  const double stress_scale = kYoung * 1e-12, force_scale = kYoung * 1e-3 * 1e-12;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    CHECK(std::fabs(s.triangles.sxx[t]) < stress_scale);
    CHECK(std::fabs(s.triangles.syy[t]) < stress_scale);
    CHECK(std::fabs(s.triangles.sxy[t]) < stress_scale);
  }
  for (std::size_t i = 0; i < s.nodes.size(); ++i) CHECK(std::hypot(s.nodes.fx[i], s.nodes.fy[i]) < force_scale);
}

TEST_CASE("patch test: a uniform strain gives the Hooke stress in every triangle, balanced at interior vertices", "[mechanics]") {
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "cross"));
  const double exx = 1e-4, eyy = -3e-5, exy = 2e-5;  // small, so the co-rotational law is Hooke's
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    s.nodes.x[i] = s.nodes.x0[i] + exx * s.nodes.x0[i] + exy * s.nodes.y0[i];
    s.nodes.y[i] = s.nodes.y0[i] + exy * s.nodes.x0[i] + eyy * s.nodes.y0[i];
  }
  net_forces(s);
  const double nu = 0.25, c = kYoung / (1 - nu * nu);  // plane stress
  const double sxx = c * (exx + nu * eyy), syy = c * (eyy + nu * exx), sxy = kYoung / (1 + nu) * exy;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    CHECK(s.triangles.sxx[t] == Approx(sxx).epsilon(1e-3));
    CHECK(s.triangles.syy[t] == Approx(syy).epsilon(1e-3));
    CHECK(s.triangles.sxy[t] == Approx(sxy).epsilon(1e-3));
  }
  // Interior vertices: the corners' forces sum to zero (the joints carry nothing here).
  std::vector<double> fx(s.nodes.size(), 0.0), fy(s.nodes.size(), 0.0);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) fx[s.nodes.vertex[i]] += s.nodes.fx[i], fy[s.nodes.vertex[i]] += s.nodes.fy[i];
  const double scale = std::fabs(sxx) * 1e-3;  // stress x element size x thickness
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const bool interior = s.nodes.x0[i] > 1e-9 && s.nodes.x0[i] < 0.004 - 1e-9 && s.nodes.y0[i] > 1e-9 && s.nodes.y0[i] < 0.003 - 1e-9;
    if (interior) CHECK(std::hypot(fx[s.nodes.vertex[i]], fy[s.nodes.vertex[i]]) < 1e-9 * scale);
  }
}

TEST_CASE("a joint's traction-opening curve integrates to gf_I, and traction-slip to gf_II", "[mechanics]") {
  MaterialModel m;
  m.mechanical = true;
  m.penalty = 1000 * kYoung;
  m.tensile_strength = 1e4;
  m.cohesion = 2e4;
  m.tan_friction = std::tan(30.0 * M_PI / 180.0);
  m.gf_I = 1.0;
  m.gf_II = 3.0;
  const double h0 = 1e-3;
  for (const bool shear : {false, true}) {
    const double strength = shear ? m.cohesion : m.tensile_strength, gf = shear ? m.gf_II : m.gf_I;
    const double end = 1.2 * gf / (softening_curve_area() * strength);
    const int n = 400000;
    double damage = 0, work = 0, peak = 0, previous = 0;
    for (int k = 1; k <= n; ++k) {  // monotonic loading, trapezoid rule
      const double d = end * k / n;
      const PointTraction t = cohesive_traction(m, 1.0, h0, shear ? 0.0 : d, shear ? d : 0.0, damage);
      damage = std::max(damage, t.damage);
      const double traction = shear ? t.shear : t.normal;
      work += 0.5 * (traction + previous) * end / n;
      previous = traction;
      peak = std::max(peak, traction);
    }
    INFO((shear ? "mode II" : "mode I"));
    CHECK(peak == Approx(strength).epsilon(1e-6));
    CHECK(work == Approx(gf).epsilon(1e-4));
    CHECK(damage == 1.0);
    CHECK(previous == 0.0);
  }
}

TEST_CASE("the pre-peak traction is the full law's, bit for bit, wherever it does not flag a peak", "[mechanics]") {
  // Points from deep compression to past the tensile and shear peaks, on a soil with cohesion
  // and on one without (no shear strength outside compression: always flagged).
  const auto [soil, cohesionless] = soils_with_and_without_cohesion();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> factor(0.8, 1.2), opening(-3e-8, 3e-8), slip(-6e-8, 6e-8);
  std::size_t flagged = 0, unflagged = 0, differing = 0, missed = 0;
  for (const MaterialModel* m : {&soil, &cohesionless})
    for (int k = 0; k < 20000; ++k) {
      const JointStrength strength = joint_strength(*m, factor(rng), 1e-3);
      const double o = opening(rng), sl = slip(rng);
      const PrePeakTraction pre = pre_peak_traction(strength, m->tan_friction, o, sl);
      const PointTraction full = cohesive_traction(*m, strength, o, sl, 0.0);
      if (pre.past_peak != 0.0) {
        ++flagged;
        continue;
      }
      ++unflagged;
      missed += full.damage != 0.0;
      differing += !ydry_test::same_bits({pre.normal, pre.shear}, {full.normal, full.shear});
    }
  CHECK(flagged > 5000);
  CHECK(unflagged > 5000);
  CHECK(missed == 0);
  CHECK(differing == 0);
}

TEST_CASE("the vector law is the full law's, bit for bit, wherever it does not flag a point", "[mechanics]") {
  // Points with a committed damage from 0 to 1, from deep compression to well past both
  // peaks: the damage grows at some and stays at others. Only a point
  // without shear strength (the cohesionless soil out of compression) is flagged; everywhere
  // else the tractions must be the full law's.
  const auto [soil, cohesionless] = soils_with_and_without_cohesion();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> factor(0.8, 1.2), opening(-3e-8, 3e-4), slip(-3e-4, 3e-4),
      committed(0.0, 1.0);
  std::size_t flagged = 0, wrongly_flagged = 0, unflagged = 0, differing = 0, growing = 0, unflagged_open = 0;
  for (const MaterialModel* m : {&soil, &cohesionless})
    for (int k = 0; k < 20000; ++k) {
      const JointStrength strength = joint_strength(*m, factor(rng), 1e-3);
      const SofteningConstants constants{m->tan_friction, m->gf_I, m->gf_II, softening_curve_area()};
      // Openings and slips spread on a log scale, so that points fall on both sides of the peaks.
      const double o = opening(rng) * std::pow(10.0, -4.0 * committed(rng));
      const double sl = slip(rng) * std::pow(10.0, -4.0 * committed(rng));
      const double d = committed(rng) < 0.1 ? 0.0 : committed(rng);
      const SoftenedTraction t = softened_traction(strength, constants, o, sl, d);
      const PointTraction full = cohesive_traction(*m, strength, o, sl, d);
      if (t.needs_full_law > 0.0) {
        ++flagged;
        wrongly_flagged += !(m == &cohesionless && o >= 0.0);
        continue;
      }
      ++unflagged;
      unflagged_open += o > strength.peak_opening;
      growing += full.damage > d;
      differing += !ydry_test::same_bits({t.normal, t.shear}, {full.normal, full.shear});
    }
  CHECK(flagged > 5000);
  CHECK(wrongly_flagged == 0);
  CHECK(unflagged > 5000);
  CHECK(unflagged_open > 1000);  // points on the softening branch, not only before the peaks
  CHECK(growing > 1000);         // points whose damage grows, z(D) made in the vector law
  CHECK(differing == 0);
}

TEST_CASE("the softening curve's own exp is libm's within 2e-15 relative", "[mechanics]") {
  // z(D) with the exp of <cmath> in its place, at 100,001 damages from 0 to 1: the difference
  // stays below 2e-15 of z plus 1e-17 absolute (z falls to 0 at D = 1, where a relative bar
  // means nothing). Ends exact: z(0) = 1, z(1) = 0.
  constexpr double a = 0.63, b = 1.8, c = 6.0;
  double worst = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double d = i / 100000.0, r = 1.0 - d;
    const double libm = (1.0 - (a + b - 1.0) / (a + b) * std::exp(d * (a + c * b) / ((a + b) * (1.0 - a - b)))) *
                        (a * r + b * std::pow(r, 6.0));
    worst = std::max(worst, std::fabs(softening_curve(d) - libm) / (2e-15 * libm + 1e-17));
  }
  CHECK(worst <= 1.0);
  CHECK(softening_curve(0.0) == 1.0);
  CHECK(softening_curve(1.0) == 0.0);
  CHECK(softening_curve(-0.5) == 1.0);
}

TEST_CASE("the joint kernel's vector passes give the full traction law's forces, bit for bit", "[mechanics][threads]") {
  // 1,750 joints (six chunks of the kernel and a partial seventh) in every regime, with a
  // strength factor of their own: nodes moved by 0.3 nm to 0.3 um, so that some joints stay
  // before the law's peaks (the peak opening is 2e-8 m, the peak slip 4e-8 m), in tension or
  // compression, and others pass them; some joints damaged, some broken. On 1 and 2 threads.
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "left", {"mesh.size=[0.03, 0.02]"}));
  REQUIRE(s.joints.size() > std::size_t(4 * kJointChunk));
  REQUIRE(s.joints.size() % kJointChunk != 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> exponent(-9.5, -6.5), factor(0.8, 1.2);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const double scale = std::pow(10.0, exponent(rng));
    s.nodes.x[i] = s.nodes.x0[i] + scale * unit(rng);
    s.nodes.y[i] = s.nodes.y0[i] + scale * unit(rng);
  }
  for (double& f : s.joints.strength_factor) f = factor(rng);
  // Damaged joints on every 7th and every 13th joint: the kernel's second vector pass takes
  // them, whether their damage grows or not.
  for (std::size_t j = 0; j < s.joints.size(); j += 7) s.joints.damage[3 * j + 1] = 0.3;
  for (std::size_t j = 5; j < s.joints.size(); j += 13) s.joints.damage[3 * j] = 0.6;
  for (std::size_t j = 3; j < s.joints.size(); j += 11) s.joints.broken[j] = 1;

  std::size_t before_peaks = 0, other = 0;
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const JointKinematics kin = joint_kinematics(s.nodes, &s.joints.node[4 * j]);
    bool intact = !s.joints.broken[j];
    for (int p = 0; p < 3; ++p) {
      const double a = kJointPointShareOfEnd0[p], b = 1.0 - a;
      const PointTraction t = cohesive_traction(s.materials[s.joints.law[j]], s.joints.strength_factor[j],
                                                s.joints.length0[j], a * kin.opening[0] + b * kin.opening[1],
                                                a * kin.slip[0] + b * kin.slip[1], s.joints.damage[3 * j + p]);
      intact = intact && t.damage == 0.0 && s.joints.damage[3 * j + p] == 0.0;
    }
    ++(intact ? before_peaks : other);
  }
  CHECK(before_peaks > 200);
  CHECK(other > 200);
  // Then the same joints of a material that cannot break: the kernel leaves them to the
  // scalar law, a linear penalty both ways.
  for (const bool breakable : {true, false}) {
    for (MaterialModel& m : s.materials) m.breakable = breakable;
    ydry_test::on_1_and_2_threads([&](int threads) {
      std::fill(s.joints.force.begin(), s.joints.force.end(), 0.0);
      joint_forces(s.nodes, s.mechanics, s.ownership, s.materials, s.joints, s.joints.force);
      std::size_t differing = 0;
      for (std::size_t j = 0; j < s.joints.size(); ++j) {
        double full[8];
        joint_nodal_forces(s.nodes, s.joints, s.mechanics, s.materials, j, full);
        for (int k = 0; k < 8; ++k) differing += !ydry_test::same_bits({full[k]}, {s.joints.force[8 * j + k]});
      }
      INFO(threads << " thread(s), breakable " << breakable);
      CHECK(differing == 0);
    });
  }
}

TEST_CASE("the element kernel's vectorised loop gives the forces and stresses of its scalar remainder, bit for bit",
          "[mechanics][threads]") {
  // The kernel takes the triangles in runs of one material, and vectorises each run four (or
  // two) triangles at a time; the last triangles of a run go through the loop one by one.
  // With two copies of one material alternating, every run is one triangle long: all of them
  // take that scalar path, and must give the bits of the whole mesh in one run.
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "left", {"mesh.size=[0.01, 0.01]"}));
  REQUIRE(s.triangles.size() > 100);
  std::mt19937 rng(11);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {  // strains of about 1e-3, rotations
    s.nodes.x[i] = s.nodes.x0[i] + 1e-6 * unit(rng) - 1e-2 * s.nodes.y0[i];
    s.nodes.y[i] = s.nodes.y0[i] + 1e-6 * unit(rng) + 1e-2 * s.nodes.x0[i];
  }
  for (double& eps : s.triangles.shrinkage_strain) eps = -1e-3 * std::fabs(unit(rng));
  const auto forces_and_stresses = [&] {
    element_forces(s.triangles, s.mechanics, s.ownership, s.materials, s.nodes);
    element_stresses(s.nodes, s.ownership, s.materials, s.triangles);
    std::vector<double> out = s.nodes.fx;
    for (const std::vector<double>* v : {&s.nodes.fy, &s.triangles.sxx, &s.triangles.syy, &s.triangles.sxy})
      out.insert(out.end(), v->begin(), v->end());
    return out;
  };
  ydry_test::on_1_and_2_threads([&](int threads) {
    INFO(threads << " thread(s)");
    std::fill(s.triangles.material.begin(), s.triangles.material.end(), std::uint16_t(0));
    const std::vector<double> one_run = forces_and_stresses();
    CHECK(std::count(one_run.begin(), one_run.end(), 0.0) == 0);
    s.materials.resize(1);
    s.materials.push_back(s.materials[0]);
    for (std::size_t t = 0; t < s.triangles.size(); t += 2) s.triangles.material[t] = 1;
    CHECK(ydry_test::same_bits(forces_and_stresses(), one_run));
  });
}

TEST_CASE("the node integration moves the free components alone, with the same bits in every lane of its vector loop",
          "[mechanics]") {
  // Every node has the same velocity, force and mass, so every free component must come out
  // the same to the bit, whether the vector loop's body or its scalar remainder did it.
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "left"));
  Nodes& n = s.nodes;
  REQUIRE(n.size() > 40);
  for (std::size_t i = 0; i < n.size(); ++i) {
    n.x[i] = n.y[i] = 0.1;
    n.vx[i] = 3e-3, n.vy[i] = -7e-3;
    n.fx[i] = 0.3, n.fy[i] = 1.1;
    n.m[i] = 0.7;
    n.constraint[i] = std::uint8_t(i % 5 == 1 ? kFixX : i % 5 == 3 ? kFixY : 0);
  }
  const VelocityUpdate update{0.9, 1e-4, 0.99, 1e-3};
  PowerLanes power;
  integrate_node_range(n, 0, n.size(), update, power);
  const double vx = (0.9 * 3e-3 + (1e-3 + 1e-4) * 0.3 / 0.7) * 0.99;
  const double vy = (0.9 * -7e-3 + (1e-3 + 1e-4) * 1.1 / 0.7) * 0.99;
  std::size_t wrong = 0, free_xs = 0, free_ys = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const bool free_x = n.constraint[i] != kFixX, free_y = n.constraint[i] != kFixY;
    free_xs += free_x, free_ys += free_y;
    wrong += !ydry_test::same_bits({n.vx[i], n.x[i]}, {n.vx[0], n.x[0]}) && free_x;
    wrong += !ydry_test::same_bits({n.vy[i], n.y[i]}, {n.vy[0], n.y[0]}) && free_y;
    wrong += !free_x && (n.vx[i] != 3e-3 || n.x[i] != 0.1);
    wrong += !free_y && (n.vy[i] != -7e-3 || n.y[i] != 0.1);
  }
  CHECK(wrong == 0);
  CHECK(n.vx[0] == Approx(vx).epsilon(1e-14));
  CHECK(n.x[0] == Approx(0.1 + vx * 1e-3).epsilon(1e-14));
  CHECK(n.vy[0] == Approx(vy).epsilon(1e-14));
  CHECK(n.y[0] == Approx(0.1 + vy * 1e-3).epsilon(1e-14));
  // The damping's v_new . f over the moved components, each f the force that moved it; a sum
  // of some hundred terms of two values: round-off only.
  CHECK(power.total() == Approx(double(free_xs) * vx * 0.3 + double(free_ys) * vy * 1.1).epsilon(1e-13));
}

TEST_CASE("nodes moved in the element kernel's pass take the bits of nodes moved before it", "[mechanics][threads]") {
  // A relaxation step moves each piece of the triangles' nodes just before their element
  // forces; it must be the integration of every node followed by the element forces, on 1 and
  // 2 threads, with some components prescribed and a rigid material among the triangles.
  const State start = prepare_state(load_deck(YDRY_SOURCE_DIR "/inputs/peron/peron.toml", {}));
  std::mt19937 rng(17);
  std::normal_distribution<double> unit(0.0, 1.0);
  State moved = start;
  for (std::size_t i = 0; i < moved.nodes.size(); ++i) {
    moved.nodes.vx[i] = 1e-3 * unit(rng), moved.nodes.vy[i] = 1e-3 * unit(rng);
    moved.nodes.fx[i] = 1e-2 * unit(rng), moved.nodes.fy[i] = 1e-2 * unit(rng);
  }
  const VelocityUpdate update{0.9, 1e-7, 1.0, 5e-7};
  State expected = moved;
  PowerLanes expected_power;
  integrate_node_range(expected.nodes, 0, expected.nodes.size(), update, expected_power);
  element_forces(expected.triangles, expected.mechanics, expected.ownership, expected.materials, expected.nodes);
  const auto positions_and_forces = [](const State& s) {
    std::vector<double> out;
    for (const std::vector<double>* v : {&s.nodes.x, &s.nodes.y, &s.nodes.vx, &s.nodes.vy, &s.nodes.fx, &s.nodes.fy})
      out.insert(out.end(), v->begin(), v->end());
    return out;
  };
  REQUIRE(std::count(start.nodes.constraint.begin(), start.nodes.constraint.end(), kFixX | kFixY) > 0);
  CHECK_FALSE(ydry_test::same_bits(positions_and_forces(expected), positions_and_forces(moved)));
  // The pass's v_new . f sums the same terms per ownership slot, then over the slots: equal
  // to the sum in node order to round-off, and the same bits on any number of threads.
  std::vector<double> power;
  ydry_test::on_1_and_2_threads([&](int threads) {
    INFO(threads << " thread(s)");
    State s = moved;
    power.push_back(element_forces(s.triangles, s.mechanics, s.ownership, s.materials, s.nodes, &update));
    CHECK(ydry_test::same_bits(positions_and_forces(s), positions_and_forces(expected)));
  });
  REQUIRE(power.size() == 2);
  CHECK(ydry_test::same_bits({power[1]}, {power[0]}));
  CHECK(power[0] == Approx(expected_power.total()).epsilon(1e-12));
  CHECK(power[0] != 0.0);
}

TEST_CASE("element and joint forces conserve linear and angular momentum, broken or not", "[mechanics]") {
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "left"));
  std::mt19937 rng(3);
  std::normal_distribution<double> jitter(0.0, 2e-5);  // openings into the softening range
  const double angle = 0.3;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const double x = s.nodes.x0[i] + jitter(rng), y = s.nodes.y0[i] + jitter(rng);
    s.nodes.x[i] = std::cos(angle) * x - std::sin(angle) * y;
    s.nodes.y[i] = std::sin(angle) * x + std::cos(angle) * y;
  }
  for (std::size_t j = 0; j < s.joints.size(); j += 5) s.joints.broken[j] = 1;
  net_forces(s);
  double fx = 0, fy = 0, torque = 0, scale = 0;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    fx += s.nodes.fx[i];
    fy += s.nodes.fy[i];
    torque += s.nodes.x[i] * s.nodes.fy[i] - s.nodes.y[i] * s.nodes.fx[i];
    scale += std::hypot(s.nodes.fx[i], s.nodes.fy[i]);
  }
  REQUIRE(scale > 1.0);  // the jitter loads the solid well beyond round-off
  CHECK(std::fabs(fx) < 1e-12 * scale);
  CHECK(std::fabs(fy) < 1e-12 * scale);
  CHECK(std::fabs(torque) < 1e-12 * scale * 0.005);  // lever arm: the block's size
}

TEST_CASE("the stable step is below 2 / omega_max of the linearised solid and within a factor 3 of it", "[mechanics]") {
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "right"));
  const std::size_t nn = s.nodes.size();
  const double step = stable_mechanics_step(s.nodes, s.triangles, s.joints, s.mechanics, s.contact, s.substrate, s.materials, 1.0);
  // Stiffness by central differences of the net forces, mass-normalised: M^-1/2 K M^-1/2.
  Eigen::MatrixXd k(2 * nn, 2 * nn);
  const double h = 1e-10;
  for (std::size_t c = 0; c < 2 * nn; ++c) {
    double& coordinate = c % 2 ? s.nodes.y[c / 2] : s.nodes.x[c / 2];
    Eigen::VectorXd plus(2 * nn), minus(2 * nn);
    for (auto* f : {&plus, &minus}) {
      coordinate += f == &plus ? h : -2 * h;
      net_forces(s);
      for (std::size_t i = 0; i < nn; ++i) (*f)[2 * i] = s.nodes.fx[i], (*f)[2 * i + 1] = s.nodes.fy[i];
    }
    coordinate += h;
    k.col(c) = -(plus - minus) / (2 * h);
  }
  for (std::size_t r = 0; r < 2 * nn; ++r)
    for (std::size_t c = 0; c < 2 * nn; ++c) k(r, c) /= std::sqrt(s.nodes.m[r / 2] * s.nodes.m[c / 2]);
  const Eigen::MatrixXd symmetric = 0.5 * (k + k.transpose());
  const double omega_max = std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(symmetric).eigenvalues().maxCoeff());
  CHECK(step <= 2.0 / omega_max);
  CHECK(step >= 2.0 / omega_max / 3.0);
}

TEST_CASE("a column hanging under its own weight stretches by rho g H^2 / 2E within 1 %", "[mechanics]") {
  ydry_test::TempDir dir;
  const double height = 0.1, g = 10.0;
  State s = setup_state(ydry_test::block_deck(dir, "cross",
                                   {"mesh.size=[0.01,0.1]", "mesh.element_size=0.0025", "materials.soil.poisson=0.0",
                                    "materials.soil.breakable=false", "run.gravity=[0.0,-10.0]",
                                    "mechanics.boundary=[{on=\"top\",fix=[\"x\",\"y\"]}]"}));
  double tip = 0;
  int corners = 0;
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.nodes.y0[i] < 1e-12) tip += s.nodes.y[i] - s.nodes.y0[i], ++corners;
  tip /= corners;
  CHECK(tip == Approx(-kDensity * g * height * height / (2 * kYoung)).epsilon(0.01));
}

TEST_CASE("the solid's equilibrium is bitwise the same on 1 and 2 threads", "[mechanics][threads]") {
  ydry_test::TempDir dir;
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/shrinkage/shrinkage.toml", {"mesh.element_size=0.0025"});
  std::vector<double> x[2];
  ydry_test::on_1_and_2_threads([&](int threads) {
    const State s = setup_state(deck);
    REQUIRE(s.nodes.size() > kReductionBlock);  // the reductions span several blocks
    x[threads - 1] = s.nodes.x;
  });
  CHECK(x[0] == x[1]);
}

TEST_CASE("shrinkage results do not depend on the relaxation controls", "[mechanics]") {
  // The paper 4.3 block on a 5 mm mesh: the top reaction (sigma_y) and the shortening.
  const auto figures = [](const std::vector<std::string>& sets) {
    std::vector<std::string> all = {"mesh.element_size=0.005"};
    all.insert(all.end(), sets.begin(), sets.end());
    const State s = setup_state(load_deck(YDRY_SOURCE_DIR "/verification/shrinkage/shrinkage.toml", all));
    double left = 0, right = 0;
    int nl = 0, nr = 0;
    for (std::size_t i = 0; i < s.nodes.size(); ++i) {
      if (s.nodes.x0[i] < 1e-12) left += s.nodes.x[i] - s.nodes.x0[i], ++nl;
      if (s.nodes.x0[i] > 0.1 - 1e-12) right += s.nodes.x[i] - s.nodes.x0[i], ++nr;
    }
    REQUIRE(s.mechanics.capped_relaxations == 0);
    return std::tuple<double, double, std::uint64_t>{s.mechanics_boundaries[1].reaction_y, left / nl - right / nr,
                                                     s.mechanics.steps};
  };
  double reaction = 0, shortening = 0;
  std::uint64_t steps = 0;
  std::tie(reaction, shortening, steps) = figures({});  // Newton, the default
  CHECK(reaction / 0.1 == Approx(20000.0).epsilon(0.005));
  CHECK(shortening == Approx(2.4e-3).epsilon(0.005));
  // The same answer with the tolerance halved (never in fewer iterations), with FIRE or the
  // damping in place of Newton, and with the damping's pseudo-step halved or its physical
  // masses, which change its path; a doubled step cap changes nothing when a relaxation ends
  // on its tolerance, as it must.
  const auto same_answer = [&](const std::vector<std::string>& sets) {
    INFO(sets.back());
    const auto [r, d, n] = figures(sets);
    CHECK(r == Approx(reaction).epsilon(1e-3));
    CHECK(d == Approx(shortening).epsilon(1e-3));
    return n;
  };
  const std::string viscous = "solver.relaxation=\"viscous\"";
  CHECK(same_answer({"solver.relaxation_tolerance=5e-8"}) >= steps);
  CHECK(same_answer({"solver.relaxation=\"fire\""}) != steps);
  const std::uint64_t viscous_steps = same_answer({viscous});
  CHECK(viscous_steps != steps);
  CHECK(same_answer({viscous, "solver.mechanics_safety=0.4"}) != viscous_steps);
  CHECK(same_answer({viscous, "solver.node_mass_scaling=false"}) != viscous_steps);
  CHECK(same_answer({viscous, "solver.relaxation_max_steps=400000"}) == viscous_steps);
}

TEST_CASE("pre-existing cracks of the deck break the joints along a segment and split the moisture field there", "[mechanics]") {
  ydry_test::TempDir dir;
  const auto with_crack = [&](const std::string& segment) {
    return setup_state(ydry_test::block_deck(dir, "right",
                                  {"cracks=[{" + segment + "}]", "materials.soil.moisture_conductivity=1e-6",
                                   "materials.soil.initial_moisture=0.3", "materials.soil.shrinkage_coefficient=0.1"}));
  };
  // A segment across the cells instead of along their edges is an input error.
  CHECK_THROWS_WITH(with_crack("from=[0.0005,0.0],to=[0.0005,0.003]"),
                    Catch::Contains("cracks[0]: the segment does not follow jointed mesh edges"));
  const State s = with_crack("from=[0.002,0.003],to=[0.002,0.001]");  // 2 mm down from the top, at x = 2 mm
  REQUIRE(std::count(s.joints.broken.begin(), s.joints.broken.end(), 1) == 2);
  // The vertices strictly inside the crack and on the top surface are split in two moisture
  // nodes; the tip vertex (x = 2 mm, y = 1 mm) stays one.
  const auto moisture_nodes_at = [&](double x, double y) {
    std::vector<index_t> found;
    for (std::size_t i = 0; i < s.nodes.size(); ++i)
      if (std::hypot(s.nodes.x0[i] - x, s.nodes.y0[i] - y) < 1e-9) found.push_back(s.nodes.mnode[i]);
    std::sort(found.begin(), found.end());
    return std::size_t(std::unique(found.begin(), found.end()) - found.begin());
  };
  CHECK(moisture_nodes_at(0.002, 0.003) == 2);
  CHECK(moisture_nodes_at(0.002, 0.002) == 2);
  CHECK(moisture_nodes_at(0.002, 0.001) == 1);
}

TEST_CASE("a rigid material stays put and never sets the time step", "[mechanics]") {
  const auto state = [](const std::string& base_young) {
    std::vector<std::string> sets = {"run.mechanics=true", "materials.soil.young=1e6", "materials.soil.poisson=0.3",
                                     "materials.soil.breakable=false", "materials.soil.shrinkage_coefficient=0.05",
                                     "materials.soil.initial_moisture=0.3", "materials.soil.stress_free_moisture=0.35",
                                     "materials.base.rigid=true"};
    if (!base_young.empty()) sets.push_back("materials.base.young=" + base_young);
    return setup_state(load_deck(YDRY_SOURCE_DIR "/tests/data/two_materials.toml", sets));
  };
  const State s = state("");
  const std::uint16_t base = ydry_test::material_id(s, "base");
  double soil_motion = 0;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const double motion = std::hypot(s.nodes.x[i] - s.nodes.x0[i], s.nodes.y[i] - s.nodes.y0[i]);
    if (s.triangles.material[triangle_of(index_t(i))] == base) CHECK(motion == 0.0);
    else soil_motion = std::max(soil_motion, motion);
  }
  CHECK(soil_motion > 1e-6);  // the soil did shrink and sag: the base held still under it
  CHECK(state("7e10").mechanics.step_s == s.mechanics.step_s);  // a stiff base changes nothing
}

TEST_CASE("the joint kernel computes every joint of a material with mechanics, run by run, and leaves a rigid one's at zero",
          "[mechanics][threads]") {
  // The kernel visits the joints of a material with mechanics as runs of consecutive joints
  // (Joints::mechanical_runs), each thread its range cut by them: a joint dropped or done
  // twice at a run's or a range's end would show here, on 1 and 2 threads.
  // The Peron deck, set up but not relaxed: its rigid base's triangles lie between the soil's
  // along the Hilbert numbering, so its soil joints come in some 300 runs.
  const State start = prepare_state(load_deck(YDRY_SOURCE_DIR "/inputs/peron/peron.toml", {}));
  const std::vector<index_t>& runs = start.joints.mechanical_runs;
  REQUIRE(runs.size() >= 2 * 100);
  std::size_t rigid = 0;
  for (std::size_t j = 0; j < start.joints.size(); ++j) rigid += !start.materials[start.joints.law[j]].mechanical;
  REQUIRE(rigid > 0);
  std::mt19937 rng(3);
  std::normal_distribution<double> unit(0.0, 1.0);
  ydry_test::on_1_and_2_threads([&](int threads) {
    INFO(threads << " thread(s)");
    State s = start;
    for (std::size_t i = 0; i < s.nodes.size(); ++i) {
      s.nodes.x[i] += 1e-6 * unit(rng);
      s.nodes.y[i] += 1e-6 * unit(rng);
    }
    joint_forces(s.nodes, s.mechanics, s.ownership, s.materials, s.joints, s.joints.force);
    std::size_t wrong = 0, carrying = 0;
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
      double expected[8];
      joint_nodal_forces(s.nodes, s.joints, s.mechanics, s.materials, j, expected);  // 0 for a rigid material's joint
      carrying += expected[0] != 0.0;
      for (int k = 0; k < 8; ++k) wrong += !ydry_test::same_bits({expected[k]}, {s.joints.force[8 * j + k]});
    }
    CHECK(carrying == s.joints.size() - rigid);
    CHECK(wrong == 0);
  });
}

TEST_CASE("a bar pulled apart over many relaxations dissipates gf_I per unit crack area, and the supports' work balances it", "[mechanics]") {
  // verification/fracture_modeI: a 4 mm line of joints (1 m thick) opened 1e-6 m per coupling
  // step past complete separation; each relaxation starts from the extrapolated equilibrium,
  // whose jump the joints must book like any other motion.
  // Every relaxation: FIRE's restarts and steering, like the damping, must take no energy
  // the joints do not book; Newton books it between equilibria.
  for (const char* method : {"viscous", "fire", "newton"}) {
    INFO(method);
    const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/fracture_modeI/fracture_modeI.toml",
                                {std::string("solver.relaxation=\"") + method + "\""});
    State s = setup_state(deck);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    const Energies e = energies(s);
    const double dissipated = 1.0 * 0.004;  // gf_I x crack area
    CHECK(e.fracture_J == Approx(dissipated).epsilon(0.01));
    CHECK(e.external_work_J == Approx(dissipated).epsilon(0.01));
  }
}

TEST_CASE("a run that runs away exits 3 with the step, the node and the causes, and keeps the failed state as its last frame and row",
          "[mechanics]") {
  // tests/data/sweep_strip.toml with its right end driven at 1 m/s: the first relaxation
  // (t = 957.6 s) moves it 958 m at once, far more than the 40 mm strip is wide.
  ydry_test::TempDir dir;
  std::string deck = ydry_test::read_text(YDRY_SOURCE_DIR "/tests/data/sweep_strip.toml");
  const std::string held = "on = \"right\"\nfix = [\"x\", \"y\"]";
  REQUIRE(deck.find(held) != std::string::npos);
  deck.replace(deck.find(held), held.size(), "on = \"right\"\nvelocity = [1.0, 0.0]");
  ydry_test::write_text(dir.file("runaway.toml"), deck);
  const ydry_test::CommandResult result = ydry_test::run_ydry(dir.file("runaway.toml") + " -o " + dir.file("run") + " --quiet");
  CHECK(result.exit_code == 3);
  CHECK(result.output.find("numerical failure at t = 957.6 s") != std::string::npos);
  CHECK(result.output.find("of triangle") != std::string::npos);
  CHECK(result.output.find("solver.mechanics_safety") != std::string::npos);
  // The failed state is the last frame and the last row.
  const std::string pvd = ydry_test::read_text(dir.file("run/strip.pvd"));
  const std::size_t last_frame = pvd.rfind("timestep=\"");
  REQUIRE(last_frame != std::string::npos);
  CHECK(std::stod(pvd.substr(last_frame + 10)) == Approx(957.6).epsilon(1e-12));
  const std::string series = ydry_test::read_text(dir.file("run/series.csv"));
  const std::size_t last_row = series.rfind('\n', series.size() - 2);
  REQUIRE(last_row != std::string::npos);
  CHECK(std::stod(series.substr(last_row + 1)) == Approx(957.6).epsilon(1e-12));
  CHECK(ydry_test::read_text(dir.file("run/summary.json")).find("\"completed\": false") != std::string::npos);
}

TEST_CASE("a non-finite position stops the relaxation with a NumericalFailure naming the node", "[mechanics]") {
  ydry_test::TempDir dir;
  const State start = setup_state(ydry_test::block_deck(dir, "right"));
  for (const RelaxationMethod method : {RelaxationMethod::viscous, RelaxationMethod::fire, RelaxationMethod::newton}) {
    INFO("relaxation method " << int(method));
    State s = start;
    s.nodes.y[4] = std::numeric_limits<double>::quiet_NaN();
    try {
      relax(s, RelaxationControls{1e-9, 100, method}, 1.0);
      FAIL("relax went on with a NaN position");
    } catch (const NumericalFailure& failure) {
      const std::string message = failure.what();
      CHECK(message.find("node 4 of triangle 1 (material soil") != std::string::npos);
      CHECK(message.find("non-finite position") != std::string::npos);
      CHECK(message.find("solver.mechanics_safety") != std::string::npos);
    }
  }
}

TEST_CASE("a relaxation built without controls runs as a deck that names none", "[mechanics]") {
  const Deck deck = ydry_test::strip_deck();
  const RelaxationControls controls;
  CHECK(controls.method == deck.relaxation);
  CHECK(controls.method == RelaxationMethod::newton);  // doc/deck.md "[solver]"
  CHECK(controls.tolerance == deck.relaxation_tolerance);
  CHECK(controls.max_steps == deck.relaxation_max_steps);
  CHECK(controls.slide_after == deck.relaxation_slide_after);
}

// A dynamic run commits the joints' damage at every step (doc/solver.md "Dynamic
// integration"): the mode I bar, its right column thrown to the right and left free, opens its
// joints past their peak and springs back within one coupling step; the damage of the peak
// passed stays, though the joints end the step nearly closed.
TEST_CASE("a joint that passes its peak and unloads within one dynamic coupling step keeps its damage", "[mechanics]") {
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/fracture_modeI/fracture_modeI.toml",
                              {"solver.integration=\"dynamic\"",
                               "mechanics.boundary=[{on = \"left\", fix = [\"x\"]}, {on = \"bottom\", fix = [\"y\"]}, "
                               "{on = \"top\", fix = [\"y\"]}]"});
  State s = setup_state(deck);
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.nodes.x0[i] > 0.0015) s.nodes.vx[i] = 0.6;  // m/s: the bar's kinetic energy is past its peak's
  move_dynamically(s, 3e-4);  // about one period of the bar's stretching
  const double damage = *std::max_element(s.joints.damage.begin(), s.joints.damage.end());
  CHECK(damage > 0.0);
  CHECK(damage < 1.0);
}
