#include "ycore/solid/stiffness_model.h"

#include <algorithm>
#include <cmath>

namespace ydry {

void StiffnessPattern::analyse(const Eigen::SparseMatrix<double>& A, StiffnessSolver& solver) {
  const auto same = [](const std::vector<int>& kept, const int* now, Eigen::Index size) {
    return kept.size() == std::size_t(size) && std::equal(kept.begin(), kept.end(), now);
  };
  if (same(outer_, A.outerIndexPtr(), A.outerSize() + 1) && same(inner_, A.innerIndexPtr(), A.nonZeros())) return;
  solver.analyzePattern(A);
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

Eigen::VectorXd out_of_balance(const FreeComponents& free, const Nodes& n) {
  Eigen::VectorXd f(Eigen::Index(free.size()));
  for (std::size_t u = 0; u < free.size(); ++u) {
    const index_t c = free.component[u];
    f[Eigen::Index(u)] = c % 2 == 0 ? n.fx[c / 2] : n.fy[c / 2];
  }
  return f;
}

Eigen::VectorXd free_masses(const FreeComponents& free, const Nodes& n) {
  Eigen::VectorXd mass(Eigen::Index(free.size()));
  for (std::size_t u = 0; u < free.size(); ++u) mass[Eigen::Index(u)] = n.m[free.component[u] / 2];
  return mass;
}

Eigen::SparseMatrix<double> model_tangent(const Eigen::SparseMatrix<double>& K_solid, const std::vector<ContactLink>& links,
                                          const std::vector<std::uint8_t>& active, const FreeComponents& free) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(72 * links.size());  // two 6 x 6 blocks a link
  add_link_stiffness(links, active, free.unknown, entries);
  Eigen::SparseMatrix<double> K(K_solid.rows(), K_solid.cols());
  K.setFromTriplets(entries.begin(), entries.end());
  return K_solid + K;
}

void limit_move(const FreeComponents& free, double limit, Eigen::VectorXd& du) {
  if (!(limit > 0.0)) return;
  // A node's unknowns are consecutive (free_components numbers them in node order).
  double longest2 = 0.0;
  for (std::size_t u = 0; u < free.size();) {
    const index_t node = free.component[u] / 2;
    double move2 = 0.0;
    for (; u < free.size() && free.component[u] / 2 == node; ++u) move2 += du[Eigen::Index(u)] * du[Eigen::Index(u)];
    longest2 = std::max(longest2, move2);
  }
  const double longest = std::sqrt(longest2);
  if (longest > limit) du *= limit / longest;
}

namespace {

// nnz(L) of the symbolic factorisation of A with the ordering.
template <class Ordering>
Eigen::Index symbolic_fill(const Eigen::SparseMatrix<double>& A) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Ordering> solver;
  solver.analyzePattern(A);
  return solver.matrixL().nestedExpression().nonZeros();
}

}  // namespace

FillOrdering fill_ordering(const Triangles& tri, const Joints& jt, const std::vector<MaterialModel>& materials,
                           const FreeComponents& free, Mechanics& m) {
  if (m.fill_ordering != FillOrdering::undecided) return m.fill_ordering;
  // The pattern of the tangent with every part in it (tangent.cpp): a block between the free
  // components of each part's nodes.
  std::vector<Eigen::Triplet<double>> entries;
  const auto add_part = [&](const index_t* node, int corners) {
    for (int r = 0; r < 2 * corners; ++r) {
      const index_t row = free.unknown[2 * std::size_t(node[r / 2]) + r % 2];
      if (row == kNoIndex) continue;
      for (int c = 0; c < 2 * corners; ++c) {
        const index_t column = free.unknown[2 * std::size_t(node[c / 2]) + c % 2];
        if (column != kNoIndex) entries.emplace_back(row, column, row == column ? 1.0 : 0.0);
      }
    }
  };
  for (std::size_t e = 0; e < tri.size(); ++e) {
    if (!materials[tri.material[e]].mechanical) continue;
    const index_t node[3] = {corner_node(index_t(e), 0), corner_node(index_t(e), 1), corner_node(index_t(e), 2)};
    add_part(node, 3);
  }
  for (std::size_t j = 0; j < jt.size(); ++j)
    if (materials[jt.law[j]].mechanical) add_part(&jt.node[4 * j], 4);
  Eigen::SparseMatrix<double> A(Eigen::Index(free.size()), Eigen::Index(free.size()));
  A.setFromTriplets(entries.begin(), entries.end());
  m.fill_ordering = symbolic_fill<Eigen::MetisOrdering<int>>(A) < symbolic_fill<Eigen::AMDOrdering<int>>(A)
                        ? FillOrdering::metis
                        : FillOrdering::amd;
  return m.fill_ordering;
}

ChordFactor& chord_factor(Mechanics& m) {
  if (!m.chord_factor) m.chord_factor = std::make_shared<ChordFactor>(m.fill_ordering);
  ChordFactor& held = *m.chord_factor;
  if (held.values == m.chord_values && held.inner == m.chord_inner && held.outer == m.chord_outer) return held;
  const Eigen::Index n = Eigen::Index(m.chord_outer.size()) - 1;
  std::vector<int> outer(m.chord_outer.begin(), m.chord_outer.end()), inner(m.chord_inner.begin(), m.chord_inner.end());
  const Eigen::Map<const Eigen::SparseMatrix<double>> A(n, n, Eigen::Index(m.chord_values.size()), outer.data(), inner.data(),
                                                         m.chord_values.data());
  held.solver.analyzePattern(A);
  held.solver.factorize(A);
  held.outer = m.chord_outer, held.inner = m.chord_inner, held.values = m.chord_values;
  return held;
}

void keep_chord_factor(const Eigen::SparseMatrix<double>& matrix, const FreeComponents& free,
                       const std::shared_ptr<ChordFactor>& factor, Mechanics& m) {
  Eigen::SparseMatrix<double> A = matrix;
  A.makeCompressed();
  m.chord_components = free.component;
  m.chord_outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  m.chord_inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  m.chord_values.assign(A.valuePtr(), A.valuePtr() + A.nonZeros());
  factor->outer = m.chord_outer, factor->inner = m.chord_inner, factor->values = m.chord_values;
  m.chord_factor = factor;
}

}  // namespace ydry
