#include "ymoist/moisture_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ycore/input/input_error.h"
#include "ycore/state/build_state.h"
#include "ymoist/moisture_step.h"

namespace ydry {
namespace {

// K_ab = k t A grad N_a . grad N_b for a linear triangle: the constant gradient of Eq. 1,
// which Eq. 2 writes by the divergence theorem, times the conductivity (Eq. 3), and the flow
// through the edge opposite corner a (Eq. 4), in matrix form.
void triangle_conductance(const double* x, const double* y, double k_times_t, double* K) {
  const double twice_area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  double gx[3], gy[3];  // grad N_a scaled by 2A
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    gx[a] = y[b] - y[c];
    gy[a] = x[c] - x[b];
  }
  const double scale = k_times_t / (2.0 * twice_area);  // k t A / (2A)^2
  int i = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) K[i++] = scale * (gx[a] * gx[b] + gy[a] * gy[b]);
}

// Half the initial length of edge a-b times the thickness: the area a boundary edge or a crack
// face lumps at each of its two end nodes.
double half_edge_area(const Nodes& n, const Deck& deck, index_t a, index_t b) {
  return 0.5 * deck.thickness_m * std::hypot(n.x0[b] - n.x0[a], n.y0[b] - n.y0[a]);
}

struct Term {
  index_t mnode;
  MoistureTermKind kind;
  double area, rate, level;
};

// Eqs. 10-12: both faces of every broken joint of a material exchange h_c (w_e - w) with the
// air in the crack, each over half its initial length at each of its two end corners'
// moisture nodes. A crack-tip node so gets a half of both faces (Eqs. 15 and 16), each term at
// the node's own w (doc/physics.md "Cracks and moisture": Eq. 15 as printed takes w_1 there).
// A debonded interface is no crack: its faces rest on each other, and exchange nothing
// (doc/physics.md "Interface joints").
void append_crack_face_terms(const MoistureMesh& mesh, const Deck& deck, std::vector<Term>& terms) {
  const double h_c = deck.crack_exchange_coefficient;
  if (h_c <= 0.0) return;
  const Joints& joints = mesh.joints;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const index_t* n = &joints.node[4 * j];
    if (!joints.broken[j] || is_interface_joint(joints, mesh.material_names.size(), j)) continue;
    const double half_area = half_edge_area(mesh.nodes, deck, n[0], n[1]);  // both faces: the joint's length
    for (int k = 0; k < 4; ++k)  // face 1: nodes 0, 1; face 2: nodes 2, 3 (none without moisture)
      if (mesh.nodes.mnode[n[k]] != kNoIndex)
        terms.push_back({mesh.nodes.mnode[n[k]], MoistureTermKind::exchange, half_area, h_c, deck.crack_air_moisture});
  }
}

// The face of a layer seen in plan view (on = "face"): each moisture node over its tributary
// area, a third of each of its triangles' (of a material with moisture), in the plane: the
// boundary's law per unit area of the layer's top (doc/physics.md "Plan view").
void append_face_terms(const MoistureMesh& mesh, const Deck& deck, const MoistureBoundaryDeck& bc, index_t moisture_nodes,
                       std::vector<Term>& terms) {
  std::vector<double> area(std::size_t(moisture_nodes), 0.0);
  for (index_t t = 0; t < index_t(mesh.triangles.size()); ++t) {
    if (!deck.materials.at(mesh.material_names[mesh.triangles.material[t]]).has_moisture()) continue;
    for (int a = 0; a < 3; ++a) area[mesh.nodes.mnode[corner_node(t, a)]] += mesh.triangles.area0[t] / 3.0;
  }
  for (index_t mn = 0; mn < moisture_nodes; ++mn) {
    if (!(area[mn] > 0.0)) continue;
    if (bc.type == MoistureBcType::flux)
      terms.push_back({mn, MoistureTermKind::flux, area[mn], bc.rate_kg_m2_s,
                       bc.has_residual ? bc.residual : -std::numeric_limits<double>::infinity()});
    else
      terms.push_back({mn, MoistureTermKind::exchange, area[mn], bc.coefficient, bc.air_moisture});
  }
}

