// Deck errors: every class exits 2 from the real executable and names the file, line and
// key. Also --set overrides, the resolved deck, and the output-folder guard.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <toml++/toml.h>

#include "tests/test_support.h"
#include "ycore/driver/setup.h"

using ydry_test::run_ydry;

namespace {

const char* const kGoodDeck = R"([run]
name = "t"
end_time = 100.0
output_interval = 50.0
mechanics = false

[mesh]
generator = "rectangle"
size = [0.01, 0.005]
element_size = 0.0025
material = "soil"

[materials.soil]
density = 1333.0
moisture_conductivity = 1.0e-6
initial_moisture = 0.2

[[moisture.boundary]]
on = "top"
type = "flux"
rate = -1.0e-5
)";

// Runs ydry on kGoodDeck with `find` replaced by `replace` (and extra arguments).
ydry_test::CommandResult run_edited(const ydry_test::TempDir& dir, const std::string& find,
                                    const std::string& replace, const std::string& extra = "") {
  std::string text = kGoodDeck;
  if (!find.empty()) {
    const auto at = text.find(find);
    REQUIRE(at != std::string::npos);
    text.replace(at, find.size(), replace);
  }
  const std::string deck = dir.file("deck.toml");
  ydry_test::write_text(deck, text);
  return run_ydry(deck + " -o " + dir.file("out") + " --quiet --force " + extra);
}

}  // namespace

TEST_CASE("a good deck runs and writes every output", "[deck]") {
  ydry_test::TempDir dir;
  const auto r = run_edited(dir, "", "");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* f : {"t.pvd", "series.csv", "summary.json", "deck.toml", "log.txt",
                        "frames/t_000000.vtu", "frames/t_000002.vtu"})
    CHECK(std::filesystem::exists(dir.file("out/") + f));
  CHECK(ydry_test::read_text(dir.file("out/summary.json")).find("\"completed\": true") != std::string::npos);
  CHECK(r.output.find("warning") == std::string::npos);
}

namespace {

// summary.json's "wall_NAME_s" entries, by NAME, and its "wall_s" under "".
std::map<std::string, double> wall_entries(const std::string& summary) {
  static const std::regex entry(R"re("wall(?:_([a-z]+))?_s": ([^,\n]+))re");
  std::map<std::string, double> wall;
  for (auto m = std::sregex_iterator(summary.begin(), summary.end(), entry); m != std::sregex_iterator(); ++m)
    wall[(*m)[1].str()] = std::stod((*m)[2].str());
  return wall;
}

// The split of the wall time a run writes: every stage of StageSeconds and "other", none
// negative, summing to wall_s (to the 17 digits summary.json prints); the log's last lines
// carry it too.
std::map<std::string, double> checked_wall_split(const ydry_test::TempDir& dir, const std::string& run) {
  std::map<std::string, double> wall = wall_entries(ydry_test::read_text(dir.file(run + "/summary.json")));
  REQUIRE(wall.size() == 9);
  double sum = 0.0;
  for (const char* stage : {"moisture", "elements", "joints", "contact", "gather", "solve", "cracking", "other"}) {
    INFO(stage);
    REQUIRE(wall.count(stage) == 1);
    CHECK(wall[stage] >= 0.0);
    sum += wall[stage];
  }
  CHECK(sum == Approx(wall[""]).epsilon(1e-12));
  CHECK(ydry_test::read_text(dir.file(run + "/log.txt")).find("wall time by stage: moisture ") != std::string::npos);
  return wall;
}

}  // namespace

TEST_CASE("a run splits its wall time by stage: the stages sum to wall_s, and a run books time only to the stages it has",
          "[deck]") {
  ydry_test::TempDir dir;
  REQUIRE(run_edited(dir, "", "").exit_code == 0);  // moisture only
  std::map<std::string, double> wall = checked_wall_split(dir, "out");
  CHECK(wall["moisture"] > 0.0);
  for (const char* stage : {"elements", "joints", "contact", "gather", "solve", "cracking"}) {
    INFO(stage);
    CHECK(wall[stage] == 0.0);
  }
  // The cracking strip of the sweep tests to its first two cracks (3 s of CPU), relaxed by
  // Newton: every stage of a mechanics run has booked time (a stage whose lap were lost would
  // read 0).
  const ydry_test::CommandResult cracking = run_ydry(std::string(YDRY_SOURCE_DIR "/tests/data/sweep_strip.toml") + " -o " +
                                                      dir.file("strip") + " --quiet --set run.end_time=1000");
  REQUIRE(cracking.exit_code == 0);
  wall = checked_wall_split(dir, "strip");
  for (const char* stage : {"moisture", "elements", "joints", "contact", "gather", "solve", "cracking"}) {
    INFO(stage);
    CHECK(wall[stage] > 0.0);
  }
}

