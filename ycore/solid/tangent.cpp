#include "ycore/solid/tangent.h"

#include <cmath>

#include "ycore/solid/corotational.h"
#include "ycore/solid/joint_forces.h"

namespace ydry {
namespace {

// The relative size of a central difference's step: small against a joint's peak opening
// (2 h0 f_t / p, a few 1e-4 of h0 at p = 100 E), large against the round-off of a coordinate.
constexpr double kRelativeStep = 1e-7;

// Entries of -d(forces)/d(coordinates) of one part with `corners` nodes, by central
// differences: forces(x, y, out) gives the 2 * corners forces at corner coordinates x, y.
// Appends the entries between free components to `entries`.
template <int corners, class Forces>
void add_part_tangent(const index_t* node, const Nodes& n, const FreeComponents& free, double step,
                      Forces forces, std::vector<Eigen::Triplet<double>>& entries) {
  double x[corners], y[corners];
  for (int k = 0; k < corners; ++k) x[k] = n.x[node[k]], y[k] = n.y[node[k]];
  for (int c = 0; c < 2 * corners; ++c) {
    const index_t column = free.unknown[2 * std::size_t(node[c / 2]) + c % 2];
    if (column == kNoIndex) continue;
    double* coordinate = c % 2 == 0 ? &x[c / 2] : &y[c / 2];
    const double at = *coordinate;
    double plus[2 * corners], minus[2 * corners];
    *coordinate = at + step;
    forces(x, y, plus);
    *coordinate = at - step;
    forces(x, y, minus);
    *coordinate = at;
    for (int r = 0; r < 2 * corners; ++r) {
      const index_t row = free.unknown[2 * std::size_t(node[r / 2]) + r % 2];
      if (row != kNoIndex) entries.emplace_back(row, column, -(plus[r] - minus[r]) / (2.0 * step));
    }
  }
}

}  // namespace

FreeComponents free_components(const Nodes& n, const Triangles& tri, const std::vector<MaterialModel>& materials) {
  FreeComponents free;
  free.unknown.assign(2 * n.size(), kNoIndex);
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!materials[tri.material[triangle_of(index_t(i))]].mechanical) continue;
    for (int axis = 0; axis < 2; ++axis) {
      if (n.constraint[i] & (axis == 0 ? kFixX : kFixY)) continue;
      free.unknown[2 * i + axis] = index_t(free.component.size());
      free.component.push_back(index_t(2 * i + axis));
    }
  }
  return free;
}

Eigen::SparseMatrix<double> tangent_stiffness(const Nodes& n, const Triangles& tri, const Joints& jt,
                                              const Mechanics& mech, const std::vector<MaterialModel>& materials,
                                              const FreeComponents& free, JointFrictionTangent friction) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(36 * tri.size() + 64 * jt.size());  // at most (2 x corners)^2 a part
  for (std::size_t e = 0; e < tri.size(); ++e) {
    const MaterialModel& m = materials[tri.material[e]];
    if (!m.mechanical) continue;
    const index_t node[3] = {corner_node(index_t(e), 0), corner_node(index_t(e), 1), corner_node(index_t(e), 2)};
    const double* inv = &tri.inv0[4 * e];
    const double volume = tri.area0[e] * mech.thickness_m;
    const double step = kRelativeStep * std::sqrt(tri.area0[e]);
    add_part_tangent<3>(node, n, free, step, [&](const double* x, const double* y, double* f) {
      const CornerForces g = corner_forces(
          first_piola(corotational_state(x, y, inv, m.lambda, m.mu, m.bulk3, tri.shrinkage_strain[e])), inv, volume);
      f[0] = g.G00 + g.G01, f[1] = g.G10 + g.G11, f[2] = -g.G00, f[3] = -g.G10, f[4] = -g.G01, f[5] = -g.G11;
    }, entries);
  }
  for (std::size_t j = 0; j < jt.size(); ++j) {
    if (jt.broken[j] || !materials[jt.law[j]].mechanical) continue;
    const index_t* node = &jt.node[4 * j];
    double compression[3];
    const bool held = friction == JointFrictionTangent::held;
    if (held) {
      const double x0[4] = {n.x[node[0]], n.x[node[1]], n.x[node[2]], n.x[node[3]]};
      const double y0[4] = {n.y[node[0]], n.y[node[1]], n.y[node[2]], n.y[node[3]]};
      joint_point_compressions(jt, materials, j, x0, y0, compression);
    }
    add_part_tangent<4>(node, n, free, kRelativeStep * jt.length0[j], [&](const double* x, const double* y, double* f) {
      joint_nodal_forces_at(jt, mech, materials, j, x, y, f, held ? compression : nullptr);
    }, entries);
  }
  Eigen::SparseMatrix<double> K(Eigen::Index(free.size()), Eigen::Index(free.size()));
  K.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> transpose = K.transpose();
  return 0.5 * (K + transpose);
}

}  // namespace ydry
