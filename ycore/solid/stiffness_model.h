// The linear algebra of the implicit equilibrium solver (newton.cpp; doc/solver.md
// "Quasi-static equilibrium"): the solid's stiffness with the contact links, its sparse LDL^T
// factorisation, and the vectors over the free components.
#pragma once

#include <iostream>  // Eigen 3.4's MetisSupport uses std::cerr without including it

#include <Eigen/MetisSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cstdint>
#include <memory>
#include <vector>

#include "ycore/contact/contact_tangent.h"
#include "ycore/solid/tangent.h"
#include "ycore/state/state.h"

namespace ydry {

// The sparse LDL^T factorisation of the stiffness with a fill-reducing ordering: AMD or METIS
// nested dissection, whichever fills the mesh's factor less (fill_ordering). On the Peron
// meshes, strips 25 times longer than high, AMD fills less and factorises 1.1-1.4 times faster;
// on square meshes METIS does, 1.25 times faster at 60,000 unknowns and 3.9 times at 670,000
// (bench/bench_factorisation.cpp, doc/solver.md "Linear algebra").
class StiffnessSolver {
 public:
  using Matrix = Eigen::SparseMatrix<double>;
  explicit StiffnessSolver(FillOrdering ordering) : metis_(ordering == FillOrdering::metis) {}
  void analyzePattern(const Matrix& A) { metis_ ? by_metis_.analyzePattern(A) : by_amd_.analyzePattern(A); }
  void factorize(const Matrix& A) { metis_ ? by_metis_.factorize(A) : by_amd_.factorize(A); }
  Eigen::ComputationInfo info() const { return metis_ ? by_metis_.info() : by_amd_.info(); }
  Eigen::VectorXd vectorD() const { return metis_ ? by_metis_.vectorD() : by_amd_.vectorD(); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    return metis_ ? Eigen::VectorXd(by_metis_.solve(b)) : Eigen::VectorXd(by_amd_.solve(b));
  }

 private:
  bool metis_;
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::AMDOrdering<int>> by_amd_;
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::MetisOrdering<int>> by_metis_;
};

// The ordering of this mesh's factorisations, kept in mechanics.fill_ordering: the one whose
// symbolic factor of the whole mesh intact (every triangle and every joint, broken or not,
// over the free components) has fewer entries. It depends on the mesh alone, so a run
// restarted from a checkpoint decides the same.
FillOrdering fill_ordering(const Triangles& triangles, const Joints& joints, const std::vector<MaterialModel>& materials,
                           const FreeComponents& free, Mechanics& mechanics);

// The factor of the chord matrix (mechanics.chord_*), with the matrix it was made from.
struct ChordFactor {
  explicit ChordFactor(FillOrdering ordering) : solver(ordering) {}
  std::vector<index_t> outer, inner;
  std::vector<double> values;
  StiffnessSolver solver;
};

// The chord matrix's factor, made (ordering and all, by mechanics.fill_ordering, which a Newton
// relaxation has decided) from mechanics.chord_* where the one held is not theirs: a run restarted from a checkpoint makes the same factor bit for bit.
ChordFactor& chord_factor(Mechanics& mechanics);

// Keeps A over `free` as the chord matrix, and `factor`, whose solver holds A's factor, as its
// factor.
void keep_chord_factor(const Eigen::SparseMatrix<double>& A, const FreeComponents& free,
                       const std::shared_ptr<ChordFactor>& factor, Mechanics& mechanics);

// The sparsity pattern a solver's ordering and symbolic factorisation were made for: analyse
// finds them again only when the pattern changes (a joint breaks, a pair comes near).
class StiffnessPattern {
 public:
  void analyse(const Eigen::SparseMatrix<double>& A, StiffnessSolver& solver);

 private:
  std::vector<int> outer_, inner_;
};

// The out-of-balance force of the free components (nodes.fx, fy).
Eigen::VectorXd out_of_balance(const FreeComponents& free, const Nodes& nodes);

// The free components' masses.
Eigen::VectorXd free_masses(const FreeComponents& free, const Nodes& nodes);

// K_solid plus the links' stiffness (explicit zeros for the inactive: one pattern for all).
Eigen::SparseMatrix<double> model_tangent(const Eigen::SparseMatrix<double>& K_solid, const std::vector<ContactLink>& links,
                                          const std::vector<std::uint8_t>& active, const FreeComponents& free);

// Scales du down so that no node moves farther than `limit` (> 0; none: 0), so that the broad
// phase, which keeps the pairs within two contact buffers, sees every surface a step brings a
// corner to.
void limit_move(const FreeComponents& free, double limit, Eigen::VectorXd& du);

}  // namespace ydry
