// Mechanical throughput, in element-steps per second: deformable triangles x mechanical
// steps / seconds of the coupling steps that made them (relaxations with their element,
// joint and contact forces; once per relaxation also 50-70 moisture steps, the breakage commit
// and the split of the moisture nodes: under 1.5 % of the time, bench/RESULTS.md). At 1
// thread and at all threads, from one and the same state (the runs are bitwise the same, so
// both do the same work). Then, as measures of the machine, the element pass alone (the
// co-rotational triangle forces with the nodes' integration fused in, no joints, no contact)
// over the same mesh, and the triangle forces alone (no integration either: the bare elastic
// kernel). Figures to report, not tests.
//   bench_mechanics [rectangle] [peron]     (both when none is named)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cstring>
#include <exception>
#include <string>
#include <type_traits>
#include <vector>

#include "ycore/output/checkpoint_file.h"
#include "ycore/input/deck.h"
#include "ycore/solid/element_forces.h"
#include "ycore/driver/setup.h"
#include "ycore/driver/coupling.h"
#include "ycore/state/stage_timing.h"
#include "ycore/state/state_fields.h"

namespace {

struct Case {
  const char* name;
  const char* deck;
  bool from_first_crack;     // time from the first broken joint on, or from the start
  std::uint64_t min_steps;   // whole relaxations until at least this many steps
};

// bench/cracking_rectangle.toml: 200,000 triangles, relaxations capped at 200 steps.
// inputs/peron/peron.toml as shipped: its first cracks come at 40,000 s, after some 200,000
// steps, too long for `make bench`, so the steps timed are its first relaxation after the
// initial equilibrium, before any joint has broken.
const Case kCases[] = {
    {"rectangle", YDRY_SOURCE_DIR "/bench/cracking_rectangle.toml", true, 1000},
    {"peron", YDRY_SOURCE_DIR "/inputs/peron/peron.toml", false, 5000},
};

std::size_t broken_joints(const ydry::State& s) {
  return std::size_t(std::count(s.joints.broken.begin(), s.joints.broken.end(), 1));
}

// Intact joints with committed damage at some point: the joint kernel gives them the full
// traction law instead of its vectorised pre-peak pass.
std::size_t damaged_joints(const ydry::State& s) {
  std::size_t count = 0;
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    count += !s.joints.broken[j] && (s.joints.damage[3 * j] > 0.0 || s.joints.damage[3 * j + 1] > 0.0 ||
                                     s.joints.damage[3 * j + 2] > 0.0);
  return count;
}

// FNV-1a-64 of the state's history and topology (ycore/state/state_fields.h). Printed so that
// two builds' runs can be told the same bits or not (a change meant to keep the results must
// keep it).
std::uint64_t state_hash(const ydry::State& s) {
  std::uint64_t hash = ydry::fnv1a64(nullptr, 0);
  const auto add = [&](const std::string&, const auto& value) {
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(value)>>)
      hash = ydry::fnv1a64(reinterpret_cast<const char*>(&value), sizeof value, hash);
    else
      ydry::hash_array(hash, value);
  };
  ydry::for_each_history_field(s, add);
  ydry::for_each_topology_field(s, add);
  return hash;
}

std::size_t deformable_triangles(const ydry::State& s) {
  std::size_t count = 0;
  for (const std::uint16_t m : s.triangles.material) count += s.materials[m].mechanical;
  return count;
}

// One relaxation: mechanics_interval of drying, then the solid relaxed (advance_to relaxes
// at its end). Returns the coupling step limit to go on with.
double relax_once(ydry::State& s, const ydry::Deck& deck, double step_limit) {
  return ydry::advance_to(s, deck, s.time_s + deck.mechanics_interval_s, step_limit);
}

struct Timed {
  std::uint64_t steps = 0;
  double seconds = 0;
  double cores = 0;  // CPU seconds of all threads / wall seconds: what the machine gave the run
  ydry::State end;
};

// Whole relaxations from `start` on `threads` threads until at least `min_steps` steps.
Timed time_relaxations(const ydry::State& start, const ydry::Deck& deck, int threads, std::uint64_t min_steps) {
  omp_set_num_threads(threads);
  Timed t{0, 0, 0, start};
  t.end.wall = {};
  double step_limit = ydry::coupling_step_limit(t.end, deck);
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  while (t.end.mechanics.steps - start.mechanics.steps < min_steps) step_limit = relax_once(t.end, deck, step_limit);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.cores = double(std::clock() - cpu0) / CLOCKS_PER_SEC / t.seconds;
  t.steps = t.end.mechanics.steps - start.mechanics.steps;
  return t;
}

