// Bad input (deck, mesh, command line): caught in main, reported, exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace ydry {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "FILE:LINE: KEY: message", the form every input error takes (line 0 is left out).
std::string input_location(const std::string& file, long line, const std::string& key);

}  // namespace ydry
