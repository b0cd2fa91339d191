#include "ycore/output/json_object.h"

#include <cmath>
#include <cstdio>

#include "ycore/output/output_files.h"

namespace ydry {
namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

void JsonObject::number(const std::string& key, double v) {
  fields.emplace_back(key, std::isfinite(v) ? format_double(v) : "null");
}
void JsonObject::integer(const std::string& key, long long v) { fields.emplace_back(key, std::to_string(v)); }
void JsonObject::text(const std::string& key, const std::string& v) { fields.emplace_back(key, json_string(v)); }
void JsonObject::boolean(const std::string& key, bool v) { fields.emplace_back(key, v ? "true" : "false"); }

std::string JsonObject::dump() const {
  std::string out = "{\n";
  for (std::size_t i = 0; i < fields.size(); ++i)
    out += "  " + json_string(fields[i].first) + ": " + fields[i].second + (i + 1 < fields.size() ? ",\n" : "\n");
  return out + "}\n";
}

}  // namespace ydry
