#include "ycore/driver/run.h"

#include <omp.h>

#include <iostream>
#include <sstream>

#include "ycore/driver/coupling.h"
#include "ycore/driver/interruption.h"
#include "ycore/driver/run_session.h"
#include "ycore/driver/setup.h"
#include "ycore/output/checkpoint.h"

namespace ydry {
namespace {

int check_checkpoint(const RunOptions& opt) {
  const Checkpoint checkpoint = read_checkpoint_file(opt.restart_path);
  const Deck deck = checkpoint_deck(checkpoint, opt.restart_path, opt.deck_path, opt.overrides);
  const State state = state_from_checkpoint(deck, checkpoint);
  checkpoint_record(checkpoint, deck, state);
  std::cout << checkpoint_deck_text(checkpoint);
  std::cerr << "ydry check: " << opt.restart_path << " is a valid checkpoint of run " << deck.name << " at t = "
            << state.time_s << " s of " << deck.end_time_s << " s (coupling step " << state.coupling_steps
            << "), written by ydry " << checkpoint.ydry_version << "\n";
  return 0;
}

}  // namespace

int check(const RunOptions& opt) {
  if (!opt.restart_path.empty()) return check_checkpoint(opt);
  const Deck deck = load_deck(opt.deck_path, opt.overrides);
  const State state = prepare_state(deck);
  std::cout << resolved_deck_text(deck);
  std::ostringstream line;
  line << "ydry check: " << deck.path << " is valid: " << state.triangles.size() << " triangles, "
       << state.joints.size() << " joints, " << state.moisture.size() << " moisture nodes; coupling step "
       << coupling_step_limit(state, deck) << " s";
  if (deck.mechanics) line << ", mechanical pseudo-step " << state.mechanics.step_s << " s";
  std::cerr << line.str() << "\n";
  return 0;
}

int run(const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const InterruptWatch interrupts;  // SIGINT, SIGTERM: a checkpoint after the coupling step under way
  RunSession session(options);
  return session.run_to_end();
}

}  // namespace ydry