TEST_CASE("a material the mesh does not use is reported, not silently ignored", "[deck]") {
  ydry_test::TempDir dir;
  const auto r = run_edited(dir, "[[moisture.boundary]]", "[materials.clay]\ndensity = 1500.0\n\n[[moisture.boundary]]");
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("warning: [materials.clay] is not used by any triangle") != std::string::npos);
  CHECK(ydry_test::read_text(dir.file("out/log.txt")).find("[materials.clay] is not used") != std::string::npos);
}

TEST_CASE("each class of deck error exits 2 naming file, line and key", "[deck]") {
  struct Case {
    const char* what;
    std::string find, replace, extra, expected;
  };
  const std::vector<Case> cases = {
      {"unknown key", "initial_moisture = 0.2", "initial_moisture = 0.2\nporosity = 0.4", "",
       "deck.toml:17: materials.soil.porosity: unknown key"},
      {"wrong type", "end_time = 100.0", "end_time = \"long\"", "", "deck.toml:3: run.end_time: expected a number"},
      {"out of range", "density = 1333.0", "density = -1.0", "", "deck.toml:14: materials.soil.density: value -1 out of range"},
      {"missing required key", "end_time = 100.0\n", "", "", "run.end_time: required key is missing"},
      {"missing mesh file", "generator = \"rectangle\"", "file = \"nowhere.msh\"", "",
       "deck.toml:8: mesh.file: mesh file"},
      {"unknown boundary", "on = \"top\"", "on = \"roof\"", "",
       "deck.toml:19: moisture.boundary[0].on: the mesh has no boundary named \"roof\""},
      {"bad enum", "type = \"flux\"", "type = \"suction\"", "", "deck.toml:20: moisture.boundary[0].type: \"suction\" is not one of"},
      {"key of another boundary type", "rate = -1.0e-5", "rate = -1.0e-5\nvalue = 0.1", "",
       "deck.toml:22: moisture.boundary[0].value: not used by a boundary of type \"flux\""},
      {"residual on an inflow", "rate = -1.0e-5", "rate = 1.0e-5\nresidual = 0.1", "",
       "deck.toml:22: moisture.boundary[0].residual: only an outflow"},
      {"TOML syntax", "density = 1333.0", "density = = 1", "", "deck.toml:14:"},
      {"--set wrong type", "", "", "--set materials.soil.density=true",
       "--set materials.soil.density=true: materials.soil.density: expected a number"},
      {"--set unknown key", "", "", "--set run.speed=2", "--set run.speed=2: run.speed: unknown key"},
      {"--set out of range", "", "", "--set materials.soil.poisson=0.5",
       "materials.soil.poisson: value 0.5 out of range: must be in (-1, 0.5)"},
      {"key the solid needs", "mechanics = false", "mechanics = true", "", "deck.toml:13: materials.soil.young: missing"},
      {"velocity with fix", "", "", "--set 'mechanics.boundary=[{on=\"left\",fix=[\"x\"],velocity=[1.0,0.0]}]'",
       "mechanics.boundary[0].velocity: prescribes both components"},
      {"material missing", "material = \"soil\"", "material = \"clay\"", "", "mesh: the mesh has material \"clay\""},
      {"negative heterogeneity", "initial_moisture = 0.2", "initial_moisture = 0.2\nstrength_heterogeneity = -0.1", "",
       "deck.toml:17: materials.soil.strength_heterogeneity: value -0.1 out of range: must be in [0, 1]"},
      {"heterogeneity above 1", "", "", "--set materials.soil.strength_heterogeneity=1.5",
       "materials.soil.strength_heterogeneity: value 1.5 out of range: must be in [0, 1]"},
      {"non-finite heterogeneity", "initial_moisture = 0.2", "initial_moisture = 0.2\nstrength_heterogeneity = nan", "",
       "deck.toml:17: materials.soil.strength_heterogeneity: must be finite"},
      {"infinite heterogeneity", "", "", "--set materials.soil.strength_heterogeneity=inf",
       "materials.soil.strength_heterogeneity: must be finite"},
      {"heterogeneity on joints that never fail", "initial_moisture = 0.2",
       "initial_moisture = 0.2\nbreakable = false\nstrength_heterogeneity = 0.2", "",
       "deck.toml:18: materials.soil.strength_heterogeneity: the joints of a material with breakable = false never fail"},
      {"heterogeneity on a rigid material", "initial_moisture = 0.2",
       "initial_moisture = 0.2\nrigid = true\nstrength_heterogeneity = 0.2", "",
       "deck.toml:18: materials.soil.strength_heterogeneity: a rigid material has no joints to weaken"},
      {"mass scaling in a dynamic run", "", "",
       "--set solver.integration=dynamic --set solver.node_mass_scaling=true",
       "solver.node_mass_scaling: needs integration = \"quasi_static\""},
      {"a relaxation method in a dynamic run", "", "",
       "--set solver.integration=dynamic --set solver.node_mass_scaling=false --set solver.relaxation=fire",
       "solver.relaxation: needs integration = \"quasi_static\""},
      {"an unknown relaxation method", "", "", "--set solver.relaxation=cg",
       "solver.relaxation: \"cg\" is not one of \"viscous\", \"fire\""},
      {"relaxations rarer than the rows of the tables", "", "", "--set solver.mechanics_interval=60",
       "solver.mechanics_interval: is longer than run.series_interval"},
      {"a substrate without plan view", "rate = -1.0e-5", "rate = -1.0e-5\n[substrate]\nstiffness = 1.0e6", "",
       "deck.toml:23: substrate.stiffness: a substrate holds a layer seen in plan view: set run.view = \"plan\""},
      {"a negative substrate stiffness", "name = \"t\"", "name = \"t\"\nview = \"plan\"",
       "--set substrate.stiffness=-1.0", "substrate.stiffness: value -1 out of range"},
      {"an unknown plan-view key", "name = \"t\"", "name = \"t\"\nview = \"plan\"", "--set substrate.shear=1.0",
       "substrate.shear: unknown key"},
      {"plan view in plane strain", "name = \"t\"", "name = \"t\"\nview = \"plan\"\nplane = \"strain\"", "",
       "deck.toml:4: run.plane: a layer seen in plan view is in plane stress"},
      {"in-plane gravity in plan view", "name = \"t\"", "name = \"t\"\nview = \"plan\"\ngravity = [0.0, -9.81]", "",
       "deck.toml:4: run.gravity: in plan view gravity acts through the layer's thickness"},
      {"an unknown view", "name = \"t\"", "name = \"t\"\nview = \"oblique\"", "",
       "deck.toml:3: run.view: \"oblique\" is not one of"},
      {"drying through the face of a vertical section", "on = \"top\"", "on = \"face\"", "",
       "deck.toml:19: moisture.boundary[0].on: a vertical section has no face to dry through"},
      {"a fixed moisture on the face", "name = \"t\"", "name = \"t\"\nview = \"plan\"",
       "--set 'moisture.boundary=[{on=\"face\",type=\"fixed\",value=0.1}]'",
       "moisture.boundary[0].type: a fixed moisture on the face would hold the whole layer at it"},
  };
  for (const Case& c : cases) {
    ydry_test::TempDir dir;
    const auto r = run_edited(dir, c.find, c.replace, c.extra);
    INFO(c.what << ":\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(c.expected) != std::string::npos);
  }
}

TEST_CASE("overrides given with --set reach the run and the resolved deck, defaults included", "[deck]") {
  ydry_test::TempDir dir;
  const auto r = run_edited(dir, "", "", "--set mesh.pattern=\\\"cross\\\" --set 'moisture.boundary[0].rate=-2e-5'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string resolved = ydry_test::read_text(dir.file("out/deck.toml"));
  CHECK(resolved.find("pattern = 'cross'") != std::string::npos);
  CHECK(resolved.find("rate = -2") != std::string::npos);
  CHECK(resolved.find("moisture_safety = 0.9") != std::string::npos);  // a default, shown
  // cross: 4 triangles per cell, 4 x 2 cells
  CHECK(ydry_test::read_text(dir.file("out/summary.json")).find("\"elements\": 32") != std::string::npos);
}

TEST_CASE("an empty array given with --set KEY=[] empties an array of tables", "[deck]") {
  CHECK(ydry_test::strip_deck().moisture_boundaries.size() == 1);
  CHECK(ydry_test::strip_deck({"moisture.boundary=[]"}).moisture_boundaries.empty());
}

TEST_CASE("a non-empty output folder that is not a ydry run is refused without --force", "[deck]") {
  ydry_test::TempDir dir;
  ydry_test::write_text(dir.file("deck.toml"), kGoodDeck);
  std::filesystem::create_directories(dir.file("out"));
  ydry_test::write_text(dir.file("out/thesis.tex"), "precious");
  const std::string args = dir.file("deck.toml") + " -o " + dir.file("out") + " --quiet";
  const auto refused = run_ydry(args);
  CHECK(refused.exit_code == 2);
  CHECK(refused.output.find("--force") != std::string::npos);
  CHECK(run_ydry(args + " --force").exit_code == 0);
  CHECK(run_ydry(args).exit_code == 0);  // now it holds an earlier run: reused
  CHECK(ydry_test::read_text(dir.file("out/thesis.tex")) == "precious");
}

TEST_CASE("a wrong output path is refused before the set-up, and a failed set-up leaves no folder", "[deck]") {
  // The shipped Peron deck beside a mesh file that is not a mesh: the set-up would fail on it
  // (and with a real mesh, spend seconds on the initial equilibrium), so the output path's
  // error can only come first if it is checked first.
  ydry_test::TempDir dir;
  std::filesystem::copy_file(YDRY_SOURCE_DIR "/inputs/peron/peron.toml", dir.file("peron.toml"));
  ydry_test::write_text(dir.file("peron.msh"), "not a mesh\n");
  ydry_test::write_text(dir.file("a_file"), "");
  const auto onto_a_file = run_ydry(dir.file("peron.toml") + " -o " + dir.file("a_file") + " --quiet");
  CHECK(onto_a_file.exit_code == 2);
  CHECK(onto_a_file.output.find("output path exists and is not a folder") != std::string::npos);
  CHECK(onto_a_file.output.find("mesh.file") == std::string::npos);
  const auto bad_mesh = run_ydry(dir.file("peron.toml") + " -o " + dir.file("new") + " --quiet");
  CHECK(bad_mesh.exit_code == 2);
  CHECK(bad_mesh.output.find("mesh.file") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.file("new")));
}

TEST_CASE("ydry check validates a deck without running it and prints the resolved deck", "[deck]") {
  ydry_test::TempDir dir;
  ydry_test::write_text(dir.file("deck.toml"), kGoodDeck);
  const auto good = run_ydry("check " + dir.file("deck.toml") + " --set run.end_time=75.5");
  CHECK(good.exit_code == 0);
  CHECK(good.output.find("is valid") != std::string::npos);
  CHECK(good.output.find("end_time = 75.5") != std::string::npos);  // the override, resolved
  CHECK(good.output.find("relaxation_tolerance") != std::string::npos);  // a default, written out
  const auto bad = run_ydry("check " + dir.file("deck.toml") + " --set materials.soil.young=-1");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("materials.soil.young") != std::string::npos);
  CHECK(run_ydry("check").exit_code == 2);  // no deck
}