// The fixed values and the flux and exchange terms of the deck's [[moisture.boundary]]
// entries and of the crack faces, on the current moisture nodes.
void add_boundary_terms(const MoistureMesh& mesh, const Deck& deck, MoistureNodes& m) {
  const index_t nm = static_cast<index_t>(m.size());
  std::vector<Term> terms;
  m.fixed_w.assign(nm, std::numeric_limits<double>::quiet_NaN());
  for (const MoistureBoundaryDeck& bc : deck.moisture_boundaries) {
    if (bc.on == kFaceBoundary) {
      append_face_terms(mesh, deck, bc, nm, terms);
      continue;
    }
    const std::vector<index_t>& pairs = boundary_nodes(mesh.boundary_edges, bc.on, bc.where);
    bool touches_moisture = false;
    for (std::size_t k = 0; k < pairs.size(); k += 2) {
      const index_t a = pairs[k], b = pairs[k + 1];
      const double half_area = half_edge_area(mesh.nodes, deck, a, b);
      for (const index_t node : {a, b}) {
        const index_t mn = mesh.nodes.mnode[node];
        if (mn == kNoIndex) continue;
        touches_moisture = true;
        switch (bc.type) {
          case MoistureBcType::fixed: m.fixed_w[mn] = bc.value; break;
          case MoistureBcType::flux:
            terms.push_back({mn, MoistureTermKind::flux, half_area, bc.rate_kg_m2_s,
                             bc.has_residual ? bc.residual : -std::numeric_limits<double>::infinity()});
            break;
          case MoistureBcType::exchange:
            terms.push_back({mn, MoistureTermKind::exchange, half_area, bc.coefficient, bc.air_moisture});
            break;
        }
      }
    }
    if (!touches_moisture)
      throw InputError(bc.where + ": boundary \"" + bc.on + "\" touches no material with moisture_conductivity");
  }
  append_crack_face_terms(mesh, deck, terms);

  // CSR by moisture node; stable, so each node's terms keep deck order, crack faces last.
  std::stable_sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) { return a.mnode < b.mnode; });
  m.term_offset.assign(std::size_t(nm) + 1, 0);
  for (const Term& t : terms) ++m.term_offset[t.mnode + 1];
  std::partial_sum(m.term_offset.begin(), m.term_offset.end(), m.term_offset.begin());
  m.term_kind.clear(), m.term_area.clear(), m.term_rate.clear(), m.term_level.clear();
  for (const Term& t : terms) {
    m.term_kind.push_back(t.kind);
    m.term_area.push_back(t.area);
    m.term_rate.push_back(t.rate);
    m.term_level.push_back(t.level);
  }
  m.boundary_node.clear();
  for (index_t i = 0; i < nm; ++i)
    if (m.term_offset[i + 1] > m.term_offset[i] || !std::isnan(m.fixed_w[i])) m.boundary_node.push_back(i);
  m.boundary_inflow.assign(nm, 0.0);
}

// Dry mass of every moisture node: density x a third of each of its triangles' areas x thickness.
void assign_dry_mass(const MoistureMesh& mesh, const Deck& deck, MoistureNodes& m) {
  m.dry_mass.assign(m.corner_offset.size() - 1, 0.0);
  for (index_t t = 0; t < mesh.triangles.size(); ++t) {
    const MaterialDeck& mat = deck.materials.at(mesh.material_names[mesh.triangles.material[t]]);
    if (!mat.has_moisture()) continue;
    for (int a = 0; a < 3; ++a)
      m.dry_mass[mesh.nodes.mnode[corner_node(t, a)]] +=
          *mat.density * mesh.triangles.area0[t] / 3.0 * deck.thickness_m;
  }
}

}  // namespace

void init_moisture(const MoistureMesh& mesh, const Deck& deck, MoistureNodes& m, MoistureElements& elements,
                   WaterBalance& water) {
  const Nodes& n = mesh.nodes;
  const index_t nm = static_cast<index_t>(m.corner_offset.size() - 1);
  const index_t nt = static_cast<index_t>(mesh.triangles.size());
  m.w.assign(nm, 0.0);
  elements.conductance.assign(6 * std::size_t(nt), 0.0);
  elements.corner_inflow.assign(3 * std::size_t(nt), 0.0);
  for (index_t t = 0; t < nt; ++t) {
    const MaterialDeck& mat = deck.materials.at(mesh.material_names[mesh.triangles.material[t]]);
    if (!mat.has_moisture()) continue;
    const index_t c0 = corner_node(t, 0);
    triangle_conductance(&n.x0[c0], &n.y0[c0], *mat.moisture_conductivity * deck.thickness_m,
                         &elements.conductance[6 * std::size_t(t)]);
    // All corners of one moisture node belong to one material, so w_0 is that material's.
    for (int a = 0; a < 3; ++a) m.w[n.mnode[c0 + a]] = *mat.initial_moisture;
  }
  assign_dry_mass(mesh, deck, m);
  add_boundary_terms(mesh, deck, m);
  for (index_t i = 0; i < nm; ++i)
    if (!std::isnan(m.fixed_w[i])) m.w[i] = m.fixed_w[i];
  water = WaterBalance{};
  water.initial_kg = total_water_kg(m);
}

void remap_moisture_nodes(const MoistureMesh& mesh, const Deck& deck, const std::vector<index_t>& old_mnode,
                          const std::vector<double>& old_w, MoistureNodes& m) {
  const index_t nm = static_cast<index_t>(m.corner_offset.size() - 1);
  m.w.assign(nm, 0.0);
  // A new node is part of one old node (splitting only refines), whose w it inherits.
  for (index_t i = 0; i < nm; ++i) m.w[i] = old_w[old_mnode[m.corner[m.corner_offset[i]]]];
  assign_dry_mass(mesh, deck, m);
  add_boundary_terms(mesh, deck, m);
}

}  // namespace ydry
