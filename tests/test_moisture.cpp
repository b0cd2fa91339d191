// The moisture scheme (paper Eqs. 1-8, 20): the per-triangle inflows, the stable step, the
// water balance, thread invariance, the 5 mm strip against the closed form, and the exchange
// through crack faces (Eqs. 10-17).
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "tests/test_support.h"
#include "ycore/driver/setup.h"
#include "ycore/driver/coupling.h"
#include "ycrack/node_sharing.h"
#include "ycrack/precracks.h"
#include "ymoist/moisture_setup.h"
#include "ymoist/moisture_step.h"

using namespace ydry;
using ydry_test::strip_deck;

namespace {

// Eq. 20: the semi-infinite strip with a constant inflow q through x = 0.
double strip_closed_form(double x, double t, double q, double k, double rho) {
  const double kappa = k / rho;
  return 2.0 * q / k *
         (std::sqrt(kappa * t / M_PI) * std::exp(-x * x / (4.0 * kappa * t)) -
          0.5 * x * std::erfc(x / (2.0 * std::sqrt(kappa * t))));
}

// The two-material Gmsh mesh (unstructured, so triangles of every shape), both wet.
Deck unstructured_deck() {
  return load_deck(YDRY_SOURCE_DIR "/tests/data/two_materials.toml",
                   {"materials.base.moisture_conductivity=7.0e-6", "materials.base.initial_moisture=0.1"});
}

}  // namespace

TEST_CASE("triangle inflows are -k t A grad N_i . grad w and sum to zero (Eq. 8)", "[moisture]") {
  const Deck deck = unstructured_deck();
  State s = setup_state(deck);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 0.5);
  for (double& w : s.moisture.w) w = uniform(rng);
  const std::vector<double> w_before = s.moisture.w;
  moisture_step(s.nodes, 1e-3, s.moisture_elements, s.moisture, s.water);  // fills corner_inflow from w_before

  for (index_t t = 0; t < s.triangles.size(); ++t) {
    const double k = s.material_names[s.triangles.material[t]] == "soil" ? 2.0e-6 : 7.0e-6;
    const index_t c = corner_node(t, 0);
    const double* x = &s.nodes.x0[c];
    const double* y = &s.nodes.y0[c];
    const double area = 0.5 * ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]));
    double gradN[3][2], gradw[2] = {0, 0};
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, d = (a + 2) % 3;
      gradN[a][0] = (y[b] - y[d]) / (2 * area);
      gradN[a][1] = (x[d] - x[b]) / (2 * area);
      const double w = w_before[s.nodes.mnode[c + a]];
      gradw[0] += w * gradN[a][0];
      gradw[1] += w * gradN[a][1];
    }
    double sum = 0, scale = 0;
    for (int a = 0; a < 3; ++a) {
      const double expected = -k * 0.05 * area * (gradN[a][0] * gradw[0] + gradN[a][1] * gradw[1]);
      const double got = s.moisture_elements.corner_inflow[c + a];
      CHECK(got == Approx(expected).epsilon(1e-12).margin(1e-25));
      sum += got;
      scale += std::abs(got);
    }
    CHECK(std::abs(sum) <= 1e-12 * scale + 1e-30);
  }
}

TEST_CASE("the stable moisture step is within the true explicit limit 2 / lambda_max", "[moisture]") {
  for (const char* pattern : {"\"right\"", "\"cross\""}) {
    State s = setup_state(strip_deck({"mesh.element_size=0.0025", std::string("mesh.pattern=") + pattern}));
    const double dt_bound = stable_moisture_step(s.moisture, s.moisture_elements, 1.0);
    // Probe A = M^-1 K column by column: one step from w = e_j gives w' = e_j - dt A e_j.
    // The strip's only boundary term is a constant flux, so switch it off for the probe.
    std::fill(s.moisture.term_rate.begin(), s.moisture.term_rate.end(), 0.0);
    const index_t n = static_cast<index_t>(s.moisture.size());
    Eigen::MatrixXd A(n, n);
    for (index_t j = 0; j < n; ++j) {
      std::fill(s.moisture.w.begin(), s.moisture.w.end(), 0.0);
      s.moisture.w[j] = 1.0;
      moisture_step(s.nodes, 1.0, s.moisture_elements, s.moisture, s.water);
      for (index_t i = 0; i < n; ++i) A(i, j) = (i == j ? 1.0 : 0.0) - s.moisture.w[i];
    }
    const double lambda_max = A.eigenvalues().real().maxCoeff();
    INFO("pattern " << pattern << ": bound " << dt_bound << " s, 2/lambda_max " << 2.0 / lambda_max << " s");
    CHECK(dt_bound <= 2.0 / lambda_max * (1 + 1e-12));
    CHECK(dt_bound >= 0.5 * 2.0 / lambda_max);  // Gershgorin is not wildly conservative here
  }
}

