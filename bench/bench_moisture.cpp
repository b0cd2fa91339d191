// Moisture kernel throughput (moisture node-steps per second) at 1 thread and at all
// threads, on bench/moisture_rectangle.toml. A figure to report, not a test.
#include <omp.h>

#include <chrono>
#include <cstdio>

#include "ycore/input/deck.h"
#include "ycore/driver/setup.h"
#include "ymoist/moisture_step.h"

namespace {

double node_steps_per_second(const ydry::Deck& deck, int threads, int steps) {
  omp_set_num_threads(threads);
  ydry::State state = ydry::setup_state(deck);
  const double dt = ydry::stable_moisture_step(state.moisture, state.moisture_elements, deck.moisture_safety);
  ydry::moisture_step(state.nodes, dt, state.moisture_elements, state.moisture, state.water);  // warm-up
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i)
    ydry::moisture_step(state.nodes, dt, state.moisture_elements, state.moisture, state.water);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return double(state.moisture.size()) * steps / s;
}

}  // namespace

int main() {
  const ydry::Deck deck = ydry::load_deck(YDRY_SOURCE_DIR "/bench/moisture_rectangle.toml", {});
  const int max_threads = omp_get_max_threads();
  const int steps = 400;
  const double one = node_steps_per_second(deck, 1, steps);
  const double all = node_steps_per_second(deck, max_threads, steps);
  std::printf("moisture node-steps/s: %.3g at 1 thread, %.3g at %d threads (speed-up %.2f)\n", one, all,
              max_threads, all / one);
  return 0;
}
