// ydry: 2D FDEM moisture diffusion - shrinkage - fracture for soil desiccation cracking.
//   ydry DECK.toml [-o OUTDIR] [--set key.path=value ...] [--threads N] [--force] [--quiet]
//        [--checkpoint-every SECONDS] [--checkpoint-every-steps N]
//   ydry --restart CHECKPOINT [DECK.toml [--set ...]] [-o OUTDIR] [...]   (continue a run)
//   ydry check DECK.toml [--set key.path=value ...]   (validate, print the resolved deck)
//   ydry check --restart CHECKPOINT                   (validate a checkpoint)
// Exit codes: 0 done, 2 bad input, 3 numerical failure, 130 interrupted (checkpoint written).
#include <CLI/CLI.hpp>

#include <iostream>
#include <new>

#include "version.h"
#include "ycore/input/input_error.h"
#include "ycore/solid/numerical_failure.h"
#include "ycore/driver/run.h"

int main(int argc, char** argv) {
  CLI::App app{"ydry: 2D FDEM simulation of soil desiccation cracking (moisture diffusion, "
               "shrinkage, cohesive fracture)"};
  ydry::RunOptions opt;
  CLI::App* check = app.add_subcommand("check", "validate a deck and its mesh and print the resolved deck "
                                                "(every value, defaults included) without running");
  check->add_option("deck", opt.deck_path, "input deck (TOML)");
  check->add_option("--set", opt.overrides, "override a deck value: key.path=value (repeatable)");
  check->add_option("--restart", opt.restart_path, "check a checkpoint instead: read it and restore its state");
  app.add_option("deck", opt.deck_path, "input deck (TOML); with --restart, only to check it is the checkpoint's");
  app.add_option("-o,--output", opt.outdir, "output folder (default runs/NAME)");
  app.add_option("--set", opt.overrides, "override a deck value: key.path=value (repeatable)");
  app.add_option("--threads", opt.threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  app.add_flag("--force", opt.force, "write into a non-empty output folder that is not an earlier run's");
  app.add_flag("-q,--quiet", opt.quiet, "no progress or log lines on stderr (warnings and errors still)");
  app.add_option("--progress-every", opt.progress_every_s,
                 "seconds between progress lines when stderr is not a terminal")
      ->check(CLI::PositiveNumber);
  app.add_option("--restart", opt.restart_path,
                 "continue the run of a checkpoint (OUTDIR/checkpoints/NAME_NNNNNN.chk) in its output folder");
  app.add_option("--checkpoint-every", opt.checkpoint_every_s,
                 "write a checkpoint every SECONDS of wall time (one is always written at the end and on SIGINT "
                 "or SIGTERM)")
      ->check(CLI::PositiveNumber);
  app.add_option("--checkpoint-every-steps", opt.checkpoint_every_steps,
                 "write a checkpoint every N coupling steps (reproducible places, unlike wall time)")
      ->check(CLI::PositiveNumber);
  app.set_version_flag("--version", std::string("ydry ") + YDRY_VERSION + " (" + YDRY_COMMIT + ")");
  try {
    app.parse(argc, argv);
    if (opt.deck_path.empty() && opt.restart_path.empty()) throw CLI::RequiredError("deck");
    if (check->parsed() && !opt.deck_path.empty() && !opt.restart_path.empty())
      throw CLI::ValidationError("check: give a DECK or --restart CHECKPOINT, not both");
    if (opt.force && !opt.restart_path.empty())
      throw CLI::ValidationError("--force: a restart writes into its run's own folder, which needs no force");
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    return check->parsed() ? ydry::check(opt) : ydry::run(opt);
  } catch (const ydry::InputError& e) {
    std::cerr << "ydry: error: " << e.what() << "\n";
    return 2;
  } catch (const ydry::NumericalFailure& e) {  // in the set-up (after it, run() reports it)
    std::cerr << "ydry: error: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "ydry: failed: out of memory: the mesh and its buffers need more memory than this machine "
                 "gives (a coarser mesh.element_size or a smaller domain)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "ydry: failed: " << e.what() << "\n";
    return 1;
  }
}
