// summary.json's writer (doc/outputs.md "Files of a run").
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ydry {

// A flat JSON object: numbers (NaN as null), strings and booleans, in insertion order.
struct JsonObject {
  std::vector<std::pair<std::string, std::string>> fields;  // key -> encoded JSON value
  void number(const std::string& key, double v);
  void integer(const std::string& key, long long v);
  void text(const std::string& key, const std::string& v);
  void boolean(const std::string& key, bool v);
  std::string dump() const;
};

}  // namespace ydry
