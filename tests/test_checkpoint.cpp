// Checkpoints and restart. A state restored from a checkpoint is the state it
// was written from, array by array, and goes on the same; a restart from any checkpoint ends in
// the files of the uninterrupted run, byte for byte, but for what honestly differs (log.txt,
// summary.json's wall_s and its split by stage); damaged, truncated, foreign or mismatched checkpoints are refused
// with a message that says what is wrong (exit 2), and no bytes make the reader or the restore
// crash.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <random>

#include "tests/test_support.h"
#include "ycore/output/checkpoint.h"
#include "ycore/driver/setup.h"
#include "ycore/driver/coupling.h"
#include "ycore/driver/run.h"

using namespace ydry;
using namespace ydry_test;
namespace fs = std::filesystem;

namespace {

const char* const kStripDeck = YDRY_SOURCE_DIR "/verification/strip1d/strip1d.toml";
// The strip of paper 4.1 (moisture only) cut to 44 coupling steps.
const std::vector<std::string> kShortStrip = {"run.end_time=200000", "run.output_interval=50000"};

RunOptions run_options(const char* deck, const std::vector<std::string>& overrides, const std::string& outdir) {
  RunOptions options;
  options.deck_path = deck;
  options.overrides = overrides;
  options.outdir = outdir;
  options.quiet = true;
  return options;
}

void check_same_bits(const Snapshot& expected, const Snapshot& actual) {
  for (const auto& [name, values] : expected) {
    INFO(name);
    CHECK(same_bits(values, actual.at(name)));
  }
}

// The files of `reference` are in `folder` with the same bytes, but for what a restart
// honestly changes: log.txt (the log of each process that worked on the run, with its folder
// and wall times) and summary.json's wall_s and its split by stage (the wall time of the
// process that wrote it).
// Anything else in `folder` is a checkpoint, the same as in `checkpoints`.
void check_same_outputs(const fs::path& reference, const fs::path& folder, const fs::path& checkpoints) {
  const std::vector<std::string> expected = files_under(reference), written = files_under(folder);
  for (const std::string& file : written) {
    INFO(folder / file);
    const bool ours = std::binary_search(expected.begin(), expected.end(), file);
    if (!ours) {
      REQUIRE(fs::path(file).parent_path() == "checkpoints");
      const fs::path same_name = checkpoints / fs::path(file).filename();
      const bool same_checkpoint = read_text((folder / file).string()) == read_text(same_name.string());
      CHECK(same_checkpoint);
    } else if (file != "log.txt") {
      CHECK(same_but_run_facts(reference / file, folder / file));
    }
  }
  for (const std::string& file : expected) {
    INFO(file);
    CHECK(std::binary_search(written.begin(), written.end(), file));
  }
}

// The checksum of a checkpoint's bytes made right again after they were changed.
void reseal(std::string& bytes) {
  const std::uint64_t sum = fnv1a64(bytes.data(), bytes.size() - 8);
  std::memcpy(&bytes[bytes.size() - 8], &sum, 8);
}

}  // namespace

TEST_CASE("a state restored from a checkpoint is the state it was written from, array by array, and goes on the same",
          "[checkpoint]") {
  const Deck deck = load_deck(kPeronDeck, kCrackingLayer);
  State written = setup_state(deck);
  // 80 steps in: joints have broken, the contacts carry friction history, and the solid has
  // not relaxed since the last relaxation interval began.
  const auto broken = [](const State& s) { return std::count(s.joints.broken.begin(), s.joints.broken.end(), 1); };
  double step = advance_to(written, deck, deck.end_time_s, coupling_step_limit(written, deck),
                           [&] { return written.coupling_steps == 80; });
  REQUIRE(written.coupling_steps == 80);
  const auto broken_at_checkpoint = broken(written);
  REQUIRE(broken_at_checkpoint >= 1);
  REQUIRE(written.mechanics.unrelaxed_s > 0.0);
  REQUIRE(std::any_of(written.contact.pair_slip.begin(), written.contact.pair_slip.end(),
                      [](double slip) { return slip != 0.0; }));
  const std::string bytes = checkpoint_bytes(deck, resolved_deck_text(deck), written, RunRecord{});
  State restored = state_from_checkpoint(deck, read_checkpoint(bytes));
  check_same_bits(state_snapshot(written), state_snapshot(restored));

  advance_to(written, deck, deck.end_time_s, step);
  advance_to(restored, deck, deck.end_time_s, step);
  CHECK(broken(written) > broken_at_checkpoint);  // the continuation split moisture nodes again
  check_same_bits(state_snapshot(written), state_snapshot(restored));
}

