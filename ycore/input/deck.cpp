// The deck schema (doc/deck.md "Format"): one reader per section, each a TableReader
// (toml_reader.h) that checks types and ranges, fills defaults into the resolved deck and
// rejects unknown keys.
#include "ycore/input/deck.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ycore/input/input_error.h"
#include "ycore/input/mesh_size.h"
#include "ycore/input/toml_reader.h"
#include "ycore/input/toml_writer.h"

namespace ydry {
namespace {

void read_run(TableReader r, Deck& d) {
  d.name = r.string("name", {}, std::nullopt);
  if (d.name.empty() || d.name.find_first_of("/\\ ") != std::string::npos)
    r.error("name", "must be a non-empty name without spaces or slashes (it names the output files)");
  d.plane_strain = r.string("plane", {"stress", "strain"}, std::string("stress")) == "strain";
  // Read only when given, so that a vertical section's resolved deck is as it always was.
  d.plan_view = r.optional_string("view", {"section", "plan"}).value_or("section") == "plan";
  if (d.plan_view && d.plane_strain)
    r.error("plane", "a layer seen in plan view is in plane stress: its top and bottom faces carry no normal stress");
  d.thickness_m = r.number("thickness", kPositive, 1.0);
  d.end_time_s = r.number("end_time", kPositive, std::nullopt);
  d.output_interval_s = r.number("output_interval", kPositive, std::nullopt);
  d.series_interval_s = r.number("series_interval", kPositive, d.output_interval_s);
  if (d.series_interval_s > d.output_interval_s)
    r.error("series_interval", "is longer than run.output_interval (tables get at least a row per frame)");
  d.gravity = r.pair("gravity", kAny, std::array<double, 2>{0.0, d.plan_view ? 0.0 : -9.81});
  if (d.plan_view && (d.gravity[0] != 0.0 || d.gravity[1] != 0.0))
    r.error("gravity", "in plan view gravity acts through the layer's thickness, pressing it on its base: give "
                       "substrate.gravity instead");
  d.mechanics = r.boolean("mechanics", true);
  d.seed = r.integer("seed", 0, 1);
  d.crack_width_threshold_m = r.number("crack_width_threshold", kNonNegative, 1e-5);
  r.finish();
}

void read_mesh(TableReader r, Deck& d) {
  d.mesh_where = r.where_table();
  const auto file = r.optional_string("file");
  const auto generator = r.optional_string("generator", {"rectangle"});
  if (file.has_value() == generator.has_value())
    r.error(file ? "generator" : "file", "give exactly one of mesh.file and mesh.generator");
  if (file) {
    const std::filesystem::path deck_dir = std::filesystem::path(d.path).parent_path();
    const std::filesystem::path p = deck_dir / *file;
    // A regular file only (stat, not opened here): the mesh reader never meets /dev/zero, a
    // FIFO or a folder. The error_code form, as a name too long to stat is "not found" too.
    std::error_code error;
    if (!std::filesystem::is_regular_file(p, error)) r.error("file", "mesh file '" + p.string() + "' not found");
    d.mesh_file = p.string();
  } else {
    d.mesh_generator = *generator;
    d.mesh_size = r.pair("size", kPositive, std::nullopt);
    d.element_size_m = r.number("element_size", kPositive, std::nullopt);
    d.mesh_pattern = r.string("pattern", {"right", "left", "cross"}, std::string("right"));
    d.mesh_material = r.string("material", {}, std::nullopt);
    const auto cells = rectangle_cells(d.mesh_size[0], d.mesh_size[1], d.element_size_m);
    const double triangles = cells[0] * cells[1] * (d.mesh_pattern == "cross" ? 4 : 2);
    if (!(triangles <= kMaxTriangles)) {  // also when the cell count overflows to inf
      std::ostringstream s;
      s << "makes " << triangles << " triangles of mesh.size; 32-bit indices number at most " << kMaxTriangles;
      r.error("element_size", s.str());
    }
  }
  r.finish();
}

MaterialDeck read_material(TableReader r, const std::string& name) {
  MaterialDeck m;
  m.name = name;
  m.where = r.where_table();
  m.density = r.optional_number("density", kPositive);
  m.young = r.optional_number("young", kPositive);
  m.poisson = r.optional_number("poisson", Range{-1, 0.5, true, true});
  m.tensile_strength = r.optional_number("tensile_strength", kPositive);
  m.cohesion = r.optional_number("cohesion", kNonNegative);
  m.friction_angle_deg = r.optional_number("friction_angle", Range{0, 90, false, true});
  m.gf_I = r.optional_number("gf_I", kPositive);
  m.gf_II = r.optional_number("gf_II", kPositive);
  m.shrinkage_coefficient = r.optional_number("shrinkage_coefficient", kNonNegative);
  m.shrinkage_limit = r.optional_number("shrinkage_limit", kNonNegative);
  m.moisture_conductivity = r.optional_number("moisture_conductivity", kNonNegative);
  m.initial_moisture = r.optional_number("initial_moisture", kNonNegative);
  m.stress_free_moisture = r.optional_number("stress_free_moisture", kNonNegative);
  m.mass_scaling = r.number("mass_scaling", kPositive, 1.0);
  m.breakable = r.boolean("breakable", true);
  m.rigid = r.boolean("rigid", false);
  // Up to 1, a Weibull modulus of 1 (strength_heterogeneity.h); a material whose joints never
  // fail refuses the key rather than ignore it.
  if (m.breakable && !m.rigid)
    m.strength_heterogeneity = r.number("strength_heterogeneity", Range{0, 1, false, false}, 0.0);
  else if (r.has("strength_heterogeneity"))
    r.error("strength_heterogeneity", m.rigid ? "a rigid material has no joints to weaken"
                                              : "the joints of a material with breakable = false never fail");
  if (m.has_moisture()) {
    if (!m.density) r.missing("density");
    if (!m.initial_moisture) r.missing("initial_moisture");
  }
  r.finish();
  return m;
}

MoistureBoundaryDeck read_moisture_boundary(TableReader r, const Deck& d) {
  MoistureBoundaryDeck b;
  b.on = r.string("on", {}, std::nullopt);
  b.where = r.where("on");
  if (b.on == kFaceBoundary && !d.plan_view)
    r.error("on", "a vertical section has no face to dry through: \"face\" needs run.view = \"plan\"");
  const std::string type = r.string("type", {"flux", "fixed", "exchange"}, std::nullopt);
  if (b.on == kFaceBoundary && type == "fixed")
    r.error("type", "a fixed moisture on the face would hold the whole layer at it: give a flux or an exchange");
  // Keys that belong to another type are errors: a user who wrote them expects an effect.
  const auto reject = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (r.has(k)) r.error(k, std::string("not used by a boundary of type \"") + type + "\"");
  };
  if (type == "flux") {
    b.type = MoistureBcType::flux;
    b.rate_kg_m2_s = r.number("rate", kAny, std::nullopt);
    if (auto res = r.optional_number("residual", kNonNegative)) {
      if (b.rate_kg_m2_s >= 0) r.error("residual", "only an outflow (rate < 0) stops at a residual moisture");
      b.residual = *res;
      b.has_residual = true;
    }
    reject({"value", "coefficient", "air_moisture"});
  } else if (type == "fixed") {
    b.type = MoistureBcType::fixed;
    b.value = r.number("value", kNonNegative, std::nullopt);
    reject({"rate", "residual", "coefficient", "air_moisture"});
  } else {
    b.type = MoistureBcType::exchange;
    b.coefficient = r.number("coefficient", kNonNegative, std::nullopt);
    b.air_moisture = r.number("air_moisture", kNonNegative, std::nullopt);
    reject({"rate", "residual", "value"});
  }
  r.finish();
  return b;
}

void read_moisture(TableReader r, Deck& d, const Origin& file) {
  if (toml::array* arr = r.table_array("boundary")) {
    for (std::size_t i = 0; i < arr->size(); ++i)
      d.moisture_boundaries.push_back(read_moisture_boundary(
          TableReader(*arr->get(i)->as_table(), "moisture.boundary[" + std::to_string(i) + "]", file), d));
  }
  TableReader cracks(r.subtable("cracks"), "moisture.cracks", file);
  d.crack_exchange_coefficient = cracks.number("exchange_coefficient", kNonNegative, 0.0);
  d.crack_air_moisture = cracks.number("air_moisture", kNonNegative, 0.0);
  cracks.finish();
  r.finish();
}

void read_mechanics(TableReader r, Deck& d, const Origin& file) {
  if (toml::array* arr = r.table_array("boundary")) {
    for (std::size_t i = 0; i < arr->size(); ++i) {
      TableReader b(*arr->get(i)->as_table(), "mechanics.boundary[" + std::to_string(i) + "]", file);
      MechanicsBoundaryDeck mb;
      mb.on = b.string("on", {}, std::nullopt);
      mb.where = b.where("on");
      if (b.has("fix"))
        for (const std::string& axis : b.string_list("fix", {"x", "y"})) (axis == "x" ? mb.fix_x : mb.fix_y) = true;
      if (b.has("velocity")) {
        if (mb.fix_x || mb.fix_y) b.error("velocity", "prescribes both components; do not combine it with fix");
        mb.driven = true;
        mb.velocity = b.pair("velocity", kAny, std::nullopt);
      } else if (!mb.fix_x && !mb.fix_y) {
        b.error("fix", "give fix = [\"x\"], [\"y\"] or [\"x\", \"y\"], or velocity = [vx, vy]");
      }
      b.finish();
      d.mechanics_boundaries.push_back(mb);
    }
  }
  r.finish();
}

void read_cracks(toml::array& arr, Deck& d, const Origin& file) {
  for (std::size_t i = 0; i < arr.size(); ++i) {
    TableReader c(*arr.get(i)->as_table(), "cracks[" + std::to_string(i) + "]", file);
    CrackSegmentDeck seg;
    seg.where = c.where_table();
    seg.from = c.pair("from", kAny, std::nullopt);
    seg.to = c.pair("to", kAny, std::nullopt);
    if (seg.from == seg.to) c.error("to", "the crack segment has zero length");
    c.finish();
    d.cracks.push_back(seg);
  }
}

// "a_b" -> the sorted pair of material names it denotes (names may contain '_').
std::pair<std::string, std::string> material_pair(const std::string& key, const Deck& d,
                                                  const TableReader& r) {
  for (std::size_t cut = key.find('_'); cut != std::string::npos; cut = key.find('_', cut + 1)) {
    const std::string a = key.substr(0, cut), b = key.substr(cut + 1);
    if (d.materials.count(a) && d.materials.count(b)) return std::minmax(a, b);
  }
  r.error(key, "not of the form MATERIAL_MATERIAL with two materials of the deck");
}

void read_contact(TableReader r, Deck& d, const Origin& file) {
  // Default 10 E of the stiffest deformable material, the soft end of the usual 10 E to 100 E
  // (doc/physics.md "Contact and friction").
  std::optional<double> stiffest;
  for (const auto& [name, m] : d.materials)
    if (m.young && !m.rigid) stiffest = std::max(stiffest.value_or(0.0), *m.young);
  d.contact_penalty_pa = stiffest ? r.number("penalty", kPositive, 10.0 * *stiffest)
                                  : r.optional_number("penalty", kPositive);
  d.contact_damping = r.number("damping", Range{0, 1, false, false}, 0.5);
  TableReader friction(r.subtable("friction"), "contact.friction", file);
  for (const std::string& key : friction.keys())
    d.friction_deg[material_pair(key, d, friction)] = friction.number(key, Range{0, 90, false, true}, std::nullopt);
  friction.finish();
  r.finish();
}

// [substrate] (doc/deck.md "[substrate]"): only in plan view.
void read_substrate(TableReader r, Deck& d) {
  if (!d.plan_view)
    r.error(r.keys().empty() ? std::string("stiffness") : r.keys().front(),
            "a substrate holds a layer seen in plan view: set run.view = \"plan\"");
  SubstrateDeck b;
  b.stiffness_pa_m = r.optional_number("stiffness", kPositive);
  // The defaults are SubstrateDeck's own (deck.h).
  b.adhesion_pa = r.number("adhesion", kNonNegative, b.adhesion_pa);
  b.friction_angle_deg = r.number("friction_angle", Range{0, 90, false, true}, b.friction_angle_deg);
  b.gravity = r.number("gravity", kNonNegative, b.gravity);
  r.finish();
  d.substrate = b;
}

void read_solver(TableReader r, Deck& d) {
  d.moisture_safety = r.number("moisture_safety", Range{0, 1, true, false}, 0.9);
  d.max_coupling_step_s = r.number("max_coupling_step", kNonNegative, 0.0);
  d.mechanics_interval_s = r.number("mechanics_interval", kNonNegative, 0.0);
  if (d.mechanics_interval_s > d.series_interval_s)
    r.error("mechanics_interval", "is longer than run.series_interval: the solid relaxes at every row of the "
                                  "tables as well, so it would have no effect");
  d.joint_penalty = r.number("joint_penalty", kPositive, 1000.0);
  d.mechanics_safety = r.number("mechanics_safety", Range{0, 1, true, false}, 0.8);
  d.relaxation_tolerance = r.number("relaxation_tolerance", kPositive, RelaxationDefaults::tolerance);
  d.relaxation_max_steps = r.integer("relaxation_max_steps", 1, RelaxationDefaults::max_steps);
  d.relaxation_slide_after = r.integer("relaxation_slide_after", 0, RelaxationDefaults::slide_after);
  d.dynamic = r.string("integration", {"quasi_static", "dynamic"}, std::string("quasi_static")) == "dynamic";
  d.node_mass_scaling = r.boolean("node_mass_scaling", !d.dynamic);
  if (d.dynamic && d.node_mass_scaling) r.error("node_mass_scaling", "needs integration = \"quasi_static\": a dynamic run keeps the physical masses");
  if (!d.dynamic) {
    const std::string method = r.string("relaxation", kRelaxationMethodKeys,
                                        kRelaxationMethodKeys[std::size_t(RelaxationDefaults::method)]);
    d.relaxation = RelaxationMethod(std::find(kRelaxationMethodKeys.begin(), kRelaxationMethodKeys.end(), method) -
                                    kRelaxationMethodKeys.begin());
  } else if (r.has("relaxation"))
    r.error("relaxation", "needs integration = \"quasi_static\": a dynamic run does not relax");
  r.finish();
}

// [interfaces.A_B] (doc/deck.md "[interfaces.A_B]"), read after [contact] and [solver]: a
// bonded interface's friction angle is also the contact friction of its pair once it has
// debonded, and its joint penalty defaults to solver.joint_penalty.
void read_interfaces(TableReader r, Deck& d, const Origin& file) {
  for (const std::string& name : r.keys()) {
    TableReader t(r.subtable(name), "interfaces." + name, file);
    InterfaceDeck f;
    f.name = name;
    f.where = t.where_table();
    f.materials = material_pair(name, d, r);
    if (f.materials.first == f.materials.second)
      r.error(name, "names one material twice: an interface joins two different materials");
    for (const InterfaceDeck& other : d.interfaces)
      if (other.materials == f.materials) r.error(name, "the same pair of materials as interfaces." + other.name);
    f.bonded = t.boolean("bonded", false);
    if (f.bonded) {
      f.tensile_strength = t.number("tensile_strength", kPositive, std::nullopt);
      f.cohesion = t.number("cohesion", kNonNegative, std::nullopt);
      f.friction_angle_deg = t.number("friction_angle", Range{0, 90, false, true}, std::nullopt);
      f.gf_I = t.number("gf_I", kPositive, std::nullopt);
      f.gf_II = t.number("gf_II", kPositive, std::nullopt);
      f.joint_penalty = t.number("joint_penalty", kPositive, d.joint_penalty);
      if (d.friction_deg.count(f.materials))
        t.error("friction_angle", "is also the pair's contact friction once debonded: give it here only, not in "
                                  "contact.friction");
      d.friction_deg[f.materials] = f.friction_angle_deg;
    } else {
      for (const char* key : {"tensile_strength", "cohesion", "friction_angle", "gf_I", "gf_II", "joint_penalty"})
        if (t.has(key)) t.error(key, "only a bonded interface (bonded = true) has joints");
    }
    t.finish();
    d.interfaces.push_back(f);
  }
  r.finish();
}

}  // namespace