TEST_CASE("water in through a flux boundary equals rate x length x thickness x time", "[moisture]") {
  const double rate = 1e-5, thickness = 0.05, height = 0.01, duration = 3.0e5;
  State s = setup_state(strip_deck({"run.thickness=0.05"}));
  advance_to(s, strip_deck({"run.thickness=0.05"}), duration,
             stable_moisture_step(s.moisture, s.moisture_elements, 0.9));
  const double expected = rate * height * thickness * duration;
  CHECK(total_water_kg(s.moisture) - s.water.initial_kg == Approx(expected).epsilon(1e-12));
  CHECK(s.water.net_in_kg + s.water.net_in_carry == Approx(expected).epsilon(1e-12));
  CHECK(water_balance_error(s.moisture, s.water) < 1e-12);
}

TEST_CASE("moisture steps are bitwise identical at 1 and 2 threads", "[moisture][determinism]") {
  const Deck deck = strip_deck({"mesh.element_size=0.002", "mesh.pattern=\"cross\""});
  std::vector<double> w[2];
  ydry_test::on_1_and_2_threads([&](int threads) {
    State s = setup_state(deck);
    advance_to(s, deck, 2.0e5, stable_moisture_step(s.moisture, s.moisture_elements, 0.9));
    w[threads - 1] = s.moisture.w;
  });
  CHECK(w[0] == w[1]);
}

TEST_CASE("the 5 mm strip matches Eq. 20 within 0.5 % (relative L2) at 800k s", "[moisture][verification]") {
  const Deck deck = strip_deck();
  State s = setup_state(deck);
  advance_to(s, deck, 8.0e5, stable_moisture_step(s.moisture, s.moisture_elements, deck.moisture_safety));
  double err2 = 0, ref2 = 0;
  for (index_t i = 0; i < s.moisture.size(); ++i) {
    const index_t c = s.moisture.corner[s.moisture.corner_offset[i]];
    const double exact = strip_closed_form(s.nodes.x0[c], 8.0e5, 1e-5, 1e-6, 1333.0);
    err2 += std::pow(s.moisture.w[i] - exact, 2);
    ref2 += exact * exact;
  }
  const double l2 = std::sqrt(err2 / ref2);
  INFO("relative L2 error " << l2);
  CHECK(l2 <= 0.005);
  CHECK(water_balance_error(s.moisture, s.water) < 1e-12);
}

TEST_CASE("a joint that breaks splits the moisture nodes: water is conserved and no longer crosses", "[moisture][mechanics]") {
  // The mode I bar of the verification, wetted from its fixed left side while it is pulled
  // apart across its middle line of joints.
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/fracture_modeI/fracture_modeI.toml",
                              {"materials.bar.moisture_conductivity=1e-8", "materials.bar.initial_moisture=0.2",
                               "materials.bar.shrinkage_coefficient=0.0",
                               "moisture.boundary=[{on=\"left\",type=\"flux\",rate=1e-5}]"});
  State s = setup_state(deck);
  const std::size_t intact_nodes = s.moisture.size();
  double step = advance_to(s, deck, 300.0, coupling_step_limit(s, deck));
  REQUIRE(std::count(s.joints.broken.begin(), s.joints.broken.end(), 1) == 4);
  CHECK(s.moisture.size() == intact_nodes + 5);  // the five vertices of the cut line split
  CHECK(water_balance_error(s.moisture, s.water) < 1e-12);
  const auto right_half_water = [&] {
    double water = 0;
    for (std::size_t i = 0; i < s.moisture.size(); ++i) {
      const index_t c = corner_node(triangle_of(s.moisture.corner[s.moisture.corner_offset[i]]), 0);
      const double centroid_x = (s.nodes.x0[c] + s.nodes.x0[c + 1] + s.nodes.x0[c + 2]) / 3.0;
      if (centroid_x > 0.001) water += s.moisture.w[i] * s.moisture.dry_mass[i];  // a right-column triangle's
    }
    return water;
  };
  const double right_before = right_half_water(), total_before = total_water_kg(s.moisture);
  step = advance_to(s, deck, 600.0, step);
  CHECK(total_water_kg(s.moisture) > total_before * 1.001);          // the left half keeps taking water in
  CHECK(right_half_water() == Approx(right_before).epsilon(1e-12));  // the right half gets none of it
  CHECK(water_balance_error(s.moisture, s.water) < 1e-12);
}

