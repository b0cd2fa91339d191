// The whole simulation state as structs of arrays, one per entity (doc/architecture.md
// "State and lifetimes"). Indices are 32-bit.
//
// The mechanical mesh is exploded, as in Y-Code: every triangle owns its three nodes, and
// node 3t+a is corner a (counter-clockwise) of triangle t, so a triangle's nodes are implied
// by its index. Coincident corners of neighbouring triangles of one material, or of two
// materials across a bonded interface, are tied by a 4-node joint on their common edge. A moisture node is a connected set of coincident
// corners under intact joints (ycrack/node_sharing.h builds them).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ycore/state/mesh_input.h"
#include "ycore/state/ownership.h"
#include "ycore/state/stage_timing.h"

namespace ydry {

constexpr index_t kNoIndex = std::numeric_limits<index_t>::max();

inline index_t corner_node(index_t triangle, int corner) { return 3 * triangle + corner; }
inline index_t triangle_of(index_t node) { return node / 3; }
// The corner after `node` counter-clockwise in its triangle: edge node -> next_corner(node),
// and the one before it.
inline index_t next_corner(index_t node) { return node % 3 == 2 ? node - 2 : node + 1; }
inline index_t previous_corner(index_t node) { return node % 3 == 0 ? node + 2 : node - 1; }

// Every field below has one of five lifetimes (doc/architecture.md "State and lifetimes"),
// marked at its group:
//   constant  set up from the deck and the mesh, never changed by a run;
//   history   changed by a run and not derivable: checkpointed (state_fields.h);
//   topology  rebuilt from the broken joints after every split (and on a restart);
//   scratch   overwritten before it is read, every step or every call;
//   totals    ledgers summed since t = 0: checkpointed with the history.

struct Nodes {                    // [3 * triangles] each
  // constant
  std::vector<double> x0, y0;     // initial position, m
  std::vector<index_t> vertex;    // the mesh vertex this corner was made from
  std::vector<double> m;          // inertial mass of the pseudo-time relaxation, kg
  std::vector<std::uint8_t> constraint;  // kFixX | kFixY: component prescribed (fixed or driven)
  // [2 * nodes]: 4 j + k for each joint j of a material with mechanics whose node k this is
  // (a corner lies on two edges of its triangle, so at most two); kNoIndex where there is
  // none. Joint forces are gathered through it, so no node is written by two threads.
  std::vector<index_t> joint_slot;
  // history
  std::vector<double> x, y;       // current position, m
  std::vector<double> vx, vy;     // velocity, m/s
  // topology
  std::vector<index_t> mnode;     // its moisture node; kNoIndex in a material without moisture
  // The lowest corner tied to this one through intact joints: corners of one tie group are
  // one material point, and never in contact with each other.
  std::vector<index_t> tie_group;
  // scratch
  std::vector<double> fx, fy;     // net force, N (elements, joints, contact, gravity)
  std::size_t size() const { return x0.size(); }
};
constexpr std::uint8_t kFixX = 1, kFixY = 2;

struct Triangles {                // [triangles] each
  // constant
  std::vector<std::uint16_t> material;  // index into State::material_names
  std::vector<double> area0;            // initial area, m^2
  std::vector<double> inv0;             // [4 * triangles] inverse of the initial edge matrix
                                        // [X1-X0 | X2-X0], row-major
  std::vector<double> mass_kg;          // physical mass rho A0 t (gravity uses it)
  // history
  std::vector<double> shrinkage_strain; // eigenstrain eps_sh of Eq. 18 (negative on drying)
  std::vector<double> sxx, syy, sxy;    // Cauchy stress, Pa, at the last equilibrium
  std::size_t size() const { return area0.size(); }
};

// One per interior edge inside a material, and per edge of a bonded interface between two
// (doc/physics.md "Interface joints").
struct Joints {
  // constant
  // [4 * joints]: edge a-b of the first triangle (CCW), then b'-a' of the second, so that
  // node 4j+0 meets 4j+3 and 4j+1 meets 4j+2.
  std::vector<index_t> node;
  // [joints] the properties of its cohesive law, an index into State::materials: those of
  // the material of both its triangles, or, from State::material_names.size() on, a bonded
  // interface's (State::interface_names; is_interface_joint).
  std::vector<std::uint16_t> law;
  std::vector<double> length0;          // [joints] initial length, m
  std::vector<double> strength_factor;  // [joints] multiplies the material's tensile strength
                                        // and cohesion (strength_heterogeneity; 1 without)
  // The joints of a material with mechanics, as runs of consecutive joints: run r is
  // [mechanical_runs[2r], mechanical_runs[2r + 1]), ascending. The joint kernel visits only
  // these; a rigid material's joints (the Peron deck's base: a third of its joints) carry
  // nothing, ever: their forces stay 0 and no work is done on them. (A list of single joints
  // instead makes the kernel a fifth slower on a mesh with no rigid joints.)
  std::vector<index_t> mechanical_runs;
  // history
  std::vector<std::uint8_t> broken;     // [joints] 1 once the joint has failed, for good
  std::vector<double> damage;           // [3 * joints] committed damage D at the two ends and
                                        // the middle (never decreases: joints do not heal)
  std::vector<double> force;            // [8 * joints] force on its nodes 0..3 at the last
                                        // step, N: the gather reads it, and the next step's
                                        // work is the trapezoid of it and the new force
  // totals
  std::vector<double> work;             // [joints] work done on the joint since t = 0, J
  std::size_t size() const { return broken.size(); }
};

// A flux or exchange term of a moisture node: a boundary edge half or a crack face half.
enum class MoistureTermKind : std::uint8_t { flux, exchange };

// Moisture nodes: connected sets of coincident corners under intact joints (doc/physics.md
// "Cracks and moisture"), rebuilt with everything they carry at every split but for w.
struct MoistureNodes {
  // history
  std::vector<double> w;              // [mnodes] moisture content, mass fraction of dry mass
  // topology
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
  // scratch
  std::vector<double> boundary_inflow;  // [mnodes] kg/s in through the boundary
  std::size_t size() const { return w.size(); }
};

// Per-triangle conductance: inflow into corner a = -sum_b K_ab w_b, K_ab = k t A grad N_a .
// grad N_b (Eqs. 2-4), from the initial geometry; 6 entries K00 K01 K02 K11 K12 K22.
struct MoistureElements {
  std::vector<double> conductance;    // constant: [6 * triangles] kg/s per unit w; 0 without moisture
  std::vector<double> corner_inflow;  // scratch: [3 * triangles] kg/s into each corner
};

// Water bookkeeping for water_balance_error (doc/measures.md "Energies and water balance"),
// compensated sums. Totals.
struct WaterBalance {
  double initial_kg = 0;     // water in the soil at t = 0
  double net_in_kg = 0;      // through boundaries and crack faces since t = 0
  double net_in_carry = 0;   // Neumaier compensation of net_in_kg
  double gross_kg = 0;       // |in| + |out| since t = 0: the scale when initial_kg is 0
};

// Derived per-material constants of the solid (built from the deck by init_mechanics).
struct MaterialModel {
  bool mechanical = false;     // has the elastic constants (every material of a mechanics run)
  bool rigid = false, breakable = true;
  double density = 0;          // kg/m^3
  double mass_scaling = 1;     // inertial mass = mass_scaling x physical (pseudo-time only)
  double lambda = 0, mu = 0;   // in-plane Lame constants (plane stress: lambda* = E nu/(1-nu^2))
  double bulk3 = 0;            // 3 K*: isotropic stress per unit shrinkage strain (Eq. 19)
  bool plane_strain = false;
  double young = 0;
  double shrinkage_coefficient = 0, shrinkage_limit = 0, stress_free_moisture = 0;  // Eq. 18
  double penalty = 0;          // joint penalty p, Pa
  double tensile_strength = 0, cohesion = 0, tan_friction = 0, gf_I = 0, gf_II = 0;
  double strength_heterogeneity = 0;  // coefficient of variation of the joints' strength factor
};

// A [[mechanics.boundary]]: nodes whose components are fixed or driven at a velocity.
struct MechanicsBoundary {
  // constant
  std::string name;
  std::vector<index_t> nodes;   // unique, ascending
  bool fix_x = false, fix_y = false;
  double vx = 0, vy = 0;        // m/s of the prescribed components (0 when fixed)
  // totals
  double reaction_x = 0, reaction_y = 0;  // N, force the support exerts, last equilibrium
  double work_J = 0;            // work done on the solid through this boundary since t = 0
};

// Two tie groups as one key, the lower in the high half (Contact::bonded_line).
inline std::uint64_t bonded_line_key(index_t a, index_t b) {
  return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

// A contact corner against one surface edge (project, ycore/contact/contact_geometry.h): where it
// projects (0..1 from the edge's first corner) and how far it lies outside (negative: inside
// the edge's triangle), with the edge's unit tangent.
struct EdgeProjection {
  double along = 0, gap = 0, length = 0, tx = 0, ty = 0;
};

// The (at most two) pairs that carry a corner's contact, where it projects on their edges, and
// their shares of it (contact_shares, ycore/contact/contact_geometry.h).
struct ContactShares {
  int count = 0;
  index_t pair[2] = {0, 0};
  EdgeProjection at[2];
  double weight[2] = {0, 0};
};

// Penalty contact between surface edges (doc/physics.md "Contact and friction"): node-to-edge
// in both directions, Coulomb friction as an elastic slip capped at mu f_n.
struct Contact {
  // constant
  double penalty_pa = 0;              // normal penalty p_n, Pa: a node pressed a depth g into
                                      // an edge carries p_n t g / 2 per surface edge of its own
                                      // (a closed joint's traction p g / l over half its length)
  std::vector<double> tan_friction;   // [materials^2] mu of each material pair
  double damping_ratio = 0;           // normal dashpot, fraction of critical
  double buffer_m = 0;                // candidates are kept within 2 buffers; rebuilt when a
                                      // surface node has moved more than one
  // topology: surfaces are triangle edges with no joint or a broken one. An edge is named by
  // its first corner c, and runs counter-clockwise to next_corner(c).
  std::vector<index_t> surface_edge;  // first corners, ascending
  std::vector<index_t> surface_node;  // corners on a surface edge, ascending
  std::vector<std::uint8_t> is_surface_edge;   // [nodes] whether the edge it starts is one
  std::vector<std::uint64_t> bonded_line;  // tie groups an intact joint's line joins, as
                                      // bonded_line_key(lower, higher), ascending
  // history: candidate pairs (node, surface edge), sorted by node then edge, from the broad
  // phase, with their friction and last forces, and where the broad phase last looked.
  std::vector<index_t> pair_node, pair_edge;
  std::vector<double> pair_slip;      // elastic tangential slip of the pair, m (friction history)
  std::vector<double> pair_force;     // [6 * pairs] force on the node, edge a, edge b at the
                                      // last step: gathered, and the trapezoid of the work
  std::vector<double> x_built, y_built;  // [surface nodes] positions at the last build
  // topology of the pairs, indexed from them (index_contact_pairs)
  std::vector<index_t> node_pairs;    // CSR: pairs of the k-th distinct node start at node_pairs[k]
  std::vector<std::size_t> corner_owner_begin;  // the corners of each Ownership slot's nodes
  std::vector<index_t> gather_offset; // [nodes + 1] CSR into gather_entry: the pair forces a
  std::vector<index_t> gather_entry;  //   node receives, as 3 pair + slot (0 node, 1 a, 2 b)
  // scratch of the positions where update_contact_pairs last ran, read by the contact phases
  // at those positions (ycore/contact/contact_forces.h): per corner (node_pairs), whether the
  // phases take it, and the pairs that carry its contact
  std::vector<std::uint8_t> corner_busy;
  std::vector<ContactShares> corner_shares;
  // totals
  double work_J = 0;                  // work done on the solid by contact forces since t = 0
  std::uint64_t builds = 0;           // broad phases run
};

// The solid's controls, relaxation scratch and energy bookkeeping.
struct ChordFactor;  // stiffness_model.h
// The fill-reducing ordering of the implicit solver's factorisations (stiffness_model.h).
enum class FillOrdering : std::uint8_t { undecided, amd, metis };

struct Mechanics {
  // constant
  double thickness_m = 1;                 // out-of-plane
  double gravity_x = 0, gravity_y = 0;    // m/s^2
  // Nodes driven at a prescribed velocity (unique, ascending) and that velocity, m/s.
  std::vector<index_t> driven_node;
  std::vector<double> driven_vx, driven_vy;
  double step_s = 0;                      // pseudo-time step of the explicit integration
  double roundoff_net2 = 0;               // N^2: |net force|^2 that round-off alone makes
  double mesh_diagonal_m = 0;             // of the initial bounding box: a node that moves
                                          // farther in one relaxation has run away
  // scratch
  std::vector<double> x_start, y_start;   // [nodes] positions when the relaxation began
  // history
  double unrelaxed_s = 0;                 // moisture time since the last relaxation
  // The matrix K + K_c + mu M a Newton relaxation last converged with (newton.cpp), over the
  // free components chord_components, in compressed columns; empty before. The next
  // relaxations take their first steps with its factor while it serves (doc/solver.md).
  std::vector<index_t> chord_components, chord_outer, chord_inner;
  std::vector<double> chord_values;
  // runtime: the factor of that matrix, made again where it is not that matrix's
  std::shared_ptr<ChordFactor> chord_factor;
  // runtime: the ordering of this mesh's factorisations, decided from the mesh at the first
  // (fill_ordering in stiffness_model.h), so again the same after a restart
  FillOrdering fill_ordering = FillOrdering::undecided;
  // totals
  double last_residual = 0;               // out-of-balance force ratio after the last relaxation
  std::uint64_t steps = 0;                // mechanical steps since t = 0
  std::uint64_t capped_relaxations = 0;   // relaxations stopped by the step cap
  std::uint64_t newton_fallbacks = 0;     // Newton relaxations that FIRE finished
  std::uint64_t friction_slide_relaxations = 0;  // relaxations whose friction slid at every step
  double worst_residual = 0;              // the largest out-of-balance ratio a relaxation ended
                                          // at, above the round-off floor
  double gravity_work_J = 0;              // work of gravity since t = 0
};

// The substrate under a layer seen in plan view (doc/physics.md "Plan view"): every node is
// held to the base over its tributary area by an elastic shear traction, capped where it
// slides (adhesion plus friction under the layer's weight). Empty in a vertical section.
struct Substrate {
  // constant, [nodes]
  std::vector<double> stiffness;      // N/m: k_b times the tributary area
  std::vector<double> cap;            // N: (c_b + tan(phi_b) rho g h) times the tributary area
  // history, [nodes]: where the node's traction is zero, from its initial position: the slide
  // committed at the last equilibrium (as the contact's friction slip)
  std::vector<double> slide_x, slide_y;
  // total
  double slide_work_J = 0;  // work the slides committed since t = 0 dissipated: cap times slide
  bool present() const { return !stiffness.empty(); }
};

struct State {
  Nodes nodes;
  Triangles triangles;
  Joints joints;
  MoistureNodes moisture;
  MoistureElements moisture_elements;
  WaterBalance water;
  Mechanics mechanics;
  Contact contact;
  Substrate substrate;
  std::vector<MechanicsBoundary> mechanics_boundaries;
  // constant
  Ownership ownership;                                     // the threads' ranges (ownership.h)
  // By material id, then by interface: entry material_names.size() + i holds the joint
  // properties of the bonded interface interface_names[i] (only its joint constants are set).
  std::vector<MaterialModel> materials;
  std::vector<std::string> material_names;                 // material id -> deck name
  std::vector<std::string> interface_names;                // bonded [interfaces.NAME] of the deck, in its order
  std::map<std::string, std::vector<index_t>> boundary_edges;  // name -> node pairs (one triangle's)
  // history
  double time_s = 0;
  std::uint64_t coupling_steps = 0;  // steps of the staggered loop since t = 0
  // this process's wall time by stage: not part of the physics, not checkpointed
  StageSeconds wall;
};

// Whether joint j ties two materials (a bonded interface's) rather than the triangles of one:
// its property index lies past the `materials` materials' (Joints::law).
inline bool is_interface_joint(const Joints& joints, std::size_t materials, std::size_t j) {
  return joints.law[j] >= materials;
}
inline bool is_interface_joint(const State& s, std::size_t j) { return is_interface_joint(s.joints, s.material_names.size(), j); }

}  // namespace ydry