TEST_CASE("the resolved deck of a deck with a mesh file is itself a deck that checks the same from elsewhere", "[deck]") {
  ydry_test::TempDir dir;
  const auto shipped = run_ydry("check " YDRY_SOURCE_DIR "/inputs/peron/peron.toml");
  REQUIRE(shipped.exit_code == 0);
  const ydry::Deck first = ydry::load_deck(YDRY_SOURCE_DIR "/inputs/peron/peron.toml", {});
  ydry_test::write_text(dir.file("resolved.toml"), ydry::resolved_deck_text(first));
  const ydry::Deck again = ydry::load_deck(dir.file("resolved.toml"), {});  // its mesh is found from here
  CHECK(std::filesystem::equivalent(again.mesh_file, first.mesh_file));
  // The same values: the resolved text differs only in the header's path.
  const std::string a = ydry::resolved_deck_text(first), b = ydry::resolved_deck_text(again);
  CHECK(a.substr(a.find('\n')) == b.substr(b.find('\n')));
}

TEST_CASE("every deck shipped in inputs/ loads and sets up", "[deck]") {
  std::vector<std::filesystem::path> decks;
  // A deck has a [run] table; the sweep files of inputs/sweeps (scripts/sweep.py) name a deck
  // and have none.
  for (const auto& entry : std::filesystem::recursive_directory_iterator(YDRY_SOURCE_DIR "/inputs"))
    if (entry.path().extension() == ".toml" && toml::parse_file(entry.path().string()).contains("run"))
      decks.push_back(entry.path());
  CHECK(decks.size() >= 3);  // the demo, the Peron case and the thickness sweep's layer
  for (const auto& deck : decks) {
    INFO(deck.string());
    // One pseudo-step of the initial equilibrium is enough to build everything a run needs.
    CHECK_NOTHROW(ydry::setup_state(ydry::load_deck(deck.string(), {"solver.relaxation_max_steps=1"})));
  }
}

