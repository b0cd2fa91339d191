// Constant-strain triangles, co-rotational (doc/physics.md "Elements").
//
// F = [x1-x0 | x2-x0] inv0 is split as F = R U (polar); Hooke's law acts on the Biot strain
// U - I in the rotated frame, minus the shrinkage stress 3 K* eps_sh (Eq. 19):
//   T = lambda tr(U - I) I + 2 mu (U - I) - 3 K* eps_sh I,   P = R T (first Piola-Kirchhoff).
// A rigid rotation gives U = I and no stress; at small strain T is the linear-elastic stress.
// The free shrinkage of Eqs. 21-22 is exact in this law (the strain is linear in the stretch),
// and P F^T = R T U R^T is symmetric because T is a polynomial in U, so the nodal forces
// conserve angular as well as linear momentum.
//
// The kernel takes each thread's triangles (ycore/state/ownership.h) in runs of one material, so
// that the material's constants are the same over a run and the loop over it vectorises:
// every array is passed as its own restrict pointer (GCC does not vectorise the loop through
// the std::vectors of Nodes and Triangles, whose data it cannot tell apart) and the three
// corners of triangle e are nodes 3e, 3e+1, 3e+2. A relaxation step moves the nodes in the same
// pass, a cache-sized piece of a run at a time (kMovedTogether), so that the positions
// integration writes are read while still in the cache, and one sweep of the node arrays and
// one parallel region a step are saved (on a mesh larger than the cache the step waits on
// memory; the gain is within the noise of a 2-core host: bench/RESULTS.md). The stress is not
// needed by the forces, only at equilibrium (element_stresses), so the step does not store it.
#include "ycore/solid/element_forces.h"

#include <algorithm>
#include <cmath>

#include "ycore/solid/corotational.h"
#include "ycore/solid/vector_clones.h"

