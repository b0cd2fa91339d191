// libFuzzer target: the deck reader as `ydry check` uses it (read_deck: TOML, --set overrides,
// schema), then the resolved deck it prints. The input is the deck's text, optionally
// followed by a line "--set" and one override "key.path=value" per line.
//
// The deck is read as if it were tests/data/fuzzed.toml, so the meshes the seeds name
// (two_materials.msh, notched_layer.msh) exist. read_deck only stats a mesh file and accepts
// a regular file alone, so no fuzzed path (/dev/zero, a FIFO, a directory) is ever opened.
// An InputError is a correct answer to any input; a crash, a sanitizer report, any other
// exception, or a resolved deck that does not read back to itself is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "ycore/input/deck.h"
#include "ycore/input/input_error.h"

namespace {

const char* const kDeckPath = YDRY_SOURCE_DIR "/tests/data/fuzzed.toml";

struct FuzzedDeck {
  std::string text;
  std::vector<std::string> overrides;
};

FuzzedDeck split_input(const std::string& input) {
  const std::string separator = "\n--set\n";
  const std::size_t cut = input.find(separator);
  FuzzedDeck out{input.substr(0, cut), {}};
  if (cut == std::string::npos) return out;
  std::istringstream lines(input.substr(cut + separator.size()));
  for (std::string line; std::getline(lines, line);) out.overrides.push_back(line);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const FuzzedDeck input = split_input(std::string(reinterpret_cast<const char*>(data), size));
  std::string resolved;
  try {
    resolved = ydry::resolved_deck_text(ydry::read_deck(input.text, kDeckPath, input.overrides));
  } catch (const ydry::InputError&) {
    return 0;
  }
  // The resolved deck (deck.toml of a run, `ydry check`'s output) is a deck that reads the same.
  const std::string again = ydry::resolved_deck_text(ydry::read_deck(resolved, kDeckPath, {}));
  if (again != resolved) {
    std::fprintf(stderr, "resolved deck:\n%s\nread back and resolved again:\n%s\n", resolved.c_str(), again.c_str());
    std::abort();
  }
  return 0;
}