TEST_CASE("a restart from any checkpoint ends in the files of the uninterrupted run, byte for byte", "[checkpoint]") {
  struct Case {
    const char* deck;
    std::vector<std::string> overrides;
    std::uint64_t every;      // coupling steps between checkpoints
    std::size_t checkpoints;  // with the one at the end
  };
  // Every 17 steps: between the relaxations (every 1000 s, 35 steps) and inside the chunks of
  // steps; every 35: at the ends of rows, before their outputs are written (checked below); the
  // strip: a run without mechanics.
  const Case cases[] = {{kPeronDeck, kCrackingLayer, 17, 7}, {kPeronDeck, kCrackingLayer, 35, 3},
                        {kStripDeck, kShortStrip, 10, 5}};
  for (const Case& c : cases) {
    INFO(c.deck << ", a checkpoint every " << c.every << " steps");
    TempDir dir;
    const fs::path reference = dir.path / "uninterrupted", checkpointed = dir.path / "checkpointed";
    REQUIRE(run(run_options(c.deck, c.overrides, reference.string())) == 0);
    RunOptions with_checkpoints = run_options(c.deck, c.overrides, checkpointed.string());
    with_checkpoints.checkpoint_every_steps = c.every;
    REQUIRE(run(with_checkpoints) == 0);
    check_same_outputs(reference, checkpointed, checkpointed / "checkpoints");  // writing them changes nothing
    const std::vector<std::string> checkpoints = files_under(checkpointed / "checkpoints");
    CHECK(checkpoints.size() == c.checkpoints);
    if (c.every == 35) {  // t = 1000 s, and the table has only its row at t = 0
      const Checkpoint at_row_end = read_checkpoint_file((checkpointed / "checkpoints" / "peron_000035.chk").string());
      double time_s = 0;
      std::uint64_t row = 0;
      at_row_end.take("time_s", time_s);
      at_row_end.take("record.row", row);
      CHECK(time_s == 1000.0);
      CHECK(row == 1);
    }
    for (const std::string& file : checkpoints) {
      INFO("restart from " << file);
      // The run's folder as it was at the end: a restart from an earlier checkpoint first
      // takes the files back to the checkpoint's time.
      const fs::path restarted = dir.path / ("restart_" + file);
      fs::copy(checkpointed, restarted, fs::copy_options::recursive);
      RunOptions restart;
      restart.restart_path = (restarted / "checkpoints" / file).string();
      restart.quiet = true;
      REQUIRE(run(restart) == 0);  // into the folder that holds checkpoints/
      check_same_outputs(reference, restarted, checkpointed / "checkpoints");
    }
  }
}

