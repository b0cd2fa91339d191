// The census of a crack network seen in plan (doc/measures.md "Crack network"): the cells
// (fragments) the broken joints cut the layer into, the crack voids between them and the
// junctions where crack branches meet, as experiments measure a photographed network.
#pragma once

#include <cstdint>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// How the branches of an interior junction meet: three branches with one angle between
// neighbours of 150 degrees or more, nearer 180 than 120 (a crack ending on an older one at
// right angles: T); three branches with every angle under 150 (Y); four or more (other).
enum class JunctionKind : std::uint8_t { T, Y, other };

struct Junction {
  double x0 = 0, y0 = 0;        // the mesh vertex where the branches meet (initial position), m
  std::vector<double> angles;   // degrees between neighbouring branches, counter-clockwise from
                                // the branch nearest the +x direction; they sum to 360
  JunctionKind kind = JunctionKind::other;
};

struct NetworkCensus {
  std::vector<index_t> cell_of_triangle;  // fragment_cells

  std::vector<double> cell_area_m2;        // [cells] current area
  std::vector<double> cell_perimeter_m;    // [cells] current length of its outline: the outer
                                           // boundary's edges and the faces of broken joints
  double layer_area_m2 = 0;                // initial area of the triangles counted
  double crack_area_m2 = 0;                // the voids between the faces of broken joints
  double crack_length_m = 0;               // initial length of the broken joints
  std::vector<Junction> junctions;         // interior junctions, in the order of their vertex
  // crack intensity factor: crack area over the layer's initial area
  double crack_intensity() const { return layer_area_m2 > 0.0 ? crack_area_m2 / layer_area_m2 : 0.0; }
  // crack length per unit area, 1/m
  double crack_density_per_m() const { return layer_area_m2 > 0.0 ? crack_length_m / layer_area_m2 : 0.0; }
  std::size_t count(JunctionKind kind) const;
};

// [triangles] the cell (fragment) of each triangle of a deformable material, kNoIndex for the
// others: the sets of triangles that intact joints join, numbered in the order of their
// lowest triangle. The census's cell_of_triangle; the frames' `cell` array.
std::vector<index_t> fragment_cells(const Triangles& triangles, const Joints& joints,
                                    const std::vector<MaterialModel>& materials);

// The census of the current state. Triangles of deformable materials count; joints of a
// bonded interface between two materials are no cracks. A cell is a set of triangles that
// intact joints join. A broken joint's void is the area of the quadrilateral between its two
// faces where they lie apart (0 where they press together). The crack network is the graph of
// the mesh vertices that broken joints join; a vertex off the outer boundary where three or
// more of them meet is a junction, each branch's direction measured from the vertex to where
// its crack has run three mean broken-joint lengths (or ends, or meets another junction), so
// that the zig-zag of a crack along the mesh's edges does not set the angles.
NetworkCensus take_network_census(const Nodes& nodes, const Triangles& triangles, const Joints& joints,
                                  const std::vector<MaterialModel>& materials, std::size_t material_count);

}  // namespace ydry
