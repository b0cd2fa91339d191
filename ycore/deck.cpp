// Deck parsing and validation. A TableReader reads the keys of one TOML table, checks type
// and range, inserts defaults (so the resolved deck shows every value used) and, at the end,
// rejects every key it was not asked for.
#include "ycore/deck.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>

#include "ycore/input_error.h"

namespace ydry {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// An allowed interval for a number; open or closed at each end.
struct Range {
  double lo = -kInf, hi = kInf;
  bool lo_open = false, hi_open = false;
  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string describe() const {
    std::ostringstream s;
    if (hi == kInf) {
      s << (lo_open ? "> " : ">= ") << lo;
    } else if (lo == -kInf) {
      s << (hi_open ? "< " : "<= ") << hi;
    } else {
      s << "in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
    }
    return s.str();
  }
};
const Range kAny{};
const Range kPositive{0, kInf, true, false};
const Range kNonNegative{0, kInf, false, false};
const Range kUnit{0, 1, false, false};  // a mass fraction, a safety factor

// Where the deck's nodes came from: the file, and the --set overrides that placed nodes
// (toml++ keeps no source for a node inserted by the program, so they are remembered here).
struct Origin {
  std::string file;
  std::map<const toml::node*, std::string> overrides;  // node -> "--set key=value"
};

// "FILE:LINE" for a node of the deck, the override text for one placed by --set.
std::string source_of(const toml::node* node, const Origin& origin) {
  if (node != nullptr) {
    const auto it = origin.overrides.find(node);
    if (it != origin.overrides.end()) return it->second;
    if (node->source().path) return *node->source().path + ":" + std::to_string(node->source().begin.line);
  }
  return origin.file;
}

[[noreturn]] void fail(const toml::node* node, const Origin& origin, const std::string& key,
                       const std::string& message) {
  throw InputError(source_of(node, origin) + ": " + key + ": " + message);
}

const char* type_name(const toml::node& n) {
  if (n.is_integer() || n.is_floating_point()) return "a number";
  if (n.is_string()) return "a string";
  if (n.is_boolean()) return "a boolean";
  if (n.is_array_of_tables()) return "an array of tables";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date or time";
}

class TableReader {
 public:
  TableReader(toml::table& table, std::string prefix, const Origin& origin)
      : table_(table), prefix_(std::move(prefix)), file_(origin) {}

  std::string key_path(const std::string& key) const {
    return prefix_.empty() ? key : prefix_ + "." + key;
  }
  std::string where(const std::string& key) const {
    return source_of(table_.get(key) ? table_.get(key) : &table_, file_) + ": " + key_path(key);
  }
  std::string where_table() const { return source_of(&table_, file_) + ": " + prefix_; }
  bool has(const std::string& key) const { return table_.contains(key); }
  std::vector<std::string> keys() const {
    std::vector<std::string> out;
    for (const auto& kv : table_) out.emplace_back(kv.first.str());
    return out;
  }

