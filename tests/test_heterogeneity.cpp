// Strength heterogeneity: per-joint Weibull factors on f_t and c, drawn from run.seed and the
// joint's mesh edge: reproducible, independent of storage order and thread count, with the
// mean and coefficient of variation asked for, and really used by the joint law.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "tests/test_support.h"
#include "ycore/solid/joint_law.h"
#include "ycore/solid/joint_damage.h"
#include "ycore/solid/joint_forces.h"
#include "ycore/driver/setup.h"
#include "ycore/solid/strength_heterogeneity.h"

using namespace ydry;

namespace {

State block_state(ydry_test::TempDir& dir, const std::vector<std::string>& sets) {
  return setup_state(ydry_test::block_deck(dir, "cross", sets));
}

// Factor by mesh edge (its two vertex ids), whatever the joint's index.
std::map<std::uint64_t, double> factor_by_edge(const State& s) {
  std::map<std::uint64_t, double> out;
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    out[edge_key(s.nodes.vertex[s.joints.node[4 * j]], s.nodes.vertex[s.joints.node[4 * j + 1]])] =
        s.joints.strength_factor[j];
  return out;
}

}  // namespace

TEST_CASE("Weibull of mean 1: CV 1 is the exponential, CV sqrt(4/pi - 1) the Rayleigh (modulus 2)",
          "[heterogeneity]") {
  const UnitMeanWeibull exponential = unit_mean_weibull(1.0);
  CHECK(exponential.inverse_shape == Approx(1.0).epsilon(1e-12));
  CHECK(exponential.scale == Approx(1.0).epsilon(1e-12));
  const UnitMeanWeibull rayleigh = unit_mean_weibull(std::sqrt(4.0 / M_PI - 1.0));
  CHECK(rayleigh.inverse_shape == Approx(0.5).epsilon(1e-12));
  CHECK(rayleigh.scale == Approx(2.0 / std::sqrt(M_PI)).epsilon(1e-12));  // 1 / Gamma(3/2)
  const UnitMeanWeibull none = unit_mean_weibull(0.0);
  CHECK(strength_factor(1, 4, 7, none) == 1.0);
}

TEST_CASE("strength factors: the same seed draws the same, another seed others, heterogeneity 0 gives exactly 1",
          "[heterogeneity]") {
  ydry_test::TempDir dir;
  const State a = block_state(dir, {"materials.soil.strength_heterogeneity=0.3", "run.seed=5"});
  const State again = block_state(dir, {"materials.soil.strength_heterogeneity=0.3", "run.seed=5"});
  const State other = block_state(dir, {"materials.soil.strength_heterogeneity=0.3", "run.seed=6"});
  const State homogeneous = block_state(dir, {"run.seed=5"});
  REQUIRE(a.joints.size() > 50);
  CHECK(a.joints.strength_factor == again.joints.strength_factor);
  std::size_t equal = 0;
  for (std::size_t j = 0; j < a.joints.size(); ++j)
    equal += a.joints.strength_factor[j] == other.joints.strength_factor[j];
  CHECK(equal == 0);
  CHECK(std::all_of(homogeneous.joints.strength_factor.begin(), homogeneous.joints.strength_factor.end(),
                    [](double f) { return f == 1.0; }));
  // Each joint's factor is the one its edge and the seed give.
  const UnitMeanWeibull weibull = unit_mean_weibull(0.3);
  for (std::size_t j = 0; j < a.joints.size(); ++j)
    CHECK(a.joints.strength_factor[j] ==
          strength_factor(5, a.nodes.vertex[a.joints.node[4 * j + 1]], a.nodes.vertex[a.joints.node[4 * j]], weibull));
}

TEST_CASE("strength factors belong to the mesh edge, not to the joint's place in storage", "[heterogeneity]") {
  ydry_test::TempDir dir;
  State s = block_state(dir, {"materials.soil.strength_heterogeneity=0.5", "run.seed=11"});
  const std::map<std::uint64_t, double> before = factor_by_edge(s);
  // Store the joints in reverse order, each seen from its other triangle (nodes 2, 3, 0, 1).
  Joints& jt = s.joints;
  const std::size_t nj = jt.size();
  std::vector<index_t> node(4 * nj);
  std::vector<std::uint16_t> law(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    const std::size_t from = nj - 1 - j;
    for (int k = 0; k < 4; ++k) node[4 * j + k] = jt.node[4 * from + (k + 2) % 4];
    law[j] = jt.law[from];
  }
  jt.node = node;
  jt.law = law;
  set_strength_factors(jt, s.nodes, s.materials, 11);
  CHECK(factor_by_edge(s) == before);
}

