// The input deck (TOML, SI units, doc/deck.md "Format"): parsed, overridden with --set,
// validated, and resolved with defaults. Every key of the schema is read here; a key the
// schema does not know, a wrong type or an out-of-range value is an InputError naming the
// file, line and key.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace ydry {

struct MaterialDeck {
  std::string name;
  std::string where;  // "FILE:LINE: materials.NAME" for errors found later
  std::optional<double> density;                 // kg/m^3 (also the dry density of the soil)
  std::optional<double> young, poisson;          // Pa, -
  std::optional<double> tensile_strength, cohesion, friction_angle_deg;  // Pa, Pa, degrees
  std::optional<double> gf_I, gf_II;             // J/m^2
  std::optional<double> shrinkage_coefficient, shrinkage_limit;         // alpha, w_s
  std::optional<double> moisture_conductivity;   // k, kg/(m s); absent: no moisture model
  std::optional<double> initial_moisture;        // w_0, mass fraction
  std::optional<double> stress_free_moisture;    // w_i of Eq. 18; default: initial_moisture
  double mass_scaling = 1.0;                     // inertial mass factor of the relaxation
  double strength_heterogeneity = 0.0;           // CV of the joints' strength factor; 0: uniform
  bool breakable = true;
  bool rigid = false;
  // A material takes part in moisture diffusion when it has a conductivity.
  bool has_moisture() const { return moisture_conductivity.has_value(); }
};

// An [interfaces.A_B]: the edges shared by triangles of materials A and B (doc/deck.md
// "[interfaces.A_B]"). Bonded, they carry cohesive joints with these properties; else the two
// materials meet through contact alone.
struct InterfaceDeck {
  std::string name;   // the table's name, "A_B" in the deck's order
  std::string where;  // "FILE:LINE: interfaces.NAME" for errors found later
  std::pair<std::string, std::string> materials;  // sorted
  bool bonded = false;
  // Only when bonded:
  double tensile_strength = 0, cohesion = 0, friction_angle_deg = 0;  // Pa, Pa, degrees
  double gf_I = 0, gf_II = 0;                                         // J/m^2
  double joint_penalty = 0;  // p / E, E the smaller Young's modulus of its deformable materials
};

enum class MoistureBcType { flux, fixed, exchange };

// The `on` of a [[moisture.boundary]] on the top face of a layer seen in plan view.
inline const std::string kFaceBoundary = "face";

struct MoistureBoundaryDeck {
  std::string on;
  std::string where;         // "FILE:LINE: moisture.boundary[i].on", for errors found against the mesh
  MoistureBcType type = MoistureBcType::flux;
  double rate_kg_m2_s = 0;   // flux: positive into the soil
  double residual = 0;       // flux out stops at a node once its w is at or below this
  bool has_residual = false;
  double value = 0;          // fixed: w on the boundary
  double coefficient = 0;    // exchange: h, kg/(m^2 s)
  double air_moisture = 0;   // exchange: w_e
};

struct MechanicsBoundaryDeck {
  std::string on;
  std::string where;
  bool fix_x = false, fix_y = false;   // "fix" components
  bool driven = false;                 // velocity = [vx, vy] given: both components prescribed
  std::array<double, 2> velocity{};    // m/s
};

struct CrackSegmentDeck {
  std::array<double, 2> from{}, to{};
  std::string where;
};

enum class RelaxationMethod { viscous, fire, newton };

// The values of solver.relaxation, in the order of RelaxationMethod.
inline const std::vector<std::string> kRelaxationMethodKeys = {"viscous", "fire", "newton"};

// The defaults of the relaxation's [solver] keys (doc/deck.md "[solver]"): the deck reader
// fills them in and RelaxationControls (ycore/solid/relaxation.h) starts from them.
// [substrate] (doc/deck.md "[substrate]"): the base under a layer seen in plan view.
struct SubstrateDeck {
  std::optional<double> stiffness_pa_m;  // k_b, Pa/m; absent: G / h of the layer's material
  double adhesion_pa = 0;                // c_b
  double friction_angle_deg = 0;         // phi_b, with the layer's weight
  double gravity = 9.81;                 // m/s^2, through the layer's thickness
};