TEST_CASE("a malformed --set key path is an error, not read as another key", "[deck]") {
  // Each of these, read loosely, would set run.name or moisture.boundary[0].rate as if well formed.
  for (const char* set : {"run[-1].name=x", "run.name[-2]=x", "run.name.=x", "moisture.boundary[0x].rate=1",
                          "moisture.boundary[ 0].rate=1", "moisture.boundary[99999999999999999999].rate=1"}) {
    INFO(set);
    CHECK_THROWS_WITH(ydry_test::strip_deck({set}), Catch::StartsWith(std::string("--set ") + set + ": ") &&
                                                        (Catch::Contains("malformed index") || Catch::Contains("empty key")));
  }
  CHECK(ydry_test::strip_deck({"moisture.boundary[0].rate=2"}).moisture_boundaries[0].rate_kg_m2_s == 2.0);
}

TEST_CASE("read_deck reads a deck's text as load_deck reads its file", "[deck]") {
  const std::string path = YDRY_SOURCE_DIR "/inputs/peron/peron.toml";
  const std::vector<std::string> sets = {"materials.soil.young=1e6"};
  const ydry::Deck from_file = ydry::load_deck(path, sets);
  const ydry::Deck from_text = ydry::read_deck(ydry_test::read_text(path), path, sets);
  CHECK(ydry::resolved_deck_text(from_text) == ydry::resolved_deck_text(from_file));
  CHECK(from_text.mesh_file == from_file.mesh_file);
  CHECK(from_text.materials.at("soil").young == 1e6);
}