TEST_CASE("over 10^4 joints the factors' mean is 1 and their CV the one asked for, within 4 standard errors",
          "[heterogeneity]") {
  ydry_test::TempDir dir;
  State s = setup_state(ydry_test::block_deck(dir, "right", {"mesh.size=[0.07,0.05]", "mesh.element_size=0.001"}));
  const std::size_t n = s.joints.size();
  REQUIRE(n > 10000);
  for (const double cv : {0.1, 0.3, 1.0}) {
    s.materials[0].strength_heterogeneity = cv;
    set_strength_factors(s.joints, s.nodes, s.materials, 2024);
    double mean = 0;
    for (const double f : s.joints.strength_factor) mean += f / double(n);
    double m2 = 0, m4 = 0;  // central moments of the sample
    for (const double f : s.joints.strength_factor) {
      const double d2 = (f - mean) * (f - mean);
      m2 += d2 / double(n);
      m4 += d2 * d2 / double(n);
    }
    const double sd = std::sqrt(m2), sample_cv = sd / mean;
    // Standard errors: of the mean sd / sqrt(n); of the standard deviation sqrt((m4 - m2^2) / n) / (2 sd);
    // of the CV at most se(sd) / mean + sd se(mean) / mean^2.
    const double se_mean = sd / std::sqrt(double(n));
    const double se_sd = std::sqrt((m4 - m2 * m2) / double(n)) / (2.0 * sd);
    const double se_cv = se_sd / mean + sd * se_mean / (mean * mean);
    INFO("cv " << cv << ": sample mean " << mean << " (se " << se_mean << "), sample cv " << sample_cv << " (se "
               << se_cv << ")");
    CHECK(std::fabs(mean - 1.0) < 4.0 * se_mean);
    CHECK(std::fabs(sample_cv - cv) < 4.0 * se_cv);
    CHECK(*std::min_element(s.joints.strength_factor.begin(), s.joints.strength_factor.end()) > 0.0);
  }
}

TEST_CASE("a single joint pulled apart peaks at factor x f_t, and slid at factor x c, within 1e-9", "[heterogeneity]") {
  ydry_test::TempDir dir;
  // One 1 mm cell of the right pattern: two triangles, one joint on the diagonal.
  State s = setup_state(ydry_test::block_deck(
      dir, "right", {"mesh.size=[0.001,0.001]", "materials.soil.strength_heterogeneity=0.3", "run.seed=3"}));
  REQUIRE(s.joints.size() == 1);
  const double factor = s.joints.strength_factor[0];
  REQUIRE(std::fabs(factor - 1.0) > 0.05);  // this seed's draw is far enough from 1 to tell
  const MaterialModel& m = s.materials[0];
  const double h0 = s.joints.length0[0];
  const JointKinematics k = joint_kinematics(s.nodes, &s.joints.node[0]);
  const index_t first = triangle_of(s.joints.node[0]);
  for (const bool shear : {false, true}) {
    // The first triangle moves rigidly along the joint's normal (opening) or its axis (slip).
    const double dx = shear ? k.ny : k.nx, dy = shear ? -k.nx : k.ny;
    const double strength = shear ? m.cohesion : m.tensile_strength;
    const double end = 3.0 * 2.0 * strength * h0 / m.penalty;  // thrice the homogeneous peak's travel
    const int steps = 1000000;
    double peak = 0;
    for (int i = 1; i <= steps; ++i) {
      const double d = end * i / steps;
      for (int a = 0; a < 3; ++a) {
        const index_t c = corner_node(first, a);
        s.nodes.x[c] = s.nodes.x0[c] + d * dx;
        s.nodes.y[c] = s.nodes.y0[c] + d * dy;
      }
      joint_forces(s.nodes, s.mechanics, s.ownership, s.materials, s.joints, s.joints.force);
      // Traction on the first face: minus the force on its nodes 0, 1 along the motion, per area.
      const double* f = &s.joints.force[0];
      peak = std::max(peak, -((f[0] + f[2]) * dx + (f[1] + f[3]) * dy) / h0);  // thickness 1
    }
    INFO((shear ? "mode II" : "mode I") << ", factor " << factor);
    CHECK(peak == Approx(factor * strength).epsilon(1e-9));
  }
}

TEST_CASE("heterogeneous joint forces and damage are bitwise the same on 1 and 2 threads", "[heterogeneity][threads]") {
  ydry_test::TempDir dir;
  State s = block_state(dir, {"materials.soil.strength_heterogeneity=0.5"});
  std::mt19937 rng(8);
  std::normal_distribution<double> jitter(0.0, 3e-4);  // openings beyond the softening length
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    s.nodes.x[i] = s.nodes.x0[i] + jitter(rng);
    s.nodes.y[i] = s.nodes.y0[i] + jitter(rng);
  }
  std::vector<double> force[2], damage[2];
  std::vector<std::uint8_t> broken[2];
  ydry_test::on_1_and_2_threads([&](int threads) {
    State t = s;
    joint_forces(t.nodes, t.mechanics, t.ownership, t.materials, t.joints, t.joints.force);
    commit_joint_damage(t.nodes, t.ownership, t.materials, t.joints);
    force[threads - 1] = t.joints.force;
    damage[threads - 1] = t.joints.damage;
    broken[threads - 1] = t.joints.broken;
  });
  CHECK(force[0] == force[1]);
  CHECK(damage[0] == damage[1]);
  CHECK(broken[0] == broken[1]);
  CHECK(std::count(broken[0].begin(), broken[0].end(), 1) > 0);  // the jitter did break joints
}

TEST_CASE("a run with heterogeneity logs the factors' min, mean and max per material", "[heterogeneity]") {
  ydry_test::TempDir dir;
  ydry_test::block_deck(dir, "right");
  const auto r = ydry_test::run_ydry(dir.file("block.toml") + " -o " + dir.file("out") +
                                     " --quiet --set materials.soil.strength_heterogeneity=0.2 --set run.seed=3");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string log = ydry_test::read_text(dir.file("out/log.txt"));
  CHECK(log.find("materials.soil: strength factors of 29 joints (Weibull, mean 1, coefficient of variation 0.2") !=
        std::string::npos);
  CHECK(log.find("seed 3): min ") != std::string::npos);
}
