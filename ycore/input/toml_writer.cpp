#include "ycore/input/toml_writer.h"

#include <algorithm>
#include <sstream>
#include <string_view>

namespace ydry {
namespace {

std::string scalar_text(const toml::node& value, toml::format_flags flags) {
  std::ostringstream out;
  out << toml::toml_formatter(value, flags);
  return out.str();
}

// A bare key, or a quoted one ("a b", "é") as a basic string on one line.
std::string key_text(std::string_view key) {
  const bool bare = !key.empty() && key.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                          "0123456789_-") == std::string_view::npos;
  return bare ? std::string(key) : scalar_text(toml::value<std::string>(std::string(key)), toml::format_flags::none);
}

std::string inline_text(const toml::node& node) {
  if (const toml::array* array = node.as_array()) {
    if (array->empty()) return "[]";
    std::string out = "[ ";
    for (std::size_t i = 0; i < array->size(); ++i) out += (i > 0 ? ", " : "") + inline_text(*array->get(i));
    return out + " ]";
  }
  if (const toml::table* table = node.as_table()) {
    if (table->empty()) return "{}";
    std::string out = "{ ";
    for (const auto& [key, value] : *table)
      out += (out.size() > 2 ? ", " : "") + key_text(key.str()) + " = " + inline_text(value);
    return out + " }";
  }
  return scalar_text(node, toml::toml_formatter::default_flags);
}

// Written under a header of its own: a table not written inline in the deck, or an array of
// such tables (as toml++, the first one decides).
bool is_section(const toml::node& node) {
  if (const toml::table* table = node.as_table()) return !table->is_inline();
  const toml::array* array = node.as_array();
  return array && !array->empty() && array->is_array_of_tables() && !array->get(0)->as_table()->is_inline();
}

void write_table(std::string& out, const toml::table& table, const std::string& path) {
  const auto header = [&](const std::string& text) { out += (out.empty() ? "" : "\n") + text + "\n"; };
  const auto section_path = [&](const toml::key& key) {
    return path.empty() ? key_text(key.str()) : path + "." + key_text(key.str());
  };
  for (const auto& [key, value] : table)
    if (!is_section(value)) out += key_text(key.str()) + " = " + inline_text(value) + "\n";
  for (const auto& [key, value] : table) {
    const toml::table* sub = value.as_table();
    if (!sub || !is_section(value)) continue;
    // A table that holds only sections needs no header: theirs name it.
    const bool only_sections = !sub->empty() && std::all_of(sub->begin(), sub->end(), [](const auto& kv) {
      return is_section(kv.second);
    });
    if (!only_sections) header("[" + section_path(key) + "]");
    write_table(out, *sub, section_path(key));
  }
  for (const auto& [key, value] : table) {
    if (!value.is_array() || !is_section(value)) continue;
    for (const toml::node& element : *value.as_array()) {
      header("[[" + section_path(key) + "]]");
      write_table(out, *element.as_table(), section_path(key));
    }
  }
}

}  // namespace

std::string toml_text(const toml::table& table) {
  std::string out;
  write_table(out, table, "");
  return out;
}

}  // namespace ydry