Deck read_deck(const std::string& text, const std::string& path, const std::vector<std::string>& overrides) {
  Deck d;
  d.path = path;
  toml::table& root = d.resolved;
  Origin origin{path, {}};
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
  for (const std::string& o : overrides) apply_override(root, o, origin);

  TableReader top(root, "", origin);
  read_run(TableReader(top.subtable("run"), "run", origin), d);
  read_mesh(TableReader(top.subtable("mesh"), "mesh", origin), d);
  TableReader materials(top.subtable("materials"), "materials", origin);
  for (const std::string& name : materials.keys())
    d.materials[name] = read_material(TableReader(materials.subtable(name), "materials." + name, origin), name);
  if (d.materials.empty()) materials.missing("<name>");
  materials.finish();
  read_moisture(TableReader(top.subtable("moisture"), "moisture", origin), d, origin);
  if (toml::array* cracks = top.table_array("cracks")) read_cracks(*cracks, d, origin);
  read_mechanics(TableReader(top.subtable("mechanics"), "mechanics", origin), d, origin);
  read_contact(TableReader(top.subtable("contact"), "contact", origin), d, origin);
  read_solver(TableReader(top.subtable("solver"), "solver", origin), d);
  // Read only when present, so that a deck without interfaces resolves as it always did.
  if (top.has("interfaces")) read_interfaces(TableReader(top.subtable("interfaces"), "interfaces", origin), d, origin);
  if (top.has("substrate")) read_substrate(TableReader(top.subtable("substrate"), "substrate", origin), d);
  top.finish();

  if (d.output_interval_s > d.end_time_s)
    TableReader(*root["run"].as_table(), "run", origin).error("output_interval", "is longer than run.end_time");
  // The resolved deck names the mesh it read by its absolute path, so that it runs as it is
  // from any folder (an output folder's deck.toml, or `ydry check` > deck.toml).
  if (!d.mesh_file.empty())
    root["mesh"].as_table()->insert_or_assign(
        "file", std::filesystem::absolute(d.mesh_file).lexically_normal().string());
  return d;
}

Deck load_deck(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw InputError(path + ": deck file not found");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the deck file");
  std::ostringstream text;
  text << in.rdbuf();
  return read_deck(text.str(), path, overrides);
}

std::string resolved_deck_values(const Deck& deck) {
  return toml_text(deck.resolved);
}

std::string resolved_deck_text(const Deck& deck) {
  return "# The deck as this run used it: " + deck.path + " with --set overrides and defaults applied.\n" +
         resolved_deck_values(deck);
}

}  // namespace ydry
