// What the fuzz targets (tests/fuzz, `make fuzz`) found, each fed here as the input that found
// it, reduced, to the shipped code: a deck or mesh that is not right is an InputError naming
// its place (exit 2), and one that is right reads as it should.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_support.h"
#include "ycore/input/deck.h"
#include "ycore/input/input_error.h"
#include "ycore/state/mesh_gmsh.h"

using ydry::InputError;

namespace {

const std::string kStripPath = YDRY_SOURCE_DIR "/verification/strip1d/strip1d.toml";

std::string strip_text() { return ydry_test::read_text(kStripPath); }

// The message of the InputError read_deck throws for `text`; fails the test if none.
std::string deck_error(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    ydry::read_deck(text, kStripPath, overrides);
  } catch (const InputError& error) {
    return error.what();
  }
  FAIL("read_deck accepted the deck");
  return "";
}

}  // namespace

// toml++ 3.3's formatter chooses one line or several for an array from static_cast<size_t> of
// log10(|x|), undefined below 0.1 (size = [0.1, 0.01]), and negates INT64_MIN: the resolved
// deck is written by toml_writer.cpp.
TEST_CASE("fuzz: numbers below 0.1 and INT64_MIN in arrays are written to the resolved deck and read back exactly", "[fuzz]") {
  const ydry::Deck deck = ydry::read_deck(strip_text(), kStripPath, {"run.gravity=[-9223372036854775808, 1e-300]"});
  const std::string resolved = ydry::resolved_deck_text(deck);
  CHECK_THAT(resolved, Catch::Contains("size = [ 0.10000000000000001, 0.01 ]"));
  CHECK_THAT(resolved, Catch::Contains("gravity = [ -9223372036854775808, 1e-300 ]"));
  const ydry::Deck again = ydry::read_deck(resolved, kStripPath, {});
  CHECK(again.gravity == std::array<double, 2>{double(std::numeric_limits<std::int64_t>::min()), 1e-300});
  CHECK(again.mesh_size == deck.mesh_size);
  CHECK(ydry::resolved_deck_text(again) == resolved);
}

// toml++ 3.3 breaks preconditions of its own parser on these (tests/fuzz/toml_as_shipped.h);
// Debian's build goes on to report them as parse errors.
TEST_CASE("fuzz: a table header that starts with no key character, and a '}' in an array, are parse errors", "[fuzz]") {
  for (const std::string& header : {std::string("[!]"), std::string("[\0]", 3), std::string("[[=]]")}) {
    INFO(header);
    const std::string message = deck_error(strip_text() + header + "\n");
    CHECK_THAT(message, Catch::StartsWith(kStripPath + ":27: "));
    CHECK_THAT(message, Catch::Contains("expected bare key starting character"));
  }
  CHECK_THAT(deck_error(strip_text() + "[solver]\nx = [}\n"),
             Catch::StartsWith(kStripPath + ":28: ") && Catch::Contains("could not determine value type"));
  // As a --set value it is not TOML, so a string, and not the array the key needs.
  CHECK_THAT(deck_error(strip_text(), {"run.gravity=[}"}), Catch::Contains("run.gravity: expected an array of two numbers"));
}

// toml++ 3.3 reaches TOML_UNREACHABLE when it asks whether most non-ASCII characters are
// whitespace (tests/fuzz/toml_as_shipped.h); Debian's build answers no, as it should.
TEST_CASE("fuzz: a non-ASCII character after a value is a parse error, and one in a string is read", "[fuzz]") {
  const std::string degree = "\xc2\xb0";
  CHECK_THAT(deck_error(strip_text() + "[solver]\nmoisture_safety = 0.5 " + degree + "\n"),
             Catch::StartsWith(kStripPath + ":28: ") && Catch::Contains("expected a comment or whitespace"));
  CHECK_THAT(deck_error(strip_text() + "[solver]\nrelaxation_max_steps = 20" + degree + "\n"),
             Catch::StartsWith(kStripPath + ":28: ") && Catch::Contains("expected digit"));
  // A continued multi-line string whose next line starts with a non-ASCII character.
  std::string text = strip_text();
  text.replace(text.find("name = \"strip1d\""), 16, "name = \"\"\"\\\n  strip" + degree + "\"\"\"");
  CHECK(ydry::read_deck(text, kStripPath, {}).name == "strip" + degree);
  const ydry_test::TempDir dir;
  ydry_test::write_text(dir.file("deck.toml"), strip_text() + "[solver]\nmoisture_safety = 0.5 " + degree + "\n");
  const auto run = ydry_test::run_ydry("check " + dir.file("deck.toml"));
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("deck.toml:28: "));
}

// std::filesystem::is_regular_file without an error_code throws filesystem_error on a name too
// long to stat, which would be an unexpected failure (exit 1), not an input error.
TEST_CASE("fuzz: a mesh file name too long to stat is not found", "[fuzz]") {
  std::string text = strip_text();
  text.replace(text.find("generator = \"rectangle\""), 23, "file = \"" + std::string(300, 'a') + ".msh\"");
  CHECK_THAT(deck_error(text), Catch::StartsWith(kStripPath + ":12: mesh.file: mesh file") && Catch::Contains("not found"));
}

// The Gmsh fuzz target's check of the mesh it gets back: coordinates near 1e300 make an
// infinite or NaN area, which must not pass as counter-clockwise.
TEST_CASE("fuzz: a triangle whose area overflows a double is refused", "[fuzz]") {
  std::string text = ydry_test::kOneTriangleMsh;
  text.replace(text.find("\n1 0 0\n"), 7, "\n1e300 0 0\n");
  text.replace(text.find("\n0 1 0\n"), 7, "\n0 1e300 0\n");
  std::istringstream in(text);
  ydry::MeshInput mesh = ydry::read_gmsh(in, "big.msh");
  CHECK_THROWS_WITH(ydry::orient_counter_clockwise(mesh), Catch::Contains("too large for a double"));
}

// A --set is bytes from the command line: a material named by invalid UTF-8 (0xDC 0xDC ...)
// would be written to the resolved deck as "\u00DC\u00DC...", which reads back as another name.
TEST_CASE("fuzz: a --set that is not UTF-8 is refused", "[fuzz]") {
  for (const std::string& set : {std::string("materials.\xdc\xdcsm.density=1500"), std::string("run.name=dry\xff"),
                                 std::string("run.name=\xc0\xae"), std::string("run.name=\xed\xa0\x80"),
                                 std::string("run.name=\xf4\x90\x80\x80"), std::string("run.name=\xe2\x82")}) {
    INFO(set);
    CHECK_THAT(deck_error(strip_text(), {set}), Catch::StartsWith("--set " + set + ": not UTF-8 text"));
  }
  // Well-formed UTF-8 of 2, 3 and 4 bytes, the highest code point among them, is taken.
  const std::string name = "s\xc3\xa9\xe2\x82\xac\xf4\x8f\xbf\xbf";
  CHECK(ydry::read_deck(strip_text(), kStripPath, {"run.name=" + name}).name == name);
}