  std::optional<double> optional_number(const std::string& key, const Range& range) {
    const toml::node* n = take(key);
    if (!n) return std::nullopt;
    return as_number(*n, key, range);
  }
  double number(const std::string& key, const Range& range, std::optional<double> fallback) {
    if (auto v = optional_number(key, range)) return *v;
    if (!fallback) missing(key);
    table_.insert_or_assign(key, *fallback);
    return *fallback;
  }
  std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t fallback) {
    const toml::node* n = take(key);
    if (!n) {
      table_.insert_or_assign(key, fallback);
      return fallback;
    }
    if (!n->is_integer()) fail(n, file_, key_path(key), std::string("expected an integer, got ") + type_name(*n));
    const std::int64_t v = n->as_integer()->get();
    if (v < lo) fail(n, file_, key_path(key), "must be >= " + std::to_string(lo));
    return v;
  }
  bool boolean(const std::string& key, bool fallback) {
    const toml::node* n = take(key);
    if (!n) {
      table_.insert_or_assign(key, fallback);
      return fallback;
    }
    if (!n->is_boolean()) fail(n, file_, key_path(key), std::string("expected true or false, got ") + type_name(*n));
    return n->as_boolean()->get();
  }
  std::optional<std::string> optional_string(const std::string& key,
                                             const std::vector<std::string>& allowed = {}) {
    const toml::node* n = take(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(n, file_, key_path(key), std::string("expected a string, got ") + type_name(*n));
    std::string v = n->as_string()->get();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
      fail(n, file_, key_path(key), "\"" + v + "\" is not one of " + list);
    }
    return v;
  }
  std::string string(const std::string& key, const std::vector<std::string>& allowed,
                     std::optional<std::string> fallback) {
    if (auto v = optional_string(key, allowed)) return *v;
    if (!fallback) missing(key);
    table_.insert_or_assign(key, *fallback);
    return *fallback;
  }
  std::optional<std::array<double, 2>> optional_pair(const std::string& key, const Range& range) {
    const toml::node* n = take(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2) fail(n, file_, key_path(key), "expected an array of two numbers");
    return std::array<double, 2>{as_number(*a->get(0), key, range), as_number(*a->get(1), key, range)};
  }
  std::array<double, 2> pair(const std::string& key, const Range& range,
                             std::optional<std::array<double, 2>> fallback) {
    if (auto v = optional_pair(key, range)) return *v;
    if (!fallback) missing(key);
    table_.insert_or_assign(key, toml::array{(*fallback)[0], (*fallback)[1]});
    return *fallback;
  }
  std::vector<std::string> string_list(const std::string& key,
                                       const std::vector<std::string>& allowed) {
    const toml::node* n = take(key);
    if (!n) missing(key);
    const toml::array* a = n->as_array();
    if (!a || a->empty()) fail(n, file_, key_path(key), "expected a non-empty array of strings");
    std::vector<std::string> out;
    for (const toml::node& item : *a) {
      if (!item.is_string()) fail(&item, file_, key_path(key), "expected strings");
      const std::string v = item.as_string()->get();
      if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
        fail(&item, file_, key_path(key), "\"" + v + "\" is not allowed here");
      out.push_back(v);
    }
    return out;
  }
  // A sub-table; created empty (and so shown in the resolved deck) when absent.
  toml::table& subtable(const std::string& key) {
    if (!table_.contains(key)) table_.insert(key, toml::table{});
    toml::node* n = take(key);
    if (!n->is_table()) fail(n, file_, key_path(key), std::string("expected a table, got ") + type_name(*n));
    return *n->as_table();
  }
  // An array of tables, possibly absent.
  toml::array* table_array(const std::string& key) {
    toml::node* n = take(key);
    if (!n) return nullptr;
    if (!n->is_array_of_tables())
      fail(n, file_, key_path(key), std::string("expected an array of tables ([[") + key_path(key) + "]]), got " + type_name(*n));
    return n->as_array();
  }
  // Keys the schema never asked for are errors, not silently ignored.
  void finish() const {
    for (const auto& [k, v] : table_) {
      const std::string key(k.str());
      if (!read_.count(key)) fail(&v, file_, key_path(key), "unknown key");
    }
  }
  [[noreturn]] void missing(const std::string& key) const {
    fail(&table_, file_, key_path(key), "required key is missing");
  }
  [[noreturn]] void error(const std::string& key, const std::string& message) const {
    fail(table_.get(key) ? table_.get(key) : &table_, file_, key_path(key), message);
  }

 private:
  toml::node* take(const std::string& key) {
    read_.insert(key);
    return table_.get(key);
  }
  double as_number(const toml::node& n, const std::string& key, const Range& range) const {
    double v;
    if (n.is_integer()) {
      v = static_cast<double>(n.as_integer()->get());
    } else if (n.is_floating_point()) {
      v = n.as_floating_point()->get();
    } else {
      fail(&n, file_, key_path(key), std::string("expected a number, got ") + type_name(n));
    }
    if (!std::isfinite(v)) fail(&n, file_, key_path(key), "must be finite");
    if (!range.contains(v)) {
      std::ostringstream s;
      s << "value " << v << " out of range: must be " << range.describe();
      fail(&n, file_, key_path(key), s.str());
    }
    return v;
  }

  toml::table& table_;
  std::string prefix_;
  const Origin& file_;
  std::set<std::string> read_;
};

// --- overrides -----------------------------------------------------------------------------

// One path segment of --set: a key, optionally indexing an array of tables ("boundary[1]").
struct PathSegment {
  std::string key;
  long index = -1;
};

std::vector<PathSegment> split_key_path(const std::string& path, const std::string& where) {
  std::vector<PathSegment> out;
  std::istringstream in(path);
  std::string part;
  while (std::getline(in, part, '.')) {
    PathSegment seg;
    const auto bracket = part.find('[');
    seg.key = part.substr(0, bracket);
    if (bracket != std::string::npos) {
      const auto close = part.find(']', bracket);
      if (close != part.size() - 1) throw InputError(where + ": malformed index in '" + part + "'");
      try {
        seg.index = std::stol(part.substr(bracket + 1, close - bracket - 1));
      } catch (const std::exception&) {
        throw InputError(where + ": malformed index in '" + part + "'");
      }
    }
    if (seg.key.empty()) throw InputError(where + ": empty key in '" + path + "'");
    out.push_back(seg);
  }
  if (out.empty()) throw InputError(where + ": no key given");
  return out;
}

// The override's value as a TOML node; text that is not a TOML value is taken as a string,
// so `--set run.name=dry` works without shell quoting.
toml::node_view<toml::node> parse_override_value(toml::table& holder, const std::string& text,
                                                 const std::string& where) {
  try {
    holder = toml::parse("value = " + text, where);
  } catch (const toml::parse_error&) {
    holder = toml::table{};
    holder.insert("value", text);
  }
  return holder["value"];
}