namespace ydry {
namespace {

// Triangles [begin, end) of one mechanical material: the co-rotational stress of each, and
// with kForces its internal forces and gravity into fx, fy of its corners, with kStress the
// stress (rotated to the current axes) into sxx, syy, sxy. Inlined into the two kernels below.
template <bool kForces, bool kStress>
__attribute__((always_inline)) inline void material_run(
    std::size_t begin, std::size_t end, const double* __restrict x, const double* __restrict y,
    const double* __restrict inv0, const double* __restrict area0, const double* __restrict mass,
    const double* __restrict shrinkage, double* __restrict fx, double* __restrict fy, double* __restrict sxx,
    double* __restrict syy, double* __restrict sxy, const MaterialModel& m, double thickness, double gx, double gy) {
  const double lambda = m.lambda, mu = m.mu, bulk3 = m.bulk3;
  for (std::size_t e = begin; e < end; ++e) {
    const double* inv = &inv0[4 * e];
    const CorotationalState k = corotational_state(&x[3 * e], &y[3 * e], inv, lambda, mu, bulk3, shrinkage[e]);
    const FirstPiola p = first_piola(k);
    if (kStress) {  // R T R^T: the stress of the law in the current axes (Cauchy at small strain)
      const double c = k.c, sn = k.s;
      sxx[e] = p.P00 * c - p.P01 * sn;
      syy[e] = p.P10 * sn + p.P11 * c;
      sxy[e] = p.P00 * sn + p.P01 * c;
    }
    if (kForces) {  // internal work A0 t P : dF
      const CornerForces g = corner_forces(p, inv, area0[e] * thickness);
      const double wx = mass[e] / 3.0 * gx, wy = mass[e] / 3.0 * gy;  // a third of the weight
      fx[3 * e] = (g.G00 + g.G01) + wx, fy[3 * e] = (g.G10 + g.G11) + wy;
      fx[3 * e + 1] = -g.G00 + wx, fy[3 * e + 1] = -g.G10 + wy;
      fx[3 * e + 2] = -g.G01 + wx, fy[3 * e + 2] = -g.G11 + wy;
    }
  }
}

YDRY_AVX2_CLONE void material_run_forces(std::size_t begin, std::size_t end, const double* __restrict x,
                                         const double* __restrict y, const double* __restrict inv0,
                                         const double* __restrict area0, const double* __restrict mass,
                                         const double* __restrict shrinkage, double* __restrict fx,
                                         double* __restrict fy, const MaterialModel& m, double thickness, double gx,
                                         double gy) {
  material_run<true, false>(begin, end, x, y, inv0, area0, mass, shrinkage, fx, fy, nullptr, nullptr, nullptr, m,
                            thickness, gx, gy);
}

YDRY_AVX2_CLONE void material_run_stresses(std::size_t begin, std::size_t end, const double* __restrict x,
                                           const double* __restrict y, const double* __restrict inv0,
                                           const double* __restrict shrinkage, double* __restrict sxx,
                                           double* __restrict syy, double* __restrict sxy, const MaterialModel& m) {
  material_run<false, true>(begin, end, x, y, inv0, nullptr, nullptr, shrinkage, nullptr, nullptr, sxx, syy, sxy, m,
                            0.0, 0.0, 0.0);
}

// Triangles moved and their forces made together, so many at a time: their nodes' data (some
// 60 bytes a node) stay in the core's cache between the two.
constexpr std::size_t kMovedTogether = 512;

// Runs body(begin, end, material) over the calling thread's triangles, in runs of one material.
template <class Body>
void for_each_material_run(const Triangles& tri, const Ownership& ownership,
                           const std::vector<MaterialModel>& materials, Body body) {
  const IndexRange owned = owned_range(ownership.triangle_begin, tri.size());
  for (std::size_t begin = owned.begin, end; begin < owned.end; begin = end) {
    const std::uint16_t id = tri.material[begin];
    for (end = begin + 1; end < owned.end && tri.material[end] == id;) ++end;
    body(begin, end, materials[id]);
  }
}

// Moves the nodes of triangles [first, last), adding each one's v_new . f to the lanes of its
// ownership slot (slot_begin: the table's triangle_begin; one slot without one).
void integrate_triangles(Nodes& n, std::size_t first, std::size_t last, const VelocityUpdate& update,
                         const std::vector<std::size_t>& slot_begin, std::vector<PowerLanes>& slot_lanes) {
  if (slot_lanes.size() == 1) {
    integrate_node_range(n, 3 * first, 3 * last, update, slot_lanes[0]);
    return;
  }
  std::size_t k = std::size_t(std::upper_bound(slot_begin.begin(), slot_begin.end(), first) - slot_begin.begin()) - 1;
  for (std::size_t a = first; a < last; a = std::min(last, slot_begin[++k])) {
    const std::size_t b = std::min(last, slot_begin[k + 1]);
    integrate_node_range(n, 3 * a, 3 * b, update, slot_lanes[k]);
  }
}

}  // namespace

double element_forces(const Triangles& tri, const Mechanics& mech, const Ownership& ownership,
                      const std::vector<MaterialModel>& materials, Nodes& n, const VelocityUpdate* move_first) {
  const double thickness = mech.thickness_m;
  const double gx = mech.gravity_x, gy = mech.gravity_y;
  // The integration's v_new . f per ownership slot, each summed in node order whatever cut
  // the team makes (PowerLanes), then over the slots in theirs: the same sum on any number of
  // threads. Without an ownership table the whole mesh is one slot, on one thread. Reused by
  // the calling thread, so a step allocates nothing; bound to a reference so that the team
  // writes the caller's buffer.
  const std::vector<std::size_t>& slot_begin = ownership.triangle_begin;
  const bool slots = slot_begin.size() >= 2 && slot_begin.back() == tri.size();
  thread_local std::vector<PowerLanes> buffer;
  buffer.assign(slots ? slot_begin.size() - 1 : 1, PowerLanes{});
  std::vector<PowerLanes>& slot_lanes = buffer;
#pragma omp parallel if (tri.size() > parallel_minimum && slots)
  for_each_material_run(tri, ownership, materials, [&](std::size_t begin, std::size_t end, const MaterialModel& m) {
    for (std::size_t first = begin, last; first < end; first = last) {
      last = std::min(end, first + kMovedTogether);
      // A rigid material's nodes are fixed: the integration would keep every value (a third
      // of the Peron deck's nodes).
      if (move_first && !m.rigid) integrate_triangles(n, first, last, *move_first, slot_begin, slot_lanes);
      if (m.mechanical) {
        material_run_forces(first, last, n.x.data(), n.y.data(), tri.inv0.data(), tri.area0.data(),
                            tri.mass_kg.data(), tri.shrinkage_strain.data(), n.fx.data(), n.fy.data(), m, thickness,
                            gx, gy);
      } else {
        std::fill(n.fx.begin() + 3 * first, n.fx.begin() + 3 * last, 0.0);
        std::fill(n.fy.begin() + 3 * first, n.fy.begin() + 3 * last, 0.0);
      }
    }
  });
  double power = 0.0;
  for (const PowerLanes& lanes : slot_lanes) power += lanes.total();
  return power;
}

void element_stresses(const Nodes& n, const Ownership& ownership, const std::vector<MaterialModel>& materials,
                      Triangles& tri) {
#pragma omp parallel if (tri.size() > parallel_minimum)
  for_each_material_run(tri, ownership, materials, [&](std::size_t begin, std::size_t end, const MaterialModel& m) {
    if (m.mechanical)
      material_run_stresses(begin, end, n.x.data(), n.y.data(), tri.inv0.data(), tri.shrinkage_strain.data(),
                            tri.sxx.data(), tri.syy.data(), tri.sxy.data(), m);
  });
}

}  // namespace ydry
