#include "ycore/input/input_error.h"

namespace ydry {

std::string input_location(const std::string& file, long line, const std::string& key) {
  const std::string where = line > 0 ? file + ":" + std::to_string(line) : file;
  return where + ": " + key + ": ";
}

}  // namespace ydry
