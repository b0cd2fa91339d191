// Setting up the solid: material constants, masses, reference geometry, joints and
// boundary constraints (doc/deck.md "[materials.NAME]" and "[[mechanics.boundary]]"; the
// arrays are those of ycore/state/state.h).
#include "ycore/solid/mechanics_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "ycore/contact/contact_setup.h"
#include "ycore/input/input_error.h"
#include "ycore/solid/stable_step.h"
#include "ycore/solid/substrate.h"
#include "ycore/solid/strength_heterogeneity.h"
#include "ycore/state/build_state.h"

namespace ydry {
namespace {

double required(const std::optional<double>& value, const MaterialDeck& md, const char* key,
                const char* why) {
  if (!value) throw InputError(md.where + "." + key + ": missing (" + why + ")");
  return *value;
}

MaterialModel material_model(const MaterialDeck& md, const Deck& deck) {
  MaterialModel m;
  m.rigid = md.rigid;
  m.breakable = md.breakable;
  if (md.rigid) return m;  // fixed nodes, a contact surface only: no constants needed
  m.mechanical = true;
  const char* solid = "the solid needs it";
  m.density = required(md.density, md, "density", solid);
  m.mass_scaling = md.mass_scaling;
  m.young = required(md.young, md, "young", solid);
  const double nu = required(md.poisson, md, "poisson", solid);
  m.mu = m.young / (2.0 * (1.0 + nu));
  m.plane_strain = deck.plane_strain;
  if (deck.plane_strain) {
    m.lambda = m.young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    m.bulk3 = 3.0 * m.lambda + 2.0 * m.mu;  // 3 K
  } else {
    m.lambda = m.young * nu / (1.0 - nu * nu);  // in-plane lambda* of plane stress
    m.bulk3 = m.young / (1.0 - nu);             // 3 K* = E / (1 - nu)
  }
  m.penalty = deck.joint_penalty * m.young;
  if (md.breakable) {
    const char* joints = "joints of a breakable material need it";
    m.tensile_strength = required(md.tensile_strength, md, "tensile_strength", joints);
    m.cohesion = required(md.cohesion, md, "cohesion", joints);
    m.tan_friction = std::tan(required(md.friction_angle_deg, md, "friction_angle", joints) * M_PI / 180.0);
    m.gf_I = required(md.gf_I, md, "gf_I", joints);
    m.gf_II = required(md.gf_II, md, "gf_II", joints);
    m.strength_heterogeneity = md.strength_heterogeneity;
  }
  if (md.has_moisture()) {
    m.shrinkage_coefficient =
        required(md.shrinkage_coefficient, md, "shrinkage_coefficient", "moisture drives shrinkage in a mechanics run");
    m.shrinkage_limit = md.shrinkage_limit.value_or(0.0);
    m.stress_free_moisture = md.stress_free_moisture.value_or(*md.initial_moisture);
  }
  return m;
}

// A bonded interface's joint properties (doc/physics.md "Interface joints"): the joint law
// of a breakable material's joints with the interface's strengths and fracture energies, and
// the penalty joint_penalty x E of the softer of its deformable materials (against a rigid one,
// the other's). Between two rigid materials its joints carry nothing, as a rigid material's.
MaterialModel interface_model(const InterfaceDeck& f, const MaterialModel& a, const MaterialModel& b) {
  MaterialModel m;
  m.mechanical = a.mechanical || b.mechanical;
  if (!m.mechanical) return m;
  const double young = !a.mechanical ? b.young : !b.mechanical ? a.young : std::min(a.young, b.young);
  m.penalty = f.joint_penalty * young;
  m.tensile_strength = f.tensile_strength;
  m.cohesion = f.cohesion;
  m.tan_friction = std::tan(f.friction_angle_deg * M_PI / 180.0);
  m.gf_I = f.gf_I;
  m.gf_II = f.gf_II;
  return m;
}

// Where the deck gives the properties of joints with properties `id` (Joints::law).
const std::string& joint_properties_where(const State& s, const Deck& deck, std::size_t id) {
  const std::size_t nm = s.material_names.size();
  if (id < nm) return deck.materials.at(s.material_names[id]).where;
  const std::string& name = s.interface_names[id - nm];
  return std::find_if(deck.interfaces.begin(), deck.interfaces.end(),
                      [&](const InterfaceDeck& f) { return f.name == name; })->where;
}

void set_reference_geometry(State& s) {
  Nodes& n = s.nodes;
  Triangles& t = s.triangles;
  const std::size_t nt = t.size();
  t.inv0.resize(4 * nt);
  t.mass_kg.assign(nt, 0.0);
  t.shrinkage_strain.assign(nt, 0.0);
  for (auto* v : {&t.sxx, &t.syy, &t.sxy}) v->assign(nt, 0.0);
  n.m.assign(n.size(), 0.0);
  for (std::size_t e = 0; e < nt; ++e) {
    const index_t i = corner_node(index_t(e), 0);
    const double a = n.x0[i + 1] - n.x0[i], b = n.x0[i + 2] - n.x0[i];  // F0 = [a b; c d]
    const double c = n.y0[i + 1] - n.y0[i], d = n.y0[i + 2] - n.y0[i];
    const double det = a * d - b * c;  // 2 A0 > 0: corners are counter-clockwise
    t.inv0[4 * e + 0] = d / det;
    t.inv0[4 * e + 1] = -b / det;
    t.inv0[4 * e + 2] = -c / det;
    t.inv0[4 * e + 3] = a / det;
    const MaterialModel& m = s.materials[t.material[e]];
    t.mass_kg[e] = m.density * t.area0[e] * s.mechanics.thickness_m;
    for (int k = 0; k < 3; ++k) n.m[i + k] = m.mass_scaling * t.mass_kg[e] / 3.0;
  }
}

void set_joint_data(State& s, const Deck& deck) {
  Joints& j = s.joints;
  const Nodes& n = s.nodes;
  const std::size_t nj = j.size();
  j.length0.resize(nj);
  j.damage.assign(3 * nj, 0.0);
  j.force.assign(8 * nj, 0.0);
  j.work.assign(nj, 0.0);
  s.nodes.joint_slot.assign(2 * n.size(), kNoIndex);
  j.mechanical_runs.clear();
  for (std::size_t k = 0; k < nj; ++k) {
    const index_t a = j.node[4 * k], b = j.node[4 * k + 1];
    j.length0[k] = std::hypot(n.x0[b] - n.x0[a], n.y0[b] - n.y0[a]);
    if (!s.materials[j.law[k]].mechanical) continue;  // carries nothing, ever
    if (j.mechanical_runs.empty() || j.mechanical_runs.back() != k)
      j.mechanical_runs.insert(j.mechanical_runs.end(), {index_t(k), index_t(k + 1)});
    else
      ++j.mechanical_runs.back();
    for (int c = 0; c < 4; ++c) {
      const index_t node = j.node[4 * k + c];
      index_t* slot = &s.nodes.joint_slot[2 * node];
      slot[slot[0] == kNoIndex ? 0 : 1] = index_t(4 * k + c);
    }
  }
  set_strength_factors(j, n, s.materials, std::uint64_t(deck.seed));
  // The pre-peak work (2/3) f_t o_p with o_p = 2 h f_t / p must leave room for softening, in
  // the joint where h f_t^2 is largest (f_t times the joint's strength factor).
  std::vector<double> largest(s.materials.size(), 0.0);  // h x factor^2, m
  for (std::size_t k = 0; k < nj; ++k) {
    const double f = j.strength_factor[k];
    largest[j.law[k]] = std::max(largest[j.law[k]], j.length0[k] * f * f);
  }
  for (std::size_t id = 0; id < s.materials.size(); ++id) {
    const MaterialModel& m = s.materials[id];
    if (!m.mechanical || !m.breakable || largest[id] == 0.0) continue;
    const double prepeak = 2.0 / 3.0 * m.tensile_strength * 2.0 * largest[id] * m.tensile_strength / m.penalty;
    if (m.gf_I <= prepeak)
      throw InputError(joint_properties_where(s, deck, id) +
                       ".gf_I: smaller than the joint's pre-peak work " + std::to_string(prepeak) +
                       " J/m^2 at this element size" + (m.strength_heterogeneity > 0.0 ? " and strongest joint" : "") +
                       "; raise " + (id < s.material_names.size() ? "solver.joint_penalty" : "its joint_penalty") +
                       " or refine the mesh");
  }
}

// Rigid materials and [[mechanics.boundary]] entries become per-node constraints; driven
// nodes are listed once with their velocity. A component given two different conditions
// is an error naming both.
void set_constraints(State& s, const Deck& deck) {
  Nodes& n = s.nodes;
  n.constraint.assign(n.size(), 0);
  // A rigid material is a support of its own: reactions.csv books the force on it as
  // "rigid:NAME".
  for (std::size_t id = 0; id < s.materials.size(); ++id) {
    if (!s.materials[id].rigid) continue;
    MechanicsBoundary b;
    b.name = "rigid:" + s.material_names[id];
    b.fix_x = b.fix_y = true;
    for (std::size_t i = 0; i < n.size(); ++i)
      if (s.triangles.material[triangle_of(index_t(i))] == id) {
        n.constraint[i] = kFixX | kFixY;
        b.nodes.push_back(index_t(i));
      }
    s.mechanics_boundaries.push_back(std::move(b));
  }

  struct Condition { double velocity; const MechanicsBoundaryDeck* by; };
  std::map<index_t, Condition> x_condition, y_condition;
  for (const MechanicsBoundaryDeck& bd : deck.mechanics_boundaries) {
    // Every corner at a vertex of the boundary, including corners of triangles that touch
    // it at that vertex only: they are the same material point, tied by stiff joints.
    std::vector<std::uint8_t> on_boundary(n.size(), 0);
    for (const index_t i : boundary_nodes(s.boundary_edges, bd.on, bd.where)) on_boundary[n.vertex[i]] = 1;
    MechanicsBoundary b;
    b.name = bd.on;
    for (std::size_t i = 0; i < n.size(); ++i)
      if (on_boundary[n.vertex[i]]) b.nodes.push_back(index_t(i));
    b.fix_x = bd.fix_x || bd.driven;
    b.fix_y = bd.fix_y || bd.driven;
    b.vx = bd.velocity[0];
    b.vy = bd.velocity[1];
    for (const index_t i : b.nodes) {
      for (int axis = 0; axis < 2; ++axis) {
        if (!(axis == 0 ? b.fix_x : b.fix_y)) continue;
        auto& conditions = axis == 0 ? x_condition : y_condition;
        const Condition c{axis == 0 ? b.vx : b.vy, &bd};
        const auto [it, fresh] = conditions.emplace(i, c);
        if (!fresh && it->second.velocity != c.velocity)
          throw InputError(bd.where + ": gives the " + (axis == 0 ? "x" : "y") +
                           " component of a node a different velocity than " + it->second.by->where);
        n.constraint[i] |= axis == 0 ? kFixX : kFixY;
      }
    }
    s.mechanics_boundaries.push_back(std::move(b));
  }
  Mechanics& mech = s.mechanics;
  for (const auto* conditions : {&x_condition, &y_condition})
    for (const auto& [node, c] : *conditions)
      if (c.velocity != 0.0) mech.driven_node.push_back(node);
  std::sort(mech.driven_node.begin(), mech.driven_node.end());
  mech.driven_node.erase(std::unique(mech.driven_node.begin(), mech.driven_node.end()), mech.driven_node.end());
  for (const index_t i : mech.driven_node) {
    const auto vx = x_condition.find(i), vy = y_condition.find(i);
    mech.driven_vx.push_back(vx == x_condition.end() ? 0.0 : vx->second.velocity);
    mech.driven_vy.push_back(vy == y_condition.end() ? 0.0 : vy->second.velocity);
  }
}

// |net force|^2 that round-off alone produces: coordinates of size L carry an error of
// eps L, which a joint of penalty p turns into a force of about p t eps L per node. A
// relaxation also ends when the out-of-balance is within 10 times that, so an unloaded or
// fully broken solid does not chase round-off.
double roundoff_net2(const State& s) {
  double penalty = 0.0, extent = 0.0;
  for (const MaterialModel& m : s.materials) penalty = std::max({penalty, m.penalty, m.young});
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    extent = std::max({extent, std::fabs(s.nodes.x0[i]), std::fabs(s.nodes.y0[i])});
  const double force = 10.0 * penalty * s.mechanics.thickness_m * std::numeric_limits<double>::epsilon() * extent;
  return force * force * double(s.nodes.size());
}

}  // namespace

void init_mechanics(State& s, const Deck& deck) {
  std::vector<std::uint8_t> used(s.material_names.size(), 0);
  for (const std::uint16_t m : s.triangles.material) used[m] = 1;
  const std::size_t nm = s.material_names.size();
  s.materials.assign(nm, MaterialModel{});
  for (std::size_t id = 0; id < nm; ++id)
    if (used[id]) s.materials[id] = material_model(deck.materials.at(s.material_names[id]), deck);
  const auto id_of = [&](const std::string& name) {
    return std::size_t(std::find(s.material_names.begin(), s.material_names.end(), name) - s.material_names.begin());
  };
  for (const InterfaceDeck& f : deck.interfaces)  // in the order of State::interface_names
    if (f.bonded)
      s.materials.push_back(interface_model(f, s.materials[id_of(f.materials.first)], s.materials[id_of(f.materials.second)]));

  Mechanics& mech = s.mechanics;
  mech.thickness_m = deck.thickness_m;
  mech.gravity_x = deck.gravity[0];
  mech.gravity_y = deck.gravity[1];
  const std::size_t nn = s.nodes.size();
  for (auto* v : {&s.nodes.fx, &s.nodes.fy, &mech.x_start, &mech.y_start})
    v->assign(nn, 0.0);
  set_reference_geometry(s);
  set_joint_data(s, deck);
  set_constraints(s, deck);
  init_contact(s.nodes, s.joints, s.material_names, deck, s.contact);
  init_substrate(deck, s.triangles, s.materials, nn, s.substrate);
  s.ownership = partition_for_threads(s.triangles, s.joints, s.materials, kOwnershipSlots);
  if (deck.node_mass_scaling) scale_node_masses_to_common_step(s.triangles, s.joints, mech, s.contact, s.substrate, s.materials, s.nodes);
  mech.step_s = stable_mechanics_step(s.nodes, s.triangles, s.joints, mech, s.contact, s.substrate, s.materials,
                                     deck.mechanics_safety);
  mech.roundoff_net2 = roundoff_net2(s);
  const auto [x_min, x_max] = std::minmax_element(s.nodes.x0.begin(), s.nodes.x0.end());
  const auto [y_min, y_max] = std::minmax_element(s.nodes.y0.begin(), s.nodes.y0.end());
  mech.mesh_diagonal_m = nn ? std::hypot(*x_max - *x_min, *y_max - *y_min) : 0.0;
}

}  // namespace ydry