struct RelaxationDefaults {
  static constexpr double tolerance = 1e-7;
  static constexpr std::int64_t max_steps = 200000;
  static constexpr std::int64_t slide_after = 20000;
  static constexpr RelaxationMethod method = RelaxationMethod::newton;
};

struct Deck {
  std::string path;  // the deck file as given

  // [run]
  std::string name;
  bool plane_strain = false;
  // run.view = "plan": the mesh is the layer seen from above, run.thickness its thickness h,
  // on the substrate below (doc/physics.md "Plan view"); "section" (the default) otherwise.
  bool plan_view = false;
  double thickness_m = 1.0;
  double end_time_s = 0;
  double output_interval_s = 0;  // between frames
  double series_interval_s = 0;  // between rows of series.csv, cracks.csv and reactions.csv
  std::array<double, 2> gravity{0.0, -9.81};
  bool mechanics = true;
  std::int64_t seed = 1;
  double crack_width_threshold_m = 1e-5;

  // [mesh]
  std::string mesh_file;        // resolved against the deck's folder; empty for a generator
  std::string mesh_generator;   // "rectangle" or empty
  std::array<double, 2> mesh_size{};
  double element_size_m = 0;
  std::string mesh_pattern;
  std::string mesh_material;
  std::string mesh_where;

  std::map<std::string, MaterialDeck> materials;  // by name
  std::vector<InterfaceDeck> interfaces;          // [interfaces.A_B], by name

  std::vector<MoistureBoundaryDeck> moisture_boundaries;
  double crack_exchange_coefficient = 0;  // h_c, kg/(m^2 s)
  double crack_air_moisture = 0;          // w_e in cracks

  std::optional<SubstrateDeck> substrate;  // only in plan view

  std::vector<CrackSegmentDeck> cracks;
  std::vector<MechanicsBoundaryDeck> mechanics_boundaries;

  // [contact]
  std::optional<double> contact_penalty_pa;  // Pa, normal penalty (default 10 x the largest E)
  std::map<std::pair<std::string, std::string>, double> friction_deg;  // sorted name pair
  double contact_damping = 0.5;  // normal dashpot, fraction of critical

  // [solver]
  double moisture_safety = 0.9;  // fraction of the explicit stability limit
  double max_coupling_step_s = 0;     // upper bound of the staggered step; 0: none
  double mechanics_interval_s = 0;    // moisture time between relaxations; 0: every step
  double joint_penalty = 1000.0;      // joint penalty p / E
  double mechanics_safety = 0.8;      // fraction of the explicit mechanical stability limit
  double relaxation_tolerance = RelaxationDefaults::tolerance;  // out-of-balance force ratio that ends a relaxation
  std::int64_t relaxation_max_steps = RelaxationDefaults::max_steps;  // step cap of one relaxation
  std::int64_t relaxation_slide_after = RelaxationDefaults::slide_after;  // steps after which the friction slides at every step; 0: never
  bool node_mass_scaling = true;      // quasi-static: nodes stiff for their mass made heavier
  // Quasi-static relaxation: "viscous" (adaptive mass-proportional damping, Underwood),
  // "fire" (FIRE, Bitzek et al. 2006; ycore/solid/relaxation.cpp) or "newton" (Newton on the
  // out-of-balance force with a trust region, FIRE where it stops; ycore/solid/newton.cpp).
  RelaxationMethod relaxation = RelaxationDefaults::method;
  // "dynamic": the solid moves in real time (undamped central differences, velocities kept)
  // instead of relaxing to equilibrium after each coupling step.
  bool dynamic = false;

  toml::table resolved;  // the deck as used: file, --set overrides and defaults
};

// Reads and validates DECK with the overrides ("key.path=value", TOML value syntax; a value
// that is not TOML is taken as a string). Throws InputError.
Deck load_deck(const std::string& path, const std::vector<std::string>& overrides);

// The same from the deck's text: `path` names it in messages and locates a relative
// mesh.file, which is only checked to be a regular file (stat), never opened here.
Deck read_deck(const std::string& text, const std::string& path, const std::vector<std::string>& overrides);

// The resolved deck as TOML text (what deck.toml in the output holds): a header line that
// names the deck file, then resolved_deck_values.
std::string resolved_deck_text(const Deck& deck);

// Every value of the resolved deck, as TOML: two decks that give the same text make the same
// run, wherever their files are.
std::string resolved_deck_values(const Deck& deck);

}  // namespace ydry
