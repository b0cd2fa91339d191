// The cost of the implicit solver's linear algebra on a deck's own stiffness, by fill-reducing
// ordering: AMD (approximate minimum degree) against METIS (nested dissection), each the
// ordering and symbolic analysis once, then the numerical LDL^T factorisation and a solve,
// single-threaded (Eigen's simplicial factorisation runs on one thread). The matrix is the
// Newton model of the first relaxation: the element and joint tangent (tangent.h), the contact
// links within the buffer, and the smallest mass shift the solver starts from. Figures to
// report, not tests; the ordering the solver uses (stiffness_model.h) is chosen from them.
//   bench_factorisation DECK [--set key=value ...]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "ycore/driver/setup.h"
#include "ycore/input/deck.h"
#include "ycore/solid/newton.h"
#include "ycore/solid/solid_forces.h"
#include "ycore/solid/stiffness_model.h"

namespace {

using Matrix = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The best of `repeats` timings of one call, in milliseconds: the machine's noise only adds.
template <class Call>
double best_ms(int repeats, Call call) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const Clock::time_point start = Clock::now();
    call();
    best = std::min(best, 1e3 * seconds_since(start));
  }
  return best;
}

template <class Ordering>
void time_ordering(const char* name, const Matrix& A, const Eigen::VectorXd& f) {
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Ordering> solver;
  const double analyse = best_ms(2, [&] { solver.analyzePattern(A); });
  const double factorise = best_ms(3, [&] { solver.factorize(A); });
  Eigen::VectorXd du;
  const double solve = best_ms(5, [&] { du = solver.solve(f); });
  const double residual = (A * du - f).norm() / f.norm();
  std::printf("  %-6s analyse %8.1f ms  factorise %8.1f ms  solve %6.2f ms  nnz(L) %10lld  residual %.1e%s\n", name,
              analyse, factorise, solve, static_cast<long long>(solver.matrixL().nestedExpression().nonZeros()),
              residual, solver.info() == Eigen::Success ? "" : "  (failed)");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_factorisation DECK [--set key=value ...]\n");
    return 2;
  }
  std::vector<std::string> overrides;
  for (int a = 2; a < argc; ++a) {
    if (std::string(argv[a]) == "--set" && a + 1 < argc) {
      overrides.emplace_back(argv[++a]);
    } else {
      std::fprintf(stderr, "bench_factorisation: unknown argument '%s'\n", argv[a]);
      return 2;
    }
  }
  try {
    const ydry::Deck deck = ydry::load_deck(argv[1], overrides);
    ydry::State s = ydry::prepare_state(deck);
    // The contact pairs and forces of the state as set up, which the links are made from.
    ydry::update_contact_pairs(s.nodes, s.ownership, s.contact);
    ydry::compute_forces(s);
    const ydry::FreeComponents free = ydry::free_components(s.nodes, s.triangles, s.materials);
    const Matrix K = ydry::tangent_stiffness(s.nodes, s.triangles, s.joints, s.mechanics, s.materials, free,
                                                   ydry::JointFrictionTangent::derived);
    const std::vector<ydry::ContactLink> links =
        ydry::contact_links(s.nodes, s.triangles, s.mechanics, s.contact, s.contact.buffer_m);
    Matrix A = ydry::model_tangent(K, links, ydry::links_in_contact(links), free);
    const Eigen::VectorXd mass = ydry::free_masses(free, s.nodes);
    A.diagonal() += ydry::kMinMu * (K.diagonal().sum() / mass.sum()) * mass;
    A.makeCompressed();
    const Eigen::VectorXd f = ydry::out_of_balance(free, s.nodes);
    std::printf("%s: %zu triangles, %zu unknowns, nnz(A) %lld, %zu contact links\n", argv[1], s.triangles.size(),
                free.size(), static_cast<long long>(A.nonZeros()), links.size());
    time_ordering<Eigen::AMDOrdering<int>>("AMD", A, f);
    time_ordering<Eigen::MetisOrdering<int>>("METIS", A, f);
    const bool metis =
        ydry::fill_ordering(s.triangles, s.joints, s.materials, free, s.mechanics) == ydry::FillOrdering::metis;
    std::printf("  the solver orders by %s\n", metis ? "METIS" : "AMD");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_factorisation: %s\n", e.what());
    return 1;
  }
  return 0;
}
