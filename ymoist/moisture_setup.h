// Setting up the moisture model on the grouped topology (paper Eqs. 1-17): values, dry masses,
// triangle conductances, and the boundary terms of the deck and of the crack faces.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// The parts of the state the moisture set-up reads: the mesh with its moisture nodes grouped
// (ycrack), its materials' names, its named boundaries, and the joints whose faces exchange
// with the air in the cracks.
struct MoistureMesh {
  const Nodes& nodes;          // x0, y0, mnode
  const Triangles& triangles;  // material, area0
  const Joints& joints;        // node, broken
  const std::vector<std::string>& material_names;
  const std::map<std::string, std::vector<index_t>>& boundary_edges;
};
inline MoistureMesh moisture_mesh(const State& s) {
  return {s.nodes, s.triangles, s.joints, s.material_names, s.boundary_edges};
}

// Sets up the moisture model on a state whose moisture nodes are grouped (moisture.corner and
// corner_offset, nodes.mnode): initial w, dry masses, triangle conductances, boundary terms
// from the deck's [[moisture.boundary]] entries and from the faces of broken joints
// ([moisture.cracks], Eqs. 10-17; doc/physics.md "Cracks and moisture"), fixed values, and
// the water balance's starting point.
void init_moisture(const MoistureMesh& mesh, const Deck& deck, MoistureNodes& moisture,
                   MoistureElements& elements, WaterBalance& water);

// After the moisture nodes were regrouped (ycrack, when joints broke): each new node takes
// the w of the node it was part of, its share of dry mass and of the boundary terms, and the
// faces of the joints that broke get their exchange terms; the water in the soil is unchanged.
// old_mnode and old_w are nodes.mnode and moisture.w before the regrouping.
void remap_moisture_nodes(const MoistureMesh& mesh, const Deck& deck, const std::vector<index_t>& old_mnode,
                          const std::vector<double>& old_w, MoistureNodes& moisture);

}  // namespace ydry
