// The state's fields by lifetime (state.h; doc/architecture.md "State and lifetimes"), each
// with its name, for everything that must visit all of one lifetime: the checkpoint writes
// and restores the history and totals (ycore/output/checkpoint.cpp), and the tests' state
// snapshot and the bench's state hash compare them and the topology. A field added to the
// state goes here too, or it is neither checkpointed nor compared.
#pragma once

#include <string>

#include "ycore/state/state.h"

namespace ydry {

// What a run changes and nothing rebuilds from the deck, the mesh and the broken joints:
// positions and velocities (a relaxation predicts from the last step's), stresses and
// eigenstrains, joint damage and the joints' last forces (the next step's work is a trapezoid
// over them), moisture, the contact pairs with their friction slip, last forces and the
// positions of the last broad phase (which decide the next one), and the totals: time, steps,
// the water, energy and step ledgers, the supports' reactions and work. The names are those
// of the checkpoint format.
template <class S, class Field>
void for_each_history_field(S& s, Field&& field) {
  field("time_s", s.time_s);
  field("moisture_steps", s.coupling_steps);
  field("nodes.x", s.nodes.x);
  field("nodes.y", s.nodes.y);
  field("nodes.vx", s.nodes.vx);
  field("nodes.vy", s.nodes.vy);
  field("triangles.shrinkage_strain", s.triangles.shrinkage_strain);
  field("triangles.sxx", s.triangles.sxx);
  field("triangles.syy", s.triangles.syy);
  field("triangles.sxy", s.triangles.sxy);
  field("joints.broken", s.joints.broken);
  field("joints.damage", s.joints.damage);
  field("joints.work", s.joints.work);
  field("joints.force", s.joints.force);
  field("moisture.w", s.moisture.w);
  field("water.initial_kg", s.water.initial_kg);
  field("water.net_in_kg", s.water.net_in_kg);
  field("water.net_in_carry", s.water.net_in_carry);
  field("water.gross_kg", s.water.gross_kg);
  field("mechanics.unrelaxed_s", s.mechanics.unrelaxed_s);
  field("mechanics.chord_components", s.mechanics.chord_components);
  field("mechanics.chord_outer", s.mechanics.chord_outer);
  field("mechanics.chord_inner", s.mechanics.chord_inner);
  field("mechanics.chord_values", s.mechanics.chord_values);
  field("mechanics.last_residual", s.mechanics.last_residual);
  field("mechanics.steps", s.mechanics.steps);
  field("mechanics.capped_relaxations", s.mechanics.capped_relaxations);
  field("mechanics.newton_fallbacks", s.mechanics.newton_fallbacks);
  field("mechanics.friction_slide_relaxations", s.mechanics.friction_slide_relaxations);
  field("mechanics.worst_residual", s.mechanics.worst_residual);
  field("mechanics.gravity_work_J", s.mechanics.gravity_work_J);
  for (std::size_t b = 0; b < s.mechanics_boundaries.size(); ++b) {
    const std::string prefix = "mechanics.boundary[" + std::to_string(b) + "].";
    field(prefix + "reaction_x", s.mechanics_boundaries[b].reaction_x);
    field(prefix + "reaction_y", s.mechanics_boundaries[b].reaction_y);
    field(prefix + "work_J", s.mechanics_boundaries[b].work_J);
  }
  if (s.substrate.present()) {  // a plan view's (its deck, and so the checkpoint's)
    field("substrate.slide_x", s.substrate.slide_x);
    field("substrate.slide_y", s.substrate.slide_y);
    field("substrate.slide_work_J", s.substrate.slide_work_J);
  }
  field("contact.pair_node", s.contact.pair_node);
  field("contact.pair_edge", s.contact.pair_edge);
  field("contact.pair_slip", s.contact.pair_slip);
  field("contact.pair_force", s.contact.pair_force);
  field("contact.x_built", s.contact.x_built);
  field("contact.y_built", s.contact.y_built);
  field("contact.work_J", s.contact.work_J);
  field("contact.builds", s.contact.builds);
}

// What follows from the broken joints alone, rebuilt after every split and on a restart:
// moisture nodes and their boundary terms, tie groups, contact surfaces and the pairs' index.
template <class S, class Field>
void for_each_topology_field(S& s, Field&& field) {
  field("nodes.mnode", s.nodes.mnode);
  field("nodes.tie_group", s.nodes.tie_group);
  field("moisture.dry_mass", s.moisture.dry_mass);
  field("moisture.corner_offset", s.moisture.corner_offset);
  field("moisture.corner", s.moisture.corner);
  field("moisture.fixed_w", s.moisture.fixed_w);
  field("moisture.term_offset", s.moisture.term_offset);
  field("moisture.term_kind", s.moisture.term_kind);
  field("moisture.term_area", s.moisture.term_area);
  field("moisture.term_rate", s.moisture.term_rate);
  field("moisture.term_level", s.moisture.term_level);
  field("moisture.boundary_node", s.moisture.boundary_node);
  field("contact.surface_edge", s.contact.surface_edge);
  field("contact.surface_node", s.contact.surface_node);
  field("contact.is_surface_edge", s.contact.is_surface_edge);
  field("contact.bonded_line", s.contact.bonded_line);
  field("contact.node_pairs", s.contact.node_pairs);
  field("contact.corner_owner_begin", s.contact.corner_owner_begin);
  field("contact.gather_offset", s.contact.gather_offset);
  field("contact.gather_entry", s.contact.gather_entry);
}

}  // namespace ydry