void apply_override(toml::table& root, const std::string& override_text, Origin& origin) {
  const std::string where = "--set " + override_text;
  const auto eq = override_text.find('=');
  if (eq == std::string::npos) throw InputError(where + ": expected key.path=value");
  const std::vector<PathSegment> path = split_key_path(override_text.substr(0, eq), where);
  toml::table holder;
  toml::node_view<toml::node> value = parse_override_value(holder, override_text.substr(eq + 1), where);

  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const PathSegment& seg = path[i];
    toml::node* next = table->get(seg.key);
    if (seg.index >= 0) {
      if (!next || !next->is_array_of_tables())
        throw InputError(where + ": " + seg.key + " is not an array of tables in the deck");
      toml::array& arr = *next->as_array();
      if (seg.index >= static_cast<long>(arr.size()))
        throw InputError(where + ": index " + std::to_string(seg.index) + " past the " +
                         std::to_string(arr.size()) + " entries of " + seg.key);
      next = arr.get(static_cast<std::size_t>(seg.index));
    } else if (!next) {
      next = &table->insert(seg.key, toml::table{}).first->second;
      origin.overrides[next] = where;
    }
    if (!next->is_table()) throw InputError(where + ": " + seg.key + " is not a table");
    table = next->as_table();
  }
  if (path.back().index >= 0) throw InputError(where + ": the last key cannot be indexed");
  origin.overrides[&table->insert_or_assign(path.back().key, *value.node()).first->second] = where;
}

// --- sections --------------------------------------------------------------------------------

void read_run(TableReader r, Deck& d) {
  d.name = r.string("name", {}, std::nullopt);
  if (d.name.empty() || d.name.find_first_of("/\\ ") != std::string::npos)
    r.error("name", "must be a non-empty name without spaces or slashes (it names the output files)");
  d.plane_strain = r.string("plane", {"stress", "strain"}, std::string("stress")) == "strain";
  d.thickness_m = r.number("thickness", kPositive, 1.0);
  d.end_time_s = r.number("end_time", kPositive, std::nullopt);
  d.output_interval_s = r.number("output_interval", kPositive, std::nullopt);
  d.gravity = r.pair("gravity", kAny, std::array<double, 2>{0.0, -9.81});
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
    if (!std::filesystem::is_regular_file(p)) r.error("file", "mesh file '" + p.string() + "' not found");
    d.mesh_file = p.string();
  } else {
    d.mesh_generator = *generator;
    d.mesh_size = r.pair("size", kPositive, std::nullopt);
    d.element_size_m = r.number("element_size", kPositive, std::nullopt);
    d.mesh_pattern = r.string("pattern", {"right", "left", "cross"}, std::string("right"));
    d.mesh_material = r.string("material", {}, std::nullopt);
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
  m.breakable = r.boolean("breakable", true);
  m.rigid = r.boolean("rigid", false);
  if (m.has_moisture()) {
    if (!m.density) r.missing("density");
    if (!m.initial_moisture) r.missing("initial_moisture");
  }
  r.finish();
  return m;
}

MoistureBoundaryDeck read_moisture_boundary(TableReader r) {
  MoistureBoundaryDeck b;
  b.on = r.string("on", {}, std::nullopt);
  b.where = r.where("on");
  const std::string type = r.string("type", {"flux", "fixed", "exchange"}, std::nullopt);
  // Keys that belong to another type are errors: a user who wrote them expects an effect.
  const auto reject = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (r.has(k)) r.error(k, std::string("not used by a boundary of type \"") + type + "\"");
  };
  if (type == "flux") {
    b.type = MoistureBcType::flux;
    b.rate_kg_m2_s = r.number("rate", kAny, std::nullopt);
    if (auto res = r.optional_number("residual", kNonNegative)) {
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
          TableReader(*arr->get(i)->as_table(), "moisture.boundary[" + std::to_string(i) + "]", file)));
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
      for (const std::string& axis : b.string_list("fix", {"x", "y"})) (axis == "x" ? mb.fix_x : mb.fix_y) = true;
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
  d.contact_penalty_pa = r.optional_number("penalty", kPositive);
  TableReader friction(r.subtable("friction"), "contact.friction", file);
  for (const std::string& key : friction.keys())
    d.friction_deg[material_pair(key, d, friction)] = friction.number(key, Range{0, 90, false, true}, std::nullopt);
  friction.finish();
  r.finish();
}

void read_solver(TableReader r, Deck& d) {
  d.moisture_safety = r.number("moisture_safety", Range{0, 1, true, false}, 0.9);
  r.finish();
}

}  // namespace

Deck load_deck(const std::string& path, const std::vector<std::string>& overrides) {
  Deck d;
  d.path = path;
  if (!std::filesystem::is_regular_file(path)) throw InputError(path + ": deck file not found");
  toml::table& root = d.resolved;
  Origin origin{path, {}};
  try {
    root = toml::parse_file(path);
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
  top.finish();

  if (d.output_interval_s > d.end_time_s)
    TableReader(*root["run"].as_table(), "run", origin).error("output_interval", "is longer than run.end_time");
  return d;
}

std::string resolved_deck_text(const Deck& deck) {
  std::ostringstream out;
  out << "# The deck as this run used it: " << deck.path
      << " with --set overrides and defaults applied.\n"
      << toml::toml_formatter(deck.resolved) << "\n";
  return out.str();
}

}  // namespace ydry
