// The substrate of a plan-view layer (ycore/solid/substrate.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "ycore/driver/setup.h"
#include "ycore/solid/substrate.h"

using namespace ydry;

namespace {

// The shear-lag strip of verification/shear_lag, its substrate's cap lowered to `adhesion` Pa.
State strip_on_substrate(double adhesion) {
  const Deck deck = load_deck(YDRY_SOURCE_DIR "/verification/shear_lag/shear_lag.toml",
                              {"substrate.adhesion=" + std::to_string(adhesion)});
  return setup_state(deck);
}

// The substrate's forces alone at the state's positions, over the free components.
std::vector<double> substrate_forces(const State& s) {
  Nodes n = s.nodes;
  std::fill(n.fx.begin(), n.fx.end(), 0.0);
  std::fill(n.fy.begin(), n.fy.end(), 0.0);
  add_substrate_forces(s.substrate, s.ownership, n);
  std::vector<double> f;
  for (std::size_t i = 0; i < n.size(); ++i) f.push_back(n.fx[i]), f.push_back(n.fy[i]);
  return f;
}

}  // namespace

TEST_CASE("the substrate holds each node over a third of its triangle's area, k_b A and its cap (c_b + tan(phi_b) "
          "rho g h) A", "[substrate]") {
  const State s = strip_on_substrate(50.0);
  const double h = 0.004, k_b = 6.4e6;
  double area = 0, stiffness = 0, cap = 0;
  for (std::size_t e = 0; e < s.triangles.size(); ++e) area += s.triangles.area0[e];
  for (std::size_t i = 0; i < s.nodes.size(); ++i) stiffness += s.substrate.stiffness[i], cap += s.substrate.cap[i];
  CHECK(stiffness == Approx(k_b * area).epsilon(1e-12));
  CHECK(cap == Approx(50.0 * area).epsilon(1e-12));
  CHECK(area == Approx(0.2 * 0.005).epsilon(1e-12));
  // Derived from the layer's own shear where the deck gives no stiffness: G / h.
  const Deck derived = load_deck(YDRY_SOURCE_DIR "/verification/shear_lag/shear_lag.toml",
                                 {"substrate={adhesion = 1.0e6, friction_angle = 30.0}"});
  const State d = setup_state(derived);
  const double G = 1.0e6 / (2.0 * 1.2), tan_phi = std::tan(30.0 * 3.14159265358979323846 / 180.0);
  const index_t i = corner_node(0, 0);
  CHECK(d.substrate.stiffness[i] == Approx(G / h * d.triangles.area0[0] / 3.0).epsilon(1e-12));
  CHECK(d.substrate.cap[i] == Approx((1.0e6 + tan_phi * 1500.0 * 9.81 * h) * d.triangles.area0[0] / 3.0).epsilon(1e-12));
}

