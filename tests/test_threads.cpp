// Issue 6, item 2: a cracking run is bitwise the same on 1 and 2 threads, in its final state
// and in every file it writes but for the run facts that name the thread count and the wall
// time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>

#include "tests/test_support.h"
#include "ycore/mechanics.h"
#include "ycore/run.h"

using namespace ydry;

namespace {

// The Peron deck on its 40 mm cousin tests/data/notched_layer.msh (642 triangles: soil on a
// rigid notched base, in contact and with friction from the start), the soil made to crack
// early (shrinkage coefficient 0.4, gf_I 0.02 J/m^2) and the relaxations kept short
// (tolerance 1e-4, cap 3000 steps): the first joint breaks by 2000 s, three by 3000 s, in
// some 10,000 steps.
const char* const kPeronDeck = YDRY_SOURCE_DIR "/inputs/peron/peron.toml";
const std::vector<std::string> kCrackingLayer = {
    "mesh.file=\"" YDRY_SOURCE_DIR "/tests/data/notched_layer.msh\"",
    "run.end_time=3000",
    "run.output_interval=1500",
    "run.series_interval=1000",
    "solver.mechanics_interval=1000",
    "materials.soil.shrinkage_coefficient=0.4",
    "materials.soil.gf_I=0.02",
    "solver.relaxation_tolerance=1e-4",
    "solver.relaxation_max_steps=3000"};

// What the run leaves behind, by name; flags and counts as doubles.
using Snapshot = std::map<std::string, std::vector<double>>;

Snapshot final_state(const State& s) {
  const Energies e = energies(s);
  return {{"x", s.nodes.x},
          {"y", s.nodes.y},
          {"vx", s.nodes.vx},
          {"vy", s.nodes.vy},
          {"moisture w", s.moisture.w},
          {"moisture node of each corner", {s.nodes.mnode.begin(), s.nodes.mnode.end()}},
          {"joint damage", s.joints.damage},
          {"joint broken", {s.joints.broken.begin(), s.joints.broken.end()}},
          {"joint work", s.joints.work},
          {"contact pair slip", s.contact.pair_slip},
          {"contact work", {s.contact.work_J}},
          {"energies", {e.kinetic_J, e.elastic_J, e.joint_work_J, e.fracture_J, e.contact_work_J,
                        e.external_work_J, e.gravity_work_J}},
          {"water", {s.water.net_in_kg, s.water.net_in_carry, s.water.gross_kg}},
          {"steps", {double(s.mechanics.steps), double(s.moisture_steps), double(s.contact.builds)}}};
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A file's text without the facts a run states about its execution: the thread count and the
// wall time (summary.json's "threads" and "wall_s", and the log's prose).
std::string without_run_facts(const std::string& text) {
  static const std::regex facts(R"("threads": \d+|"wall_s": [^,\n]+|\d+ threads|wall [^ ,\n]+ s)");
  return std::regex_replace(text, facts, "<run fact>");
}

// The files under `folder`, as paths relative to it, sorted.
std::vector<std::string> files_under(const std::filesystem::path& folder) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(std::filesystem::relative(entry.path(), folder).string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("a cracking run ends in a bitwise identical state on 1 and 2 threads", "[threads]") {
  const Deck deck = load_deck(kPeronDeck, kCrackingLayer);
  Snapshot state[2];
  ydry_test::on_1_and_2_threads([&](int threads) {
    State s = setup_state(deck);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    state[threads - 1] = final_state(s);
  });
  // It means something: joints broke, and the contacts carried load and slipped.
  const std::vector<double>& broken = state[0]["joint broken"];
  CHECK(std::count(broken.begin(), broken.end(), 1.0) >= 1);
  CHECK(state[0]["contact work"][0] > 0.0);
  for (const auto& [name, values] : state[0]) {
    INFO(name);
    CHECK(same_bits(values, state[1][name]));
  }
}

TEST_CASE("a cracking run writes byte-identical files on 1 and 2 threads", "[threads]") {
  ydry_test::TempDir dir;
  ydry_test::on_1_and_2_threads([&](int threads) {
    RunOptions options;
    options.deck_path = kPeronDeck;
    options.overrides = kCrackingLayer;
    options.outdir = dir.file("run");  // one path for both, since the log names it
    options.threads = threads;
    options.quiet = true;
    REQUIRE(run(options) == 0);
    std::filesystem::rename(options.outdir, dir.file(std::to_string(threads)));
  });
  const std::vector<std::string> written = files_under(dir.path / "1");
  REQUIRE(written == files_under(dir.path / "2"));
  CHECK(std::count_if(written.begin(), written.end(), [](const std::string& f) {
          return f.size() > 4 && f.compare(f.size() - 4, 4, ".vtu") == 0;
        }) == 6);  // frames at 0, 1500 and 3000 s, bulk and cracks
  for (const std::string& file : written) {
    INFO(file);
    CHECK(without_run_facts(ydry_test::read_text(dir.file("1/" + file))) ==
          without_run_facts(ydry_test::read_text(dir.file("2/" + file))));
  }
}
