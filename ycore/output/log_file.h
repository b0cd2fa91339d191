// log.txt, and its lines on stderr.
#pragma once

#include <fstream>
#include <string>

namespace ydry {

// log.txt and stderr. Messages go to both (stderr unless quiet); warnings always reach stderr.
struct Log {
  std::ofstream file;
  bool quiet = false;
  bool stderr_is_terminal = false;
  void open(const std::string& path, bool quiet_console, bool append = false);
  void info(const std::string& message);
  void warning(const std::string& message);
};

}  // namespace ydry