namespace {

constexpr double kCrackH = 2.0e-4, kCrackAir = 0.05, kThickness = 0.05;  // h_c, w_e, t

// The strip's material on `size` (TOML, m) of 5 mm cells, 5 cm thick, with no boundary terms
// but the faces of the deck's [[cracks]] `cracks` (TOML), which exchange with air at
// w_e = 0.05 with h_c = 2e-4 kg/(m^2 s).
Deck crack_exchange_deck(const std::string& size, const std::string& cracks) {
  return strip_deck({"mesh.size=" + size, "run.thickness=0.05", "moisture.boundary=[]", "cracks=" + cracks,
                     "moisture.cracks.exchange_coefficient=2e-4", "moisture.cracks.air_moisture=0.05"});
}

// Random w in [0.1, 0.6] at every moisture node.
void randomize_moisture(State& s) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(0.1, 0.6);
  for (double& w : s.moisture.w) w = uniform(rng);
}

}  // namespace

TEST_CASE("one crack face takes in h_c (w_e - (w1 + w2)/2) L t, half at each end (Eqs. 10-11)", "[moisture][crack]") {
  // Two cells side by side, split by a crack through the whole height: its one joint has four
  // distinct end nodes. Face 2 is held at w_e, so only face 1 exchanges.
  const Deck deck = crack_exchange_deck("[0.01, 0.005]", "[{from=[0.005, 0.0], to=[0.005, 0.005]}]");
  State s = setup_state(deck);
  REQUIRE(std::count(s.joints.broken.begin(), s.joints.broken.end(), 1) == 1);
  const std::size_t j = std::find(s.joints.broken.begin(), s.joints.broken.end(), 1) - s.joints.broken.begin();
  index_t node[4];
  for (int k = 0; k < 4; ++k) node[k] = s.nodes.mnode[s.joints.node[4 * j + k]];
  REQUIRE(std::set<index_t>(node, node + 4).size() == 4);
  randomize_moisture(s);
  s.moisture.w[node[2]] = s.moisture.w[node[3]] = kCrackAir;
  s.water.initial_kg = total_water_kg(s.moisture);
  const double w1 = s.moisture.w[node[0]], w2 = s.moisture.w[node[1]], length = 0.005;

  const double dt = stable_moisture_step(s.moisture, s.moisture_elements, 0.9);
  moisture_step(s.nodes, dt, s.moisture_elements, s.moisture, s.water);
  const double face_kg = kCrackH * (kCrackAir - 0.5 * (w1 + w2)) * length * kThickness * dt;  // Eq. 10
  CHECK(s.moisture.boundary_inflow[node[0]] == Approx(0.5 * kCrackH * (kCrackAir - w1) * length * kThickness).epsilon(1e-15));
  CHECK(s.moisture.boundary_inflow[node[1]] == Approx(0.5 * kCrackH * (kCrackAir - w2) * length * kThickness).epsilon(1e-15));
  CHECK(s.moisture.boundary_inflow[node[2]] == 0.0);
  CHECK(s.moisture.boundary_inflow[node[3]] == 0.0);
  CHECK(s.water.net_in_kg + s.water.net_in_carry == Approx(face_kg).epsilon(1e-15));
  CHECK(total_water_kg(s.moisture) - s.water.initial_kg == Approx(face_kg).epsilon(1e-12));  // the difference loses digits
  CHECK(water_balance_error(s.moisture, s.water) < 1e-15);
}

TEST_CASE("a crack tip stays one node and takes in through both faces (Eqs. 14-17)", "[moisture][crack]") {
  // 2 x 2 cells, a crack from the top down to the centre vertex, its tip.
  const Deck deck = crack_exchange_deck("[0.01, 0.01]", "[{from=[0.005, 0.01], to=[0.005, 0.005]}]");
  State s = setup_state(deck);
  std::set<index_t> tip;
  for (index_t c = 0; c < s.nodes.size(); ++c)
    if (s.nodes.x0[c] == 0.005 && s.nodes.y0[c] == 0.005) tip.insert(s.nodes.mnode[c]);
  REQUIRE(tip.size() == 1);
  const index_t i = *tip.begin();
  REQUIRE(s.moisture.term_offset[i + 1] - s.moisture.term_offset[i] == 2);  // a half of each face
  randomize_moisture(s);
  const double w_tip = s.moisture.w[i];
  moisture_step(s.nodes, stable_moisture_step(s.moisture, s.moisture_elements, 0.9), s.moisture_elements, s.moisture,
                s.water);
  // Eqs. 15-16 with the tip's own w (doc/physics.md "Cracks and moisture"): two halves of 5 mm faces.
  CHECK(s.moisture.boundary_inflow[i] == Approx(kCrackH * (kCrackAir - w_tip) * 0.005 * kThickness).epsilon(1e-15));
}

