#include "ycore/input/toml_reader.h"

#include <charconv>

#include "ycore/input/input_error.h"

namespace ydry {

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


namespace {

// One path segment of --set: a key, optionally indexing an array of tables ("boundary[1]").
struct PathSegment {
  std::string key;
  long index = -1;  // none
};

// "a.b[1].c" -> a, b[1], c. An empty key ("a..b", "a.b."), or an index that is not a plain
// decimal number ("b[-1]", "b[0x1]", "b[ 1]"), is an error rather than read as something else.
std::vector<PathSegment> split_key_path(const std::string& path, const std::string& where) {
  std::vector<PathSegment> out;
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot - start);  // to the end when there is no dot
    PathSegment seg;
    const auto bracket = part.find('[');
    seg.key = part.substr(0, bracket);
    if (seg.key.empty()) throw InputError(where + ": empty key in '" + path + "'");
    if (bracket != std::string::npos) {
      const std::string digits = part.substr(bracket + 1, part.size() - bracket - 2);
      const char* const end = digits.data() + digits.size();
      const bool plain = part.back() == ']' && !digits.empty() &&
                         digits.find_first_not_of("0123456789") == std::string::npos;
      const auto parsed = std::from_chars(digits.data(), end, seg.index);
      if (!plain || parsed.ec != std::errc() || parsed.ptr != end)
        throw InputError(where + ": malformed index in '" + part + "'");
    }
    out.push_back(seg);
    if (dot == std::string::npos) return out;
    start = dot + 1;
  }
}

// Whether `text` is well-formed UTF-8 (Unicode table 3-7: no overlong forms, surrogates or
// code points past U+10FFFF), as every TOML document is.
bool is_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = [&](std::size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
    const unsigned lead = byte(0);
    unsigned length = 1, lo = 0x80, hi = 0xBF;  // bytes of the character; range of its second
    if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
      lo = lead == 0xE0 ? 0xA0 : lo;
      hi = lead == 0xED ? 0x9F : hi;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
      lo = lead == 0xF0 ? 0x90 : lo;
      hi = lead == 0xF4 ? 0x8F : hi;
    } else if (lead >= 0x80) {
      return false;
    }
    for (unsigned k = 1; k < length; ++k)
      if (byte(k) < (k == 1 ? lo : 0x80) || byte(k) > (k == 1 ? hi : 0xBF)) return false;
    i += length;
  }
  return true;
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

}  // namespace

void apply_override(toml::table& root, const std::string& override_text, Origin& origin) {
  const std::string where = "--set " + override_text;
  // The command line is bytes: a key or bare string that is not UTF-8 would make a resolved
  // deck (deck.toml) that is not TOML, or reads back as other names.
  if (!is_utf8(override_text)) throw InputError(where + ": not UTF-8 text, as a deck must be");
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

}  // namespace ydry
