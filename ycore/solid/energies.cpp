#include "ycore/solid/energies.h"

#include "ycore/solid/corotational.h"
#include "ycore/solid/substrate.h"
#include "ycore/state/blocked_sum.h"

namespace ydry {

Energies energies(const State& s) {
  const Nodes& n = s.nodes;
  const Triangles& tri = s.triangles;
  Energies e;
  const auto kinetic = blocked_sum<1>(n.size(), [&](std::size_t i, std::array<double, 1>& sum) {
    sum[0] += 0.5 * tri.mass_kg[triangle_of(index_t(i))] / 3.0 * (n.vx[i] * n.vx[i] + n.vy[i] * n.vy[i]);
  });
  e.kinetic_J = kinetic[0];
  // Strain energy 1/2 sigma : eps_elastic, eps_elastic = (U - I) - eps_sh I in the plane; in
  // plane strain the out-of-plane elastic strain -eps_sh under sigma_zz adds its share.
  const auto elastic = blocked_sum<1>(tri.size(), [&](std::size_t t, std::array<double, 1>& sum) {
    const MaterialModel& m = s.materials[tri.material[t]];
    if (!m.mechanical) return;
    const CorotationalState k = corotational_state(n, tri, m, t);
    const double sh = tri.shrinkage_strain[t];
    double w = k.T00 * (k.e00 - sh) + k.T11 * (k.e11 - sh) + 2.0 * k.T01 * k.e01;
    if (m.plane_strain) w -= (m.lambda * (k.e00 + k.e11 - 3.0 * sh) - 2.0 * m.mu * sh) * sh;
    sum[0] += 0.5 * w * tri.area0[t] * s.mechanics.thickness_m;
  });
  e.elastic_J = elastic[0];
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    e.joint_work_J += s.joints.work[j];
    if (s.joints.broken[j]) e.fracture_J += s.joints.work[j];
  }
  e.contact_work_J = s.contact.work_J;
  e.substrate_elastic_J = substrate_elastic_energy(n, s.substrate);
  e.substrate_slide_work_J = s.substrate.slide_work_J;
  for (const MechanicsBoundary& b : s.mechanics_boundaries) e.external_work_J += b.work_J;
  e.gravity_work_J = s.mechanics.gravity_work_J;
  return e;
}

}  // namespace ydry
