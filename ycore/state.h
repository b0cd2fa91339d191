// The whole simulation state as structs of arrays (DESIGN section 3). Indices are 32-bit.
//
// The mechanical mesh is exploded, as in Y-Code: every triangle owns its three nodes, and
// node 3t+a is corner a (counter-clockwise) of triangle t, so a triangle's nodes are implied
// by its index. Coincident corners of neighbouring triangles of one material are tied by a
// 4-node joint on their common edge. A moisture node is a connected set of coincident
// corners under intact joints (ycrack builds them).
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "ycore/mesh_input.h"

namespace ydry {

constexpr index_t kNoIndex = std::numeric_limits<index_t>::max();

inline index_t corner_node(index_t triangle, int corner) { return 3 * triangle + corner; }
inline index_t triangle_of(index_t node) { return node / 3; }

struct Nodes {                    // [3 * triangles] each
  std::vector<double> x0, y0;     // initial position, m
  std::vector<double> x, y;       // current position, m
  std::vector<double> vx, vy;     // velocity, m/s
  std::vector<index_t> vertex;    // the mesh vertex this corner was made from
  std::vector<index_t> mnode;     // its moisture node; kNoIndex in a material without moisture
  std::size_t size() const { return x0.size(); }
};

struct Triangles {                // [triangles] each
  std::vector<std::uint16_t> material;  // index into State::material_names
  std::vector<double> area0;            // initial area, m^2
  std::size_t size() const { return area0.size(); }
};

struct Joints {                   // one per interior edge inside a material
  // [4 * joints]: edge a-b of the first triangle (CCW), then b'-a' of the second, so that
  // node 4j+0 meets 4j+3 and 4j+1 meets 4j+2.
  std::vector<index_t> node;
  std::vector<std::uint8_t> broken;     // [joints] 1 once the joint has failed, for good
  std::size_t size() const { return broken.size(); }
};

// A flux or exchange term of a moisture node: a boundary edge half, later a crack face half.
enum class MoistureTermKind : std::uint8_t { flux, exchange };

struct MoistureNodes {
  std::vector<double> w;              // [mnodes] moisture content, mass fraction of dry mass
  std::vector<double> dry_mass;       // [mnodes] kg
  std::vector<index_t> corner_offset; // [mnodes + 1] CSR into corner
  std::vector<index_t> corner;        // mechanical nodes merged into each moisture node
  std::vector<double> fixed_w;        // [mnodes] Dirichlet value, NaN where free
  // Boundary terms, CSR by moisture node (term_offset [mnodes + 1]); per term [terms]:
  std::vector<index_t> term_offset;
  std::vector<MoistureTermKind> term_kind;
  std::vector<double> term_area;      // half edge length x thickness, m^2
  std::vector<double> term_rate;      // flux: kg/(m^2 s) into the soil; exchange: h, kg/(m^2 s)
  std::vector<double> term_level;     // flux: residual w (flux out stops at or below it);
                                      // exchange: air moisture w_e
  std::vector<index_t> boundary_node;   // moisture nodes with terms or a fixed value, ascending
  std::vector<double> boundary_inflow;  // [mnodes] scratch: kg/s in through the boundary
  std::size_t size() const { return w.size(); }
};

// Per-triangle conductance: inflow into corner a = -sum_b K_ab w_b, K_ab = k t A grad N_a .
// grad N_b (Eqs. 2-4), from the initial geometry; 6 entries K00 K01 K02 K11 K12 K22.
struct MoistureElements {
  std::vector<double> conductance;    // [6 * triangles] kg/s per unit w; 0 without moisture
  std::vector<double> corner_inflow;  // [3 * triangles] scratch: kg/s into each corner
};

// Water bookkeeping for water_balance_error (DESIGN section 5), compensated sums.
struct WaterBalance {
  double initial_kg = 0;     // water in the soil at t = 0
  double net_in_kg = 0;      // through boundaries and crack faces since t = 0
  double net_in_carry = 0;   // Neumaier compensation of net_in_kg
  double gross_kg = 0;       // |in| + |out| since t = 0: the scale when initial_kg is 0
};

struct State {
  Nodes nodes;
  Triangles triangles;
  Joints joints;
  MoistureNodes moisture;
  MoistureElements moisture_elements;
  WaterBalance water;
  std::vector<std::string> material_names;                 // material id -> deck name
  std::map<std::string, std::vector<index_t>> boundary_edges;  // name -> node pairs (one triangle's)
  double time_s = 0;
  std::uint64_t moisture_steps = 0;
};

}  // namespace ydry
