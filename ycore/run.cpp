#include "ycore/run.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "version.h"
#include "ycore/build_state.h"
#include "ycore/input_error.h"
#include "ycore/output_files.h"
#include "ycore/progress.h"
#include "ycore/vtk_output.h"
#include "ycrack/node_sharing.h"
#include "ymoist/moisture.h"

namespace ydry {
namespace {

// Features of the deck schema whose physics is not built yet: refused, never ignored.
void refuse_unbuilt_features(const Deck& deck) {
  const std::string file = deck.path;
  if (deck.mechanics)
    throw InputError(file + ": run.mechanics: the mechanical solver is not built yet; "
                            "set run.mechanics = false for a moisture-only run");
  if (!deck.cracks.empty())
    throw InputError(deck.cracks.front().where +
                     ": pre-existing cracks need the node-sharing split, which is not built yet");
}

std::vector<double> series_row(const State& s) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double water_lost = s.water.initial_kg - total_water_kg(s);
  // Crack, displacement, energy and relaxation columns need mechanics: NaN in this build.
  return {s.time_s, mean_moisture(s), water_lost, water_balance_error(s), nan, nan, nan, nan, nan, nan, nan};
}

JsonObject summary_json(const Deck& deck, const State& s, const Series& series, double wall_s,
                        bool completed) {
  JsonObject j;
  j.text("name", deck.name);
  j.text("version", std::string(YDRY_VERSION) + " (" + YDRY_COMMIT + ")");
  for (std::size_t c = 0; c < kSeriesColumns.size(); ++c) j.number(kSeriesColumns[c], series.rows.back()[c]);
  j.integer("threads", omp_get_max_threads());
  j.number("wall_s", wall_s);
  j.integer("elements", static_cast<long long>(s.triangles.size()));
  j.integer("joints", static_cast<long long>(s.joints.size()));
  j.integer("moisture_nodes", static_cast<long long>(s.moisture.size()));
  j.integer("moisture_steps", static_cast<long long>(s.moisture_steps));
  j.integer("mechanical_steps", 0);
  j.boolean("completed", completed);
  return j;
}

}  // namespace

State setup_state(const Deck& deck) {
  refuse_unbuilt_features(deck);
  State s = build_state(load_mesh(deck), deck);
  std::vector<std::uint8_t> has_moisture(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    has_moisture[t] = deck.materials.at(s.material_names[s.triangles.material[t]]).has_moisture();
  if (std::none_of(has_moisture.begin(), has_moisture.end(), [](std::uint8_t h) { return h != 0; }))
    throw InputError(deck.path + ": materials: no material of the mesh has moisture_conductivity, "
                                 "so a moisture-only run has nothing to compute");
  group_moisture_nodes(s.joints, has_moisture, s.nodes, s.moisture);
  init_moisture(s, deck);
  return s;
}

void advance_to(State& s, double until_s, double max_step_s) {
  while (s.time_s < until_s) {
    const double remaining = until_s - s.time_s;
    // The last step lands exactly on until_s (it is never longer than a stable step).
    const bool last = remaining <= max_step_s;
    moisture_step(s, last ? remaining : max_step_s);
    s.time_s = last ? until_s : s.time_s + max_step_s;
    ++s.moisture_steps;
  }
}

int run(const RunOptions& opt) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const Deck deck = load_deck(opt.deck_path, opt.overrides);
  State state = setup_state(deck);
  const std::string outdir = opt.outdir.empty() ? "runs/" + deck.name : opt.outdir;
  prepare_output_dir(outdir, opt.force);
  write_file_atomically(outdir + "/deck.toml", resolved_deck_text(deck));

  Log log;
  log.open(outdir + "/log.txt", opt.quiet);
  std::ostringstream head;
  head << "ydry " << YDRY_VERSION << " (" << YDRY_COMMIT << "), deck " << deck.path << ", "
       << omp_get_max_threads() << " threads\n"
       << "mesh: " << state.triangles.size() << " triangles, " << state.joints.size() << " joints, "
       << state.moisture.size() << " moisture nodes";
  log.info(head.str());
  std::vector<std::uint8_t> material_used(state.material_names.size(), 0);
  for (const std::uint16_t m : state.triangles.material) material_used[m] = 1;
  for (std::size_t m = 0; m < material_used.size(); ++m)
    if (!material_used[m])
      log.warning("[materials." + state.material_names[m] + "] is not used by any triangle of the mesh");
  const double stable_step = stable_moisture_step(state, deck.moisture_safety);
  // Nothing diffuses or exchanges: the state only changes through flux terms, step per frame.
  const double max_step = std::isfinite(stable_step) ? stable_step : deck.output_interval_s;
  log.info("moisture step " + std::to_string(max_step) + " s (safety " +
           std::to_string(deck.moisture_safety) + " of the explicit limit); output to " + outdir);

  FrameSeries frames{outdir, deck.name, {}, {}};
  Series series;
  Progress progress;
  progress.start(deck.end_time_s, opt.quiet, opt.progress_every_s);
  const auto write_outputs = [&](bool completed) {
    write_frame(frames, state, state.time_s);
    series.rows.push_back(series_row(state));
    write_series_csv(outdir + "/series.csv", series);
    write_file_atomically(outdir + "/summary.json",
                          summary_json(deck, state, series, progress.wall_s(), completed).dump());
  };

  write_outputs(false);
  for (long frame = 1; state.time_s < deck.end_time_s; ++frame) {
    const double next_output = std::min(deck.end_time_s, frame * deck.output_interval_s);
    while (state.time_s < next_output) {
      // Advance in chunks so the progress line stays live on long intervals.
      advance_to(state, std::min(next_output, state.time_s + 1000 * max_step), max_step);
      progress.update(state.time_s, state.moisture_steps);
    }
    write_outputs(state.time_s >= deck.end_time_s);
  }
  progress.finish(state.time_s, state.moisture_steps);

  std::ostringstream tail;
  tail << "done: t = " << state.time_s << " s, " << state.moisture_steps << " moisture steps, "
       << "mean moisture " << mean_moisture(state) << ", water balance error "
       << water_balance_error(state) << ", wall " << progress.wall_s() << " s\n"
       << "outputs: " << outdir << "/" << deck.name << ".pvd, series.csv, summary.json, deck.toml, log.txt";
  log.info(tail.str());
  return 0;
}

}  // namespace ydry
