#include "ycore/output/log_file.h"

#include <unistd.h>

#include <iostream>

namespace ydry {

void Log::open(const std::string& path, bool quiet_console, bool append) {
  file.open(path, append ? std::ios::app : std::ios::trunc);
  quiet = quiet_console;
  stderr_is_terminal = isatty(STDERR_FILENO);
}

void Log::info(const std::string& message) {
  file << message << "\n" << std::flush;
  if (!quiet) std::cerr << (stderr_is_terminal ? "\r\033[K" : "") << message << "\n";
}

void Log::warning(const std::string& message) {
  file << "warning: " << message << "\n" << std::flush;
  std::cerr << (stderr_is_terminal ? "\r\033[K" : "") << "ydry: warning: " << message << "\n";
}

}  // namespace ydry
