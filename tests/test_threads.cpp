// A cracking run is bitwise the same on 1 and 2 threads, in its final state
// and in every file it writes but for the run facts that name the thread count and the wall
// time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "tests/test_support.h"
#include "ycore/driver/setup.h"
#include "ycore/driver/coupling.h"
#include "ycore/driver/run.h"

using namespace ydry;
using namespace ydry_test;

TEST_CASE("a cracking run ends in a bitwise identical state on 1 and 2 threads", "[threads]") {
  const Deck deck = load_deck(kPeronDeck, kCrackingLayer);
  Snapshot state[2];
  on_1_and_2_threads([&](int threads) {
    State s = setup_state(deck);
    advance_to(s, deck, deck.end_time_s, coupling_step_limit(s, deck));
    state[threads - 1] = state_snapshot(s);
  });
  // It means something: joints broke, and the contacts carried load and slipped.
  const std::vector<double>& broken = state[0]["joints.broken"];
  CHECK(std::count(broken.begin(), broken.end(), 1.0) >= 1);
  CHECK(state[0]["contact.work_J"][0] > 0.0);
  for (const auto& [name, values] : state[0]) {
    INFO(name);
    CHECK(same_bits(values, state[1][name]));
  }
}

TEST_CASE("a cracking run writes byte-identical files on 1 and 2 threads", "[threads]") {
  TempDir dir;
  on_1_and_2_threads([&](int threads) {
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
    CHECK(same_but_run_facts(dir.path / "1" / file, dir.path / "2" / file));
  }
}
