// The explicit moisture kernels. Two flat loops, neither of which scatters: triangles write
// their own corners' inflows, then each moisture node gathers its corners and boundary terms
// in a fixed (CSR) order. So there are no races, no atomics, and the result is bitwise the
// same for any number of threads.
#include "ymoist/moisture_step.h"

#include <cmath>
#include <limits>

#include "ycore/state/blocked_sum.h"

namespace ydry {
namespace {

// Conductance entry (a, b) of a triangle's packed symmetric matrix K00 K01 K02 K11 K12 K22.
inline double conductance_entry(const double* K, int a, int b) {
  static constexpr int packed[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  return K[packed[a][b]];
}

// kg/s into a node of moisture w through one term.
inline double term_inflow(MoistureTermKind kind, double area, double rate, double level, double w) {
  if (kind == MoistureTermKind::exchange) return rate * (level - w) * area;  // Eqs. 10-11
  return (rate < 0.0 && w <= level) ? 0.0 : rate * area;  // flux out stops at the residual
}

// Neumaier-compensated sum += x.
inline void compensated_add(double& sum, double& carry, double x) {
  const double t = sum + x;
  carry += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
  sum = t;
}

}  // namespace

double stable_moisture_step(const MoistureNodes& m, const MoistureElements& elements, double safety) {
  const std::vector<double>& K = elements.conductance;
  double dt = std::numeric_limits<double>::infinity();
  for (index_t i = 0; i < m.size(); ++i) {
    if (!std::isnan(m.fixed_w[i])) continue;  // prescribed, never integrated
    double row = 0.0;  // K_ii + sum_j |K_ij| + exchange coefficients
    for (index_t k = m.corner_offset[i]; k < m.corner_offset[i + 1]; ++k) {
      const index_t c = m.corner[k];
      const double* Kt = &K[6 * std::size_t(triangle_of(c))];
      const int a = static_cast<int>(c % 3);
      for (int b = 0; b < 3; ++b) row += std::abs(conductance_entry(Kt, a, b));
    }
    for (index_t k = m.term_offset[i]; k < m.term_offset[i + 1]; ++k)
      if (m.term_kind[k] == MoistureTermKind::exchange) row += m.term_rate[k] * m.term_area[k];
    if (row > 0.0) dt = std::min(dt, 2.0 * m.dry_mass[i] / row);
  }
  return safety * dt;
}

void moisture_step(const Nodes& nodes, double dt, MoistureElements& elements, MoistureNodes& m,
                   WaterBalance& wb) {
  const std::vector<index_t>& mnode = nodes.mnode;
  const double* K = elements.conductance.data();
  double* corner_inflow = elements.corner_inflow.data();
  const std::int64_t nt = static_cast<std::int64_t>(nodes.size() / 3);  // 3 corners per triangle
  const std::int64_t nm = static_cast<std::int64_t>(m.size());

  // Eq. 4 per triangle: inflow into corner a = -sum_b K_ab w_b; the three sum to zero (Eq. 8).
#pragma omp parallel for schedule(static) if (std::size_t(nt) > parallel_minimum)
  for (std::int64_t t = 0; t < nt; ++t) {
    const index_t c0 = corner_node(static_cast<index_t>(t), 0);
    if (mnode[c0] == kNoIndex) continue;
    const double* Kt = K + 6 * t;
    const double w0 = m.w[mnode[c0]], w1 = m.w[mnode[c0 + 1]], w2 = m.w[mnode[c0 + 2]];
    corner_inflow[c0] = -(Kt[0] * w0 + Kt[1] * w1 + Kt[2] * w2);
    corner_inflow[c0 + 1] = -(Kt[1] * w0 + Kt[3] * w1 + Kt[4] * w2);
    corner_inflow[c0 + 2] = -(Kt[2] * w0 + Kt[4] * w1 + Kt[5] * w2);
  }

  // Eqs. 5-7 per moisture node: the inflows of its corners' triangles (Eq. 5; Eq. 9 and Eq.
  // 14 where a crack has split or ends at the node, as its corners are only those on its side)
  // plus its boundary and crack-face terms (Eq. 13, Eq. 17), over its dry mass (Eq. 6).
#pragma omp parallel for schedule(static) if (std::size_t(nm) > parallel_minimum)
  for (std::int64_t i = 0; i < nm; ++i) {
    double inflow = 0.0;
    for (index_t k = m.corner_offset[i]; k < m.corner_offset[i + 1]; ++k) inflow += corner_inflow[m.corner[k]];
    double boundary = 0.0;
    for (index_t k = m.term_offset[i]; k < m.term_offset[i + 1]; ++k)
      boundary += term_inflow(m.term_kind[k], m.term_area[k], m.term_rate[k], m.term_level[k], m.w[i]);
    if (std::isnan(m.fixed_w[i])) {
      m.w[i] += dt * (inflow + boundary) / m.dry_mass[i];
    } else {
      // A fixed node takes whatever keeps it at its value: that water crossed the boundary.
      boundary = (m.fixed_w[i] - m.w[i]) * m.dry_mass[i] / dt - inflow;
      m.w[i] = m.fixed_w[i];
    }
    m.boundary_inflow[i] = boundary;
  }

  // Book the boundary water in a fixed order (few nodes; serial keeps it thread-invariant).
  for (const index_t i : m.boundary_node) {
    const double kg = m.boundary_inflow[i] * dt;
    compensated_add(wb.net_in_kg, wb.net_in_carry, kg);
    wb.gross_kg += std::abs(kg);
  }
}

double total_water_kg(const MoistureNodes& m) {
  double sum = 0.0, carry = 0.0;
  for (index_t i = 0; i < m.size(); ++i) compensated_add(sum, carry, m.w[i] * m.dry_mass[i]);
  return sum + carry;
}

double mean_moisture(const MoistureNodes& m) {
  double dry = 0.0;
  for (const double md : m.dry_mass) dry += md;
  return dry > 0.0 ? total_water_kg(m) / dry : std::numeric_limits<double>::quiet_NaN();
}

double water_balance_error(const MoistureNodes& m, const WaterBalance& wb) {
  const double scale = std::max(wb.initial_kg, wb.gross_kg);
  if (scale == 0.0) return 0.0;
  return std::abs(total_water_kg(m) - wb.initial_kg - (wb.net_in_kg + wb.net_in_carry)) / scale;
}

}  // namespace ydry
