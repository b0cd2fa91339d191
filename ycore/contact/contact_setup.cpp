// Contact set-up: the penalty, friction per material pair, the broad-phase buffer, and the
// surfaces (triangle edges with no joint or a broken one).
#include "ycore/contact/contact_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ydry {
namespace {

// The corners that cannot move (both components prescribed: a rigid body, a support) and lie
// where their body's surface is straight: the interior angles of their tie group (one material
// point) add up to pi, from the initial positions, as a mesh of a straight side makes them.
// Such a corner is only a receiver of contact, never a contactor. Where two bodies overlap,
// the deepest point of the overlap is a convex vertex of one of them or a crossing of their
// edges, never a vertex on a straight side, so the other body's corners find the contact
// there (and see one straight surface, so their force is continuous across its vertices). As
// a contactor it would switch: where the Peron soil rests on its rigid base with coinciding
// vertices, a base corner on the land falls now on one soil edge, now on the next, now between
// them, as the joint that holds the soil's corners there together gives by nanometres, and
// the relaxations stall (doc/physics.md "Contact and friction").
std::vector<std::uint8_t> fixed_flat_corners(const Nodes& n) {
  const std::size_t nn = n.size();
  std::vector<double> interior_angle(nn, 0.0);  // per tie group, at its lowest corner
  for (index_t i = 0; i < nn; ++i) {
    const index_t a = next_corner(i), b = previous_corner(i);
    const double ax = n.x0[a] - n.x0[i], ay = n.y0[a] - n.y0[i], bx = n.x0[b] - n.x0[i], by = n.y0[b] - n.y0[i];
    interior_angle[n.tie_group[i]] += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  constexpr double kStraight = 1e-6;  // radians from pi: a straight side's rounding, not a kink
  std::vector<std::uint8_t> flat(nn, 0);
  for (index_t i = 0; i < nn; ++i)
    flat[i] = n.constraint[i] == (kFixX | kFixY) && std::fabs(interior_angle[n.tie_group[i]] - M_PI) < kStraight;
  return flat;
}

}  // namespace

void init_contact(const Nodes& n, const Joints& joints, const std::vector<std::string>& material_names,
                  const Deck& deck, Contact& c) {
  if (n.tie_group.size() != n.size()) throw std::logic_error("init_contact: corners not tied yet");
  c.penalty_pa = deck.contact_penalty_pa.value_or(0.0);
  c.damping_ratio = deck.contact_damping;
  const std::size_t nm = material_names.size();
  c.tan_friction.assign(nm * nm, 0.0);
  for (const auto& [pair, degrees] : deck.friction_deg) {
    const auto id = [&](const std::string& name) {
      return std::size_t(std::find(material_names.begin(), material_names.end(), name) - material_names.begin());
    };
    const std::size_t a = id(pair.first), b = id(pair.second);
    if (a == nm || b == nm) continue;  // a deck material the mesh does not use (warned about)
    c.tan_friction[a * nm + b] = c.tan_friction[b * nm + a] = std::tan(degrees * M_PI / 180.0);
  }
  // A tenth of the shortest edge: contacts move little between two builds, and the 2-buffer
  // shell around an edge holds few corners besides the ones that can touch it.
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n.size(); ++i) {
    const index_t j = next_corner(index_t(i));
    shortest = std::min(shortest, std::hypot(n.x0[j] - n.x0[i], n.y0[j] - n.y0[i]));
  }
  c.buffer_m = 0.1 * shortest;
  c.work_J = 0.0;
  refresh_contact_surfaces(n, joints, c);
}

void refresh_contact_surfaces(const Nodes& n, const Joints& jt, Contact& c) {
  const std::size_t nn = n.size();
  // An edge is a surface unless an intact joint covers it. The joint's first triangle's edge
  // starts at its node 0, the second's at its node 2 (Joints::node, ycore/state/state.h).
  c.is_surface_edge.assign(nn, 1);
  c.bonded_line.clear();
  for (std::size_t j = 0; j < jt.size(); ++j) {
    if (jt.broken[j]) continue;
    c.is_surface_edge[jt.node[4 * j]] = c.is_surface_edge[jt.node[4 * j + 2]] = 0;
    c.bonded_line.push_back(bonded_line_key(n.tie_group[jt.node[4 * j]], n.tie_group[jt.node[4 * j + 1]]));
  }
  std::sort(c.bonded_line.begin(), c.bonded_line.end());
  c.bonded_line.erase(std::unique(c.bonded_line.begin(), c.bonded_line.end()), c.bonded_line.end());
  c.surface_edge.clear();
  for (index_t e = 0; e < nn; ++e)
    if (c.is_surface_edge[e]) c.surface_edge.push_back(e);
  c.surface_node.clear();
  const std::vector<std::uint8_t> receiver_only = fixed_flat_corners(n);
  for (index_t i = 0; i < nn; ++i)
    if ((c.is_surface_edge[i] || c.is_surface_edge[previous_corner(i)]) && !receiver_only[i]) c.surface_node.push_back(i);
  // Forces a broad phase at the next force evaluation; the pairs stay for their history.
  c.x_built.assign(c.surface_node.size(), std::numeric_limits<double>::infinity());
  c.y_built.assign(c.surface_node.size(), std::numeric_limits<double>::infinity());
}

double contact_stiffness_bound(const Mechanics& mech, const Contact& c) {
  // Normal and tangential stiffness p_n t each (two surface edges of p_n t / 2), counted once
  // as the node of a pair and once more for the pairs whose edge it ends (Gershgorin row).
  return 8.0 * c.penalty_pa * mech.thickness_m;
}

}  // namespace ydry
