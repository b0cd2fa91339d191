#include "ycore/contact/contact_tangent.h"

#include <algorithm>
#include <cmath>

#include "ycore/contact/contact_geometry.h"

namespace ydry {
namespace {

constexpr double kOnEdge = 1e-6;  // |gap| / edge length of a corner that lies on the edge

// value B B^T into the entries, B = share x (dx, dy) over the receivers.
void add_penalty(const ContactLink& link, double dx, double dy, double value,
                 const std::vector<index_t>& unknown, std::vector<Eigen::Triplet<double>>& entries) {
  for (int r = 0; r < 6; ++r) {
    const index_t row = unknown[2 * std::size_t(link.receivers[r / 2]) + r % 2];
    if (row == kNoIndex) continue;
    const double br = link.share[r / 2] * (r % 2 == 0 ? dx : dy);
    for (int c = 0; c < 6; ++c) {
      const index_t column = unknown[2 * std::size_t(link.receivers[c / 2]) + c % 2];
      if (column != kNoIndex) entries.emplace_back(row, column, value * br * link.share[c / 2] * (c % 2 == 0 ? dx : dy));
    }
  }
}

// B du for B = share x (dx, dy): the unknowns' part of the change.
double along(const ContactLink& link, double dx, double dy, const Eigen::VectorXd& du, const std::vector<index_t>& unknown) {
  double change = 0.0;
  for (int r = 0; r < 6; ++r) {
    const index_t u = unknown[2 * std::size_t(link.receivers[r / 2]) + r % 2];
    if (u != kNoIndex) change += link.share[r / 2] * (r % 2 == 0 ? dx : dy) * du[Eigen::Index(u)];
  }
  return change;
}

}  // namespace

std::vector<ContactLink> contact_links(const Nodes& n, const Triangles& tri, const Mechanics& mech, const Contact& c,
                                       double reach) {
  std::vector<ContactLink> links;
  const std::size_t material_count = std::size_t(std::lround(std::sqrt(double(c.tan_friction.size()))));
  const double half_penalty = 0.5 * c.penalty_pa * mech.thickness_m;
  const auto link_of = [&](index_t p, const EdgeProjection& at, double weight) {
    const index_t i = c.pair_node[p], e = c.pair_edge[p];
    ContactLink link;
    link.receivers[0] = i, link.receivers[1] = e, link.receivers[2] = next_corner(e);
    const double b = std::clamp(at.along, 0.0, 1.0);
    link.share[0] = 1.0, link.share[1] = -(1.0 - b), link.share[2] = -b;
    link.tx = at.tx, link.ty = at.ty, link.gap = at.gap, link.length = at.length;
    link.stiffness = weight * corner_stiffness(c, half_penalty, i);
    for (int d = 0; d < 6; ++d) link.force[d] = c.pair_force[6 * std::size_t(p) + d];
    const double normal = link.force[0] * at.ty - link.force[1] * at.tx;
    link.pressing = normal > 0.0;
    // The force kernel's rule on the pair's slip. A link that does not press yet has no slip
    // (the kernel keeps none where there is no contact) and is taken as stuck, as it is once
    // the step presses it.
    const double cap = link.pressing ? friction_coefficient(c, tri, material_count, i, e) * normal : 0.0;
    link.sticks = friction_sticks(-link.stiffness * c.pair_slip[std::size_t(p)], cap);
    return link;
  };
  const std::size_t corners = c.node_pairs.size() - 1;
  for (std::size_t k = 0; k < corners; ++k) {
    const index_t first = c.node_pairs[k], last = c.node_pairs[k + 1];
    const index_t i = c.pair_node[first];
    // The pairs that carry its contact (contact_forces made the forces at these positions),
    // or else the edge it lies nearest outside, within `reach`, as the force kernel would see it.
    const ContactShares carrying = contact_shares(n, c, i, first, last);
    for (int s = 0; s < carrying.count; ++s) links.push_back(link_of(carrying.pair[s], carrying.at[s], carrying.weight[s]));
    if (carrying.count > 0) continue;
    index_t nearest = last;
    EdgeProjection at;
    for (index_t p = first; p < last; ++p) {
      const EdgeProjection q = project(n, i, c.pair_edge[p]);
      if (faces_edge(n, c, i, q, reach) && (nearest == last || std::fabs(q.gap) < std::fabs(at.gap))) nearest = p, at = q;
    }
    if (nearest != last) links.push_back(link_of(nearest, at, end_weight(at.along)));
  }
  return links;
}

std::vector<std::uint8_t> links_in_contact(const std::vector<ContactLink>& links) {
  std::vector<std::uint8_t> active(links.size());
  for (std::size_t k = 0; k < links.size(); ++k)
    active[k] = links[k].pressing || std::fabs(links[k].gap) <= kOnEdge * links[k].length;
  return active;
}

void add_link_stiffness(const std::vector<ContactLink>& links, const std::vector<std::uint8_t>& active,
                        const std::vector<index_t>& unknown, std::vector<Eigen::Triplet<double>>& entries) {
  for (std::size_t k = 0; k < links.size(); ++k) {
    const ContactLink& link = links[k];
    const double stiffness = active[k] ? link.stiffness : 0.0;
    add_penalty(link, link.ty, -link.tx, stiffness, unknown, entries);
    add_penalty(link, link.tx, link.ty, link.sticks ? stiffness : 0.0, unknown, entries);
  }
}

void model_link_forces(const std::vector<ContactLink>& links, const std::vector<std::uint8_t>& active,
                       const std::vector<index_t>& unknown, Eigen::VectorXd& rhs) {
  for (std::size_t k = 0; k < links.size(); ++k) {
    const ContactLink& link = links[k];
    // The model's normal force at du = 0 where active: -stiffness gap (pulling where the gap
    // is open: the step must close it for the link to stay active); its friction as it is.
    const double normal_now = link.force[0] * link.ty - link.force[1] * link.tx;
    const double normal_model = active[k] ? -link.stiffness * link.gap : 0.0;
    const double tangential_model = active[k] ? link.force[0] * link.tx + link.force[1] * link.ty : 0.0;
    const double tangential_now = link.force[0] * link.tx + link.force[1] * link.ty;
    const double dn = normal_model - normal_now, dt = tangential_model - tangential_now;
    const double fx = dn * link.ty + dt * link.tx, fy = -dn * link.tx + dt * link.ty;
    for (int k3 = 0; k3 < 3; ++k3) {
      const index_t ux = unknown[2 * std::size_t(link.receivers[k3])], uy = unknown[2 * std::size_t(link.receivers[k3]) + 1];
      if (ux != kNoIndex) rhs[Eigen::Index(ux)] += link.share[k3] * fx;
      if (uy != kNoIndex) rhs[Eigen::Index(uy)] += link.share[k3] * fy;
    }
  }
}

std::size_t update_active_links(const std::vector<ContactLink>& links, const Eigen::VectorXd& du,
                                const std::vector<index_t>& unknown, std::vector<std::uint8_t>& changes,
                                std::vector<std::uint8_t>& active) {
  constexpr std::uint8_t kHeldAfter = 2;  // changes
  std::size_t changed = 0;
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (changes[k] >= kHeldAfter) continue;
    const std::uint8_t closes = links[k].gap + along(links[k], links[k].ty, -links[k].tx, du, unknown) < 0.0;
    if (closes == active[k]) continue;
    const std::uint8_t next = ++changes[k] >= kHeldAfter ? std::uint8_t(links[k].pressing) : closes;
    changed += next != active[k];
    active[k] = next;
  }
  return changed;
}

}  // namespace ydry