TEST_CASE("a damaged, truncated, foreign or mismatched checkpoint is refused with a message that says why (exit 2)",
          "[checkpoint]") {
  TempDir dir;
  const std::string run_folder = dir.file("run"), strip = std::string(kStripDeck) + " --set run.end_time=200000 "
                                                          "--set run.output_interval=50000";
  REQUIRE(run_ydry(strip + " -o " + run_folder + " --quiet").exit_code == 0);
  const std::string good = run_folder + "/checkpoints/strip1d_000044.chk";
  const std::string bytes = read_text(good);
  const auto refused = [&](const std::string& damaged, const std::string& arguments, const std::string& why) {
    if (!damaged.empty()) write_text(dir.file("run/checkpoints/bad.chk"), damaged);
    const CommandResult result = run_ydry("--restart " + (damaged.empty() ? good : dir.file("run/checkpoints/bad.chk")) +
                                          " " + arguments);
    INFO(result.output);
    CHECK(result.exit_code == 2);
    CHECK(result.output.find(why) != std::string::npos);
  };
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x10;
  refused(flipped, "", "the checksum does not match");
  refused(bytes.substr(0, bytes.size() - 100), "", "truncated");
  refused(read_text(run_folder + "/frames/strip1d_000000.vtu"), "", "not a ydry checkpoint");
  std::string newer = bytes;
  newer[8] = char(kCheckpointFormat + 1);  // the format version
  reseal(newer);
  refused(newer, "", "checkpoint format version " + std::to_string(kCheckpointFormat + 1) + "; this ydry reads version " +
                         std::to_string(kCheckpointFormat));
  refused("", strip + " --set run.end_time=300000", "is not the deck");
  refused("", "--set run.end_time=300000", "--set with --restart");
  refused("", "-o " + dir.file("elsewhere"), "holds no ydry run to continue");

  // A checkpoint outside a checkpoints/ folder needs -o; the folder must hold its frames.
  fs::copy_file(good, dir.file("loose.chk"));
  const CommandResult loose = run_ydry("--restart " + dir.file("loose.chk"));
  CHECK(loose.exit_code == 2);
  CHECK(loose.output.find("give the run's output folder with -o") != std::string::npos);
  fs::remove(run_folder + "/frames/strip1d_000002.vtu");
  refused("", "", "a frame the checkpoint lists is missing");

  // The mesh file changed since: one node moved by 1e-14 m.
  fs::copy_file(YDRY_SOURCE_DIR "/tests/data/notched_layer.msh", dir.file("mesh.msh"));
  std::string layer = std::string(kPeronDeck) + " -o " + dir.file("layer") + " --quiet";
  for (const std::string& set : kCrackingLayer) layer += " --set '" + set + "'";
  layer += " --set 'mesh.file=\"" + dir.file("mesh.msh") + "\"' --set run.end_time=100 --set run.output_interval=100 "
           "--set run.series_interval=100 --set solver.mechanics_interval=100";
  REQUIRE(run_ydry(layer).exit_code == 0);
  refused("", "-o " + dir.file("layer"), "holds another run than the checkpoint's");
  std::string mesh = read_text(dir.file("mesh.msh"));
  const std::size_t node = mesh.find("0.01446000902242 ");
  REQUIRE(node != std::string::npos);
  mesh[node + 15] = '3';
  write_text(dir.file("mesh.msh"), mesh);
  const CommandResult moved = run_ydry("check --restart " + dir.file("layer/checkpoints/peron_000004.chk"));
  INFO(moved.output);
  CHECK(moved.exit_code == 2);
  CHECK(moved.output.find("has the mesh file changed") != std::string::npos);
}

TEST_CASE("no bytes make the checkpoint reader or the restore crash: they are read, or refused with an InputError",
          "[checkpoint]") {
  const Deck deck = load_deck(kPeronDeck, kCrackingLayer);
  State s = setup_state(deck);
  advance_to(s, deck, 2500.0, coupling_step_limit(s, deck));
  RunRecord record;
  record.max_step_s = coupling_step_limit(s, deck);
  record.series.columns = series_columns(s.interface_names);
  record.series.rows.assign(1, std::vector<double>(record.series.columns.size(), 0.0));
  const std::string bytes = checkpoint_bytes(deck, resolved_deck_text(deck), s, record);
  const auto outcome = [&](const std::string& b) {  // 0 read and restored, 1 refused
    try {
      const Checkpoint c = read_checkpoint(b);
      const State restored = state_from_checkpoint(checkpoint_deck(c, "mutant", "", {}), c);
      checkpoint_record(c, deck, restored);
      return 0;
    } catch (const InputError&) {
      return 1;
    }
  };
  REQUIRE(outcome(bytes) == 0);
  // Truncated anywhere (every length in the header, then every 997 bytes): refused.
  for (std::size_t length = 0; length < bytes.size(); length += length < 200 ? 1 : 997) {
    INFO("the first " << length << " bytes");
    CHECK(outcome(bytes.substr(0, length)) == 1);
  }
  // Any byte changed, the checksum made right: read or refused, never a crash or a hang.
  std::mt19937_64 random(8);
  int refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string mutant = bytes;
    const std::size_t at = std::uniform_int_distribution<std::size_t>(8, bytes.size() - 9)(random);
    mutant[at] = char(std::uniform_int_distribution<int>(0, 255)(random));
    reseal(mutant);
    refused += outcome(mutant);
  }
  CHECK(refused > 0);
  // A length that claims more than the file holds (the first field's count set to 2^62).
  std::string greedy = bytes;
  const std::size_t first_count = greedy.find("deck.toml") + 9 + 1;  // after its name and type
  const std::uint64_t huge = std::uint64_t(1) << 62;
  std::memcpy(&greedy[first_count], &huge, 8);
  reseal(greedy);
  CHECK_THROWS_WITH(read_checkpoint(greedy), Catch::Contains("claims 4611686018427387904 values"));
}
