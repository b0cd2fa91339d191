#include "ycore/solid/substrate.h"

#include <cmath>

#include "ycore/state/blocked_sum.h"
#include "ycore/state/ownership.h"

namespace ydry {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The elastic stretch e of node i's traction, and the factor (<= 1) that caps its force.
struct Stretch {
  double x, y, capped;
};
inline Stretch stretch(const Nodes& n, const Substrate& b, std::size_t i) {
  Stretch e;
  e.x = n.x[i] - n.x0[i] - b.slide_x[i];
  e.y = n.y[i] - n.y0[i] - b.slide_y[i];
  const double pull = b.stiffness[i] * std::sqrt(e.x * e.x + e.y * e.y);
  e.capped = pull > b.cap[i] ? b.cap[i] / pull : 1.0;
  return e;
}

}  // namespace

void init_substrate(const Deck& deck, const Triangles& tri, const std::vector<MaterialModel>& materials,
                    std::size_t node_count, Substrate& b) {
  b = Substrate{};
  if (!deck.substrate) return;
  const SubstrateDeck& d = *deck.substrate;
  const double h = deck.thickness_m, tan_phi = std::tan(d.friction_angle_deg * kPi / 180.0);
  for (auto* v : {&b.stiffness, &b.cap, &b.slide_x, &b.slide_y}) v->assign(node_count, 0.0);
  for (std::size_t e = 0; e < tri.size(); ++e) {
    const MaterialModel& m = materials[tri.material[e]];
    if (!m.mechanical || m.rigid) continue;
    const double area = tri.area0[e] / 3.0;
    const double k_b = d.stiffness_pa_m.value_or(m.mu / h);
    for (int a = 0; a < 3; ++a) {
      const index_t i = corner_node(index_t(e), a);
      b.stiffness[i] = k_b * area;
      b.cap[i] = (d.adhesion_pa + tan_phi * m.density * d.gravity * h) * area;
    }
  }
}

void add_substrate_forces(const Substrate& b, const Ownership& ownership, Nodes& n) {
  if (!b.present()) return;
  for_each_owned(ownership.node_begin, n.size(), [&](std::size_t i) {
    const Stretch e = stretch(n, b, i);
    n.fx[i] -= b.stiffness[i] * e.capped * e.x;
    n.fy[i] -= b.stiffness[i] * e.capped * e.y;
  });
}

void commit_substrate_slide(const Nodes& n, const Ownership& ownership, Substrate& b) {
  if (!b.present()) return;
  const auto work = blocked_sum<1>(n.size(), [&](std::size_t i, std::array<double, 1>& sum) {
    const Stretch e = stretch(n, b, i);
    const double slide = 1.0 - e.capped;
    b.slide_x[i] += slide * e.x;
    b.slide_y[i] += slide * e.y;
    if (slide > 0.0) sum[0] += b.cap[i] * slide * std::sqrt(e.x * e.x + e.y * e.y);
  }, ownership.node_begin);
  b.slide_work_J += work[0];
}

double substrate_elastic_energy(const Nodes& n, const Substrate& b) {
  if (!b.present()) return 0.0;
  const auto energy = blocked_sum<1>(n.size(), [&](std::size_t i, std::array<double, 1>& sum) {
    const Stretch e = stretch(n, b, i);
    sum[0] += 0.5 * b.stiffness[i] * e.capped * e.capped * (e.x * e.x + e.y * e.y);
  });
  return energy[0];
}

Eigen::SparseMatrix<double> substrate_tangent(const Nodes& n, const Substrate& b, const FreeComponents& free) {
  Eigen::SparseMatrix<double> K(Eigen::Index(free.size()), Eigen::Index(free.size()));
  if (!b.present()) return K;
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!(b.stiffness[i] > 0.0)) continue;
    const Stretch e = stretch(n, b, i);
    double block[2][2] = {{1.0, 0.0}, {0.0, 1.0}};
    if (e.capped < 1.0) {  // sliding: no stiffness along the stretch, cap / |e| across it
      const double length2 = e.x * e.x + e.y * e.y;
      block[0][0] -= e.x * e.x / length2, block[1][1] -= e.y * e.y / length2;
      block[0][1] = block[1][0] = -e.x * e.y / length2;
    }
    const double k = b.stiffness[i] * e.capped;
    for (int r = 0; r < 2; ++r) {
      const index_t row = free.unknown[2 * i + r];
      if (row == kNoIndex) continue;
      for (int c = 0; c < 2; ++c) {
        const index_t column = free.unknown[2 * i + c];
        if (column != kNoIndex) entries.emplace_back(row, column, k * block[r][c]);
      }
    }
  }
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

}  // namespace ydry
