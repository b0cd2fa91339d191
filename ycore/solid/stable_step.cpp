#include "ycore/solid/stable_step.h"

#include <algorithm>
#include <cmath>

#include "ycore/contact/contact_setup.h"

namespace ydry {

std::vector<double> node_stiffness_bound(const Nodes& n, const Triangles& tri, const Joints& jt,
                                         const Mechanics& mech, const Contact& c, const Substrate& substrate,
                                         const std::vector<MaterialModel>& materials) {
  const double thickness = mech.thickness_m;
  const double contact = contact_stiffness_bound(mech, c);  // any corner may come to lie on a crack face
  std::vector<double> bound(n.size(), 0.0);
  for (std::size_t e = 0; e < tri.size(); ++e) {
    const MaterialModel& m = materials[tri.material[e]];
    if (!m.mechanical) continue;
    const index_t i = corner_node(index_t(e), 0);
    double edge[3];  // edge[a]: length of the edge opposite corner a
    for (int a = 0; a < 3; ++a) {
      const index_t p = i + (a + 1) % 3, q = i + (a + 2) % 3;
      edge[a] = std::hypot(n.x0[q] - n.x0[p], n.y0[q] - n.y0[p]);
    }
    const double perimeter = edge[0] + edge[1] + edge[2];
    for (int a = 0; a < 3; ++a) {
      if (n.constraint[i + a] == (kFixX | kFixY)) continue;
      // |K_ab| <= t (lambda + 2 mu) l_a l_b / (4 A0) for a CST; two components per node.
      double k = thickness * (m.lambda + 2.0 * m.mu) * edge[a] * perimeter / (2.0 * tri.area0[e]);
      for (int slot = 0; slot < 2; ++slot) {  // row sum ~ p t, p the joint's (an interface's may differ)
        const index_t js = n.joint_slot[2 * (i + a) + slot];
        if (js != kNoIndex) k += materials[jt.law[js / 4]].penalty * thickness;
      }
      bound[i + a] = k + contact + (substrate.present() ? substrate.stiffness[i + a] : 0.0);
    }
  }
  return bound;
}

double stable_mechanics_step(const Nodes& n, const Triangles& tri, const Joints& jt, const Mechanics& mech,
                             const Contact& c, const Substrate& substrate,
                             const std::vector<MaterialModel>& materials, double safety) {
  const std::vector<double> bound = node_stiffness_bound(n, tri, jt, mech, c, substrate, materials);
  double omega2_max = 0.0;
  for (std::size_t i = 0; i < bound.size(); ++i) omega2_max = std::max(omega2_max, bound[i] / n.m[i]);
  return omega2_max > 0.0 ? safety * 2.0 / std::sqrt(omega2_max) : 1.0;
}

void scale_node_masses_to_common_step(const Triangles& tri, const Joints& jt, const Mechanics& mech, const Contact& c,
                                      const Substrate& substrate, const std::vector<MaterialModel>& materials, Nodes& n) {
  const std::vector<double> bound = node_stiffness_bound(n, tri, jt, mech, c, substrate, materials);
  std::vector<double> omega2;
  for (std::size_t i = 0; i < bound.size(); ++i)
    if (bound[i] > 0.0) omega2.push_back(bound[i] / n.m[i]);
  if (omega2.empty()) return;
  auto median = omega2.begin() + omega2.size() / 2;
  std::nth_element(omega2.begin(), median, omega2.end());
  for (std::size_t i = 0; i < bound.size(); ++i) n.m[i] = std::max(n.m[i], bound[i] / *median);
}

}  // namespace ydry
