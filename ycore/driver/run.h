// The commands of the ydry executable: run a deck (or continue a checkpoint), and check one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ydry {

struct RunOptions {
  std::string deck_path;
  std::string outdir;                  // empty: runs/NAME
  std::vector<std::string> overrides;  // --set key.path=value
  int threads = 0;                     // 0: OpenMP's default
  bool force = false;
  bool quiet = false;
  double progress_every_s = 10.0;      // plain progress lines when stderr is not a terminal
  std::string restart_path;            // a checkpoint to continue; deck_path may then be empty
  double checkpoint_every_s = 0;       // wall seconds between checkpoints; 0: none
  std::uint64_t checkpoint_every_steps = 0;  // coupling steps between checkpoints; 0: none
};

// `ydry check DECK`: reads the deck (with its --set overrides) and the mesh, checks them as
// a run would, prints the resolved deck (every value, defaults included) on stdout and a
// line with the mesh's sizes and steps on stderr, without running. Returns 0; bad input
// throws InputError like run(). `ydry check --restart CHECKPOINT` reads the checkpoint and
// restores its state as a restart would, and prints its deck.toml and a line on its time.
int check(const RunOptions& options);

// Runs a deck end to end with outputs, or continues the run of options.restart_path; writes
// checkpoints on request, at the end, and on SIGINT or SIGTERM (then returns 130). Returns
// the process exit code.
int run(const RunOptions& options);

}  // namespace ydry
