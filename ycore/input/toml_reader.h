// Reading a TOML deck against a schema: typed, range-checked keys with defaults, unknown
// keys rejected, every error naming the file, line and key (or the --set that placed the
// value). The deck schema itself is in deck.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace ydry {

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

// Where the deck's nodes came from: the file, and the --set overrides that placed nodes
// (toml++ keeps no source for a node inserted by the program, so they are remembered here).
struct Origin {
  std::string file;
  std::map<const toml::node*, std::string> overrides;  // node -> "--set key=value"
};

// "FILE:LINE" for a node of the deck, the override text for one placed by --set.
std::string source_of(const toml::node* node, const Origin& origin);

[[noreturn]] void fail(const toml::node* node, const Origin& origin, const std::string& key,
                       const std::string& message);

// "a number", "a string", ... for messages.
const char* type_name(const toml::node& n);

// Applies one --set override ("key.path=value", a TOML value; text that is not TOML is taken
// as a string) to the deck's root table, remembering the placed nodes in origin.
void apply_override(toml::table& root, const std::string& override_text, Origin& origin);

class TableReader {
 public:
  TableReader(toml::table& table, std::string prefix, const Origin& origin)
      : table_(table), prefix_(std::move(prefix)), origin_(origin) {}

  std::string key_path(const std::string& key) const {
    return prefix_.empty() ? key : prefix_ + "." + key;
  }
  std::string where(const std::string& key) const {
    return source_of(table_.get(key) ? table_.get(key) : &table_, origin_) + ": " + key_path(key);
  }
  std::string where_table() const { return source_of(&table_, origin_) + ": " + prefix_; }
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
    if (!n->is_integer()) fail(n, origin_, key_path(key), std::string("expected an integer, got ") + type_name(*n));
    const std::int64_t v = n->as_integer()->get();
    if (v < lo) fail(n, origin_, key_path(key), "must be >= " + std::to_string(lo));
    return v;
  }
  bool boolean(const std::string& key, bool fallback) {
    const toml::node* n = take(key);
    if (!n) {
      table_.insert_or_assign(key, fallback);
      return fallback;
    }
    if (!n->is_boolean()) fail(n, origin_, key_path(key), std::string("expected true or false, got ") + type_name(*n));
    return n->as_boolean()->get();
  }
  std::optional<std::string> optional_string(const std::string& key,
                                             const std::vector<std::string>& allowed = {}) {
    const toml::node* n = take(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(n, origin_, key_path(key), std::string("expected a string, got ") + type_name(*n));
    std::string v = n->as_string()->get();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
      fail(n, origin_, key_path(key), "\"" + v + "\" is not one of " + list);
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
    if (!a || a->size() != 2) fail(n, origin_, key_path(key), "expected an array of two numbers");
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
    if (!a || a->empty()) fail(n, origin_, key_path(key), "expected a non-empty array of strings");
    std::vector<std::string> out;
    for (const toml::node& item : *a) {
      if (!item.is_string()) fail(&item, origin_, key_path(key), "expected strings");
      const std::string v = item.as_string()->get();
      if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
        fail(&item, origin_, key_path(key), "\"" + v + "\" is not allowed here");
      out.push_back(v);
    }
    return out;
  }
  // A sub-table; created empty (and so shown in the resolved deck) when absent.
  toml::table& subtable(const std::string& key) {
    if (!table_.contains(key)) table_.insert(key, toml::table{});
    toml::node* n = take(key);
    if (!n->is_table()) fail(n, origin_, key_path(key), std::string("expected a table, got ") + type_name(*n));
    return *n->as_table();
  }
  // An array of tables, possibly absent or empty (`--set KEY=[]` removes a deck's entries).
  toml::array* table_array(const std::string& key) {
    toml::node* n = take(key);
    if (!n) return nullptr;
    if (!n->is_array_of_tables() && !(n->is_array() && n->as_array()->empty()))
      fail(n, origin_, key_path(key), std::string("expected an array of tables ([[") + key_path(key) + "]]), got " + type_name(*n));
    return n->as_array();
  }
  // Keys the schema never asked for are errors, not silently ignored.
  void finish() const {
    for (const auto& [k, v] : table_) {
      const std::string key(k.str());
      if (!read_.count(key)) fail(&v, origin_, key_path(key), "unknown key");
    }
  }
  [[noreturn]] void missing(const std::string& key) const {
    fail(&table_, origin_, key_path(key), "required key is missing");
  }
  [[noreturn]] void error(const std::string& key, const std::string& message) const {
    fail(table_.get(key) ? table_.get(key) : &table_, origin_, key_path(key), message);
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
      fail(&n, origin_, key_path(key), std::string("expected a number, got ") + type_name(n));
    }
    if (!std::isfinite(v)) fail(&n, origin_, key_path(key), "must be finite");
    if (!range.contains(v)) {
      std::ostringstream s;
      s << "value " << v << " out of range: must be " << range.describe();
      fail(&n, origin_, key_path(key), s.str());
    }
    return v;
  }

  toml::table& table_;
  std::string prefix_;
  const Origin& origin_;
  std::set<std::string> read_;
};

}  // namespace ydry