TEST_CASE("the substrate's tangent is the derivative of its forces, stuck and sliding, and a committed slide "
          "leaves the traction at its cap", "[substrate]") {
  // Displacements of 0 to 2.1e-5 m: with k_b = 6.4e6 Pa/m and a cap of 100 Pa the traction
  // caps above 1.56e-5 m, so some of the nodes slide.
  State s = strip_on_substrate(100.0);
  Nodes& n = s.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    n.x[i] += 1.5e-5 * std::sin(1.0 + 3.0 * double(i)), n.y[i] += 1.5e-5 * std::cos(2.0 * double(i));
  }
  std::size_t sliding = 0;
  for (std::size_t i = 0; i < n.size(); ++i)
    sliding += s.substrate.stiffness[i] * std::hypot(n.x[i] - n.x0[i], n.y[i] - n.y0[i]) > s.substrate.cap[i];
  REQUIRE(sliding > n.size() / 4);
  REQUIRE(sliding < 3 * n.size() / 4);
  const FreeComponents free = free_components(n, s.triangles, s.materials);
  const Eigen::SparseMatrix<double> K = substrate_tangent(n, s.substrate, free);
  // Central differences of each component, 1e-9 m: the force is smooth within a node's stuck
  // or sliding branch, which no node is that close to the edge of (measured: 2.4e-9 of the largest).
  const double step = 1e-9;
  double worst = 0, scale = 0;
  for (std::size_t u = 0; u < free.size(); u += 7) {
    const index_t c = free.component[u], i = c / 2;
    double& coordinate = c % 2 == 0 ? n.x[i] : n.y[i];
    const double at = coordinate;
    coordinate = at + step;
    const std::vector<double> plus = substrate_forces(s);
    coordinate = at - step;
    const std::vector<double> minus = substrate_forces(s);
    coordinate = at;
    for (int r = 0; r < 2; ++r) {
      const double derivative = -(plus[2 * i + r] - minus[2 * i + r]) / (2.0 * step);
      const index_t row = free.unknown[2 * i + r];
      worst = std::max(worst, std::fabs(derivative - K.coeff(row, Eigen::Index(u))));
      scale = std::max(scale, std::fabs(derivative));
    }
  }
  CHECK(worst <= 1e-6 * scale);
  // The slide committed: every node's traction is then at most its cap, exactly at it where it
  // slid, and each keeps its direction.
  const std::vector<double> before = substrate_forces(s);
  commit_substrate_slide(n, s.ownership, s.substrate);
  const std::vector<double> after = substrate_forces(s);
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double cap = s.substrate.cap[i];
    CHECK(std::hypot(after[2 * i], after[2 * i + 1]) <= cap * (1.0 + 1e-12));
    CHECK(after[2 * i] == Approx(before[2 * i]).margin(1e-12 * cap));
    CHECK(after[2 * i + 1] == Approx(before[2 * i + 1]).margin(1e-12 * cap));
  }
}

TEST_CASE("the substrate books what a node pulled along a line past its cap does: the traction's energy stored "
          "and the cap times the slide dissipated", "[substrate]") {
  // One node of the strip, its traction first set to zero, pulled in 400 steps along a fixed
  // direction to 4 times the stretch at which its traction reaches the cap, the slide
  // committed after each step. The stored energy grows by cap^2 / (2 k), the slides' work by
  // cap (d - cap / k), and their sum is the work the pull does, the trapezoid of the
  // substrate's force over each step: exact on each step but the one that passes the cap (its
  // error at most k du^2 / 8, 2e-6 of the total). The other nodes, at rest, add nothing, but
  // their stored energy, some 5,000 times this node's, is subtracted: its round-off, about
  // 1e-12 of this node's, is why the ledger is checked to 1e-9 and not to 1e-15.
  State s = strip_on_substrate(50.0);
  const std::size_t i = s.nodes.size() / 2;
  const double k = s.substrate.stiffness[i], cap = s.substrate.cap[i];
  s.substrate.slide_x[i] = s.nodes.x[i] - s.nodes.x0[i];
  s.substrate.slide_y[i] = s.nodes.y[i] - s.nodes.y0[i];
  commit_substrate_slide(s.nodes, s.ownership, s.substrate);
  const double stored0 = substrate_elastic_energy(s.nodes, s.substrate), slid0 = s.substrate.slide_work_J;
  const double reach = 4.0 * cap / k, dx = 0.6 * reach / 400.0, dy = 0.8 * reach / 400.0;
  std::vector<double> before = substrate_forces(s);
  double work = 0.0;
  for (int step = 0; step < 400; ++step) {
    s.nodes.x[i] += dx, s.nodes.y[i] += dy;
    const std::vector<double> after = substrate_forces(s);
    work -= 0.5 * ((before[2 * i] + after[2 * i]) * dx + (before[2 * i + 1] + after[2 * i + 1]) * dy);
    commit_substrate_slide(s.nodes, s.ownership, s.substrate);
    before = substrate_forces(s);
  }
  const double stored = substrate_elastic_energy(s.nodes, s.substrate) - stored0;
  const double slid = s.substrate.slide_work_J - slid0;
  INFO("stored " << stored << ", slid " << slid << ", work " << work);
  CHECK(std::fabs(stored - cap * cap / (2.0 * k)) <= 1e-9 * stored);
  CHECK(std::fabs(slid - cap * (reach - cap / k)) <= 1e-9 * slid);
  CHECK(std::fabs(stored + slid - work) <= 1e-5 * work);
}