TEST_CASE("crack faces exchange the same whether the crack is in the deck or breaks later", "[moisture][crack]") {
  // The terms are rebuilt when the nodes regroup; the water balance counts them.
  const std::string crack = "[{from=[0.005, 0.01], to=[0.005, 0.0]}, {from=[0.0, 0.005], to=[0.005, 0.005]}]";
  const Deck precracked = crack_exchange_deck("[0.01, 0.01]", crack);
  const Deck intact = crack_exchange_deck("[0.01, 0.01]", "[]");
  const State expected = setup_state(precracked);
  State s = setup_state(intact);
  CHECK(s.moisture.term_kind.empty());
  const std::vector<index_t> old_mnode = s.nodes.mnode;
  const std::vector<double> old_w = s.moisture.w;
  break_joints_along_cracks(s.nodes, precracked.cracks, s.joints);
  group_moisture_nodes(s.joints, s.triangles, std::vector<std::uint8_t>(s.triangles.size(), 1), s.nodes, s.moisture);
  remap_moisture_nodes(moisture_mesh(s), intact, old_mnode, old_w,
                       s.moisture);
  REQUIRE(expected.moisture.term_kind.size() == 4 * 3);  // three broken joints, four halves each
  CHECK(s.moisture.term_offset == expected.moisture.term_offset);
  CHECK(s.moisture.term_kind == expected.moisture.term_kind);
  CHECK(s.moisture.term_area == expected.moisture.term_area);
  CHECK(s.moisture.term_rate == expected.moisture.term_rate);
  CHECK(s.moisture.term_level == expected.moisture.term_level);
  CHECK(s.moisture.boundary_node == expected.moisture.boundary_node);

  randomize_moisture(s);
  s.water.initial_kg = total_water_kg(s.moisture);
  advance_to(s, intact, 1.0e6, stable_moisture_step(s.moisture, s.moisture_elements, 0.9));
  CHECK(std::abs(mean_moisture(s.moisture) - kCrackAir) < 1e-3);  // the air in the cracks has drawn the soil to w_e
  CHECK(water_balance_error(s.moisture, s.water) < 1e-14);
}

TEST_CASE("a layer seen in plan view dries through its face uniformly: w falls by rate t / (rho h) at every node, "
          "exchange decays w - w_e as exp(-h_c t / (rho h))", "[moisture][planview]") {
  // The shear-lag strip without its solid: a flux out of its face takes rate A t from a dry
  // mass rho h A, the same at every node, so no gradient forms and w stays uniform.
  const double rate = -1e-4, rho = 1500.0, h = 0.004, duration = 1000.0, w0 = 0.3;
  const std::vector<std::string> flux = {"run.mechanics=false", "run.end_time=1000", "run.output_interval=1000",
                                         "moisture.boundary=[{on = \"face\", type = \"flux\", rate = -1e-4}]"};
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/shear_lag/shear_lag.toml", flux);
  State s = setup_state(deck);
  advance_to(s, deck, duration, coupling_step_limit(s, deck));
  double area = 0;
  for (std::size_t e = 0; e < s.triangles.size(); ++e) area += s.triangles.area0[e];
  CHECK(total_water_kg(s.moisture) - s.water.initial_kg == Approx(rate * area * duration).epsilon(1e-12));
  CHECK(water_balance_error(s.moisture, s.water) < 1e-12);
  for (const double w : s.moisture.w) CHECK(w == Approx(w0 + rate * duration / (rho * h)).epsilon(1e-12));
  // Exchange with the air: d(w - w_e)/dt = -h_c (w - w_e) / (rho h), integrated by explicit
  // steps: each multiplies w - w_e by 1 - h_c dt / (rho h), which is exp(-h_c dt / (rho h)) to
  // its second-order term, so the error is that term over the steps.
  const double h_c = 1e-4, w_e = 0.1;
  const Deck exchange = load_deck(YDRY_SOURCE_DIR "/verification/shear_lag/shear_lag.toml",
                                  {"run.mechanics=false", "run.end_time=1000", "run.output_interval=1000",
                                   "moisture.boundary=[{on = \"face\", type = \"exchange\", coefficient = 1e-4, "
                                   "air_moisture = 0.1}]"});
  State x = setup_state(exchange);
  advance_to(x, exchange, duration, coupling_step_limit(x, exchange));
  const double exact = w_e + (w0 - w_e) * std::exp(-h_c * duration / (rho * h));
  for (const double w : x.moisture.w) CHECK(w == Approx(exact).epsilon(1e-4));  // measured 1.6e-5
  CHECK(water_balance_error(x.moisture, x.water) < 1e-12);
}