// Seconds of `steps` element passes over a copy of `start` on `threads` threads: with
// `integrate`, the nodes move undamped by the stable pseudo-step, as in a relaxation's step;
// without, the forces of the same positions again and again.
double time_element_pass(const ydry::State& start, int threads, int steps, bool integrate) {
  omp_set_num_threads(threads);
  ydry::State s = start;
  const ydry::VelocityUpdate undamped{1.0, 0.0, 1.0, s.mechanics.step_s};
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k)
    ydry::element_forces(s.triangles, s.mechanics, s.ownership, s.materials, s.nodes, integrate ? &undamped : nullptr);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int bench(const Case& c) {
  const int max_threads = omp_get_max_threads();
  const ydry::Deck deck = ydry::load_deck(c.deck, {});
  if (deck.mechanics_interval_s <= 0.0) {
    std::fprintf(stderr, "bench_mechanics: %s: solver.mechanics_interval must be > 0\n", c.deck);
    return 2;
  }
  ydry::State start = ydry::setup_state(deck);  // on all threads
  if (c.from_first_crack) {
    double step_limit = ydry::coupling_step_limit(start, deck);
    while (broken_joints(start) == 0 && start.time_s < deck.end_time_s)
      step_limit = relax_once(start, deck, step_limit);
    if (broken_joints(start) == 0) {
      std::fprintf(stderr, "bench_mechanics: %s: no joint broke by run.end_time = %g s\n", c.deck, deck.end_time_s);
      return 1;
    }
  }
  const std::size_t triangles = deformable_triangles(start);
  std::printf("mechanics %s: %zu deformable triangles (%zu in all), %zu joints; from t = %g s (%zu joints broken, "
              "%zu damaged, %zu contact pairs)\n",
              c.name, triangles, start.triangles.size(), start.joints.size(), start.time_s, broken_joints(start),
              damaged_joints(start), start.contact.pair_node.size());
  const Timed one = time_relaxations(start, deck, 1, c.min_steps);
  const Timed all = time_relaxations(start, deck, max_threads, c.min_steps);
  std::printf("mechanics %s: %llu steps to t = %g s (%zu joints broken, %zu damaged, %zu contact pairs; state hash "
              "%016llx): %.2f s at 1 thread, %.2f s at %d threads (on %.2f cores)\n",
              c.name, static_cast<unsigned long long>(one.steps), one.end.time_s, broken_joints(one.end),
              damaged_joints(one.end), one.end.contact.pair_node.size(),
              static_cast<unsigned long long>(state_hash(one.end)), one.seconds, all.seconds, max_threads, all.cores);
  for (const Timed* t : {&one, &all})
    std::printf("mechanics %s: at %d thread(s), %s\n", c.name, t == &one ? 1 : max_threads,
                ydry::wall_by_stage_text(t->end.wall, t->seconds).c_str());
  const double rate_one = double(triangles) * one.steps / one.seconds;
  const double rate_all = double(triangles) * all.steps / all.seconds;
  std::printf("mechanics %s: element-steps/s: %.3g at 1 thread, %.3g at %d threads (speed-up %.2f)\n", c.name,
              rate_one, rate_all, max_threads, rate_all / rate_one);
  constexpr int kElementPasses = 500;
  for (const bool integrate : {true, false}) {
    const double pass_one = time_element_pass(start, 1, kElementPasses, integrate);
    const double pass_all = time_element_pass(start, max_threads, kElementPasses, integrate);
    std::printf("mechanics %s: %s: element-steps/s: %.3g at 1 thread, %.3g at %d threads\n", c.name,
                integrate ? "the element pass alone (no joints, no contact; the machine's measure)"
                          : "the triangle forces alone (no integration either: the bare kernel)",
                double(triangles) * kElementPasses / pass_one, double(triangles) * kElementPasses / pass_all,
                max_threads);
  }
  std::fflush(stdout);
  // A check on a large mesh, where every loop runs in parallel (the tests force small ones to).
  const bool same = one.end.nodes.x == all.end.nodes.x && one.end.nodes.y == all.end.nodes.y &&
                    one.end.joints.damage == all.end.joints.damage && one.end.moisture.w == all.end.moisture.w;
  if (same) return 0;
  std::fprintf(stderr, "bench_mechanics: %s: the state after %d threads differs from the one after 1 thread\n",
               c.name, max_threads);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<const Case*> cases;
  for (int a = 1; a < argc; ++a) {
    const auto named = std::find_if(std::begin(kCases), std::end(kCases),
                                    [&](const Case& c) { return std::strcmp(c.name, argv[a]) == 0; });
    if (named == std::end(kCases)) {
      std::fprintf(stderr, "bench_mechanics: unknown case '%s' (cases: rectangle, peron)\n", argv[a]);
      return 2;
    }
    cases.push_back(named);
  }
  if (cases.empty())
    for (const Case& c : kCases) cases.push_back(&c);
  try {
    for (const Case* c : cases)
      if (const int code = bench(*c)) return code;
  } catch (const std::exception& e) {  // a deck that cannot be run
    std::fprintf(stderr, "bench_mechanics: %s\n", e.what());
    return 2;
  }
  return 0;
}