TEST_CASE("a generated rectangle with more triangles than 32-bit indices number is refused", "[deck]") {
  // 1e5 x 1e5 cells: 2e10 triangles (a count cast to 32 bits would be undefined past 2^32).
  CHECK_THROWS_WITH(ydry_test::strip_deck({"mesh.size=[1.0, 1.0]", "mesh.element_size=1e-5"}),
                    Catch::Contains("mesh.element_size: makes 2e+10 triangles"));
  CHECK_THROWS_WITH(ydry_test::strip_deck({"mesh.element_size=1e-320"}), Catch::Contains("mesh.element_size: makes inf"));
  // 10,000 x 10,000 cells of "right" fit: 2e8 triangles, 6e8 corners.
  CHECK_NOTHROW(ydry_test::strip_deck({"mesh.size=[1.0, 1.0]", "mesh.element_size=1e-4"}));
}

TEST_CASE("a mesh file that is not a regular file is not found, and never opened", "[deck]") {
  // read_deck only stats mesh.file, so neither it nor the mesh reader ever reads /dev/zero.
  for (const char* file : {"/dev/zero", "/dev/stdin", YDRY_SOURCE_DIR "/tests/data"}) {
    INFO(file);
    std::string text = ydry_test::read_text(YDRY_SOURCE_DIR "/verification/strip1d/strip1d.toml");
    text.replace(text.find("generator = \"rectangle\""), 23, std::string("file = \"") + file + "\"");
    CHECK_THROWS_WITH(ydry::read_deck(text, "deck.toml", {}), Catch::Contains("mesh.file: mesh file") &&
                                                                  Catch::Contains("not found"));
  }
}
