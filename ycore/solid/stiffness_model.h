// The linear algebra of the implicit equilibrium solver (newton.cpp; doc/solver.md
// "Quasi-static equilibrium"): the solid's stiffness with the contact links, its sparse LDL^T
// factorisation, and the vectors over the free components.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cstdint>
#include <memory>
#include <vector>

#include "ycore/contact/contact_tangent.h"
#include "ycore/solid/tangent.h"
#include "ycore/state/state.h"

namespace ydry {

using StiffnessSolver = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>>;

// The factor of the chord matrix (mechanics.chord_*), with the matrix it was made from.
struct ChordFactor {
  std::vector<index_t> outer, inner;
  std::vector<double> values;
  StiffnessSolver solver;
};

// The chord matrix's factor, made (ordering and all) from mechanics.chord_* where the one held
// is not theirs: a run restarted from a checkpoint makes the same factor bit for bit.
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
