#include "ycore/driver/run_session.h"

#include <cmath>
#include <csignal>
#include <filesystem>
#include <sstream>

#include "ycore/driver/coupling.h"
#include "ycore/driver/interruption.h"
#include "ycore/driver/run_log.h"
#include "ycore/driver/run_tables.h"
#include "ycore/driver/setup.h"
#include "ycore/input/input_error.h"
#include "ycore/output/reactions_csv.h"
#include "ycrack/cracks_csv.h"
#include "ycrack/network_census.h"
#include "ycrack/network_csv.h"
#include "ycrack/surface_profile.h"

namespace ydry {
namespace {

// A restart's output folder by default: the one that holds the checkpoint's checkpoints/.
std::string run_folder_of(const std::string& checkpoint) {
  const std::filesystem::path folder = std::filesystem::absolute(checkpoint).parent_path();
  if (folder.filename() != "checkpoints")
    throw InputError(checkpoint + ": not in a run's checkpoints/ folder; give the run's output folder with -o");
  return folder.parent_path().string();
}

std::string output_folder(const RunOptions& options, const Deck& deck) {
  if (!options.outdir.empty()) return options.outdir;
  return options.restart_path.empty() ? "runs/" + deck.name : run_folder_of(options.restart_path);
}

}  // namespace

RunSession::RunSession(const RunOptions& options)
    : options_(options),
      restart_(!options.restart_path.empty()),
      checkpoint_(restart_ ? read_checkpoint_file(options.restart_path) : Checkpoint{}),
      deck_(restart_ ? checkpoint_deck(checkpoint_, options.restart_path, options.deck_path, options.overrides)
                     : load_deck(options.deck_path, options.overrides)),
      deck_text_(restart_ ? checkpoint_deck_text(checkpoint_) : resolved_deck_text(deck_)),
      outdir_(output_folder(options, deck_)) {
  // The folder is checked before the set-up (its initial equilibrium can take minutes), so
  // that a wrong -o is reported at once.
  if (restart_)
    check_resume_dir(outdir_, deck_text_);
  else
    check_output_dir(outdir_, options.force);
  progress_.start(deck_.end_time_s, options.quiet, options.progress_every_s);
  state_ = restart_ ? state_from_checkpoint(deck_, checkpoint_) : setup_state(deck_);
  if (restart_)
    record_ = checkpoint_record(checkpoint_, deck_, state_);
  else
    record_.series.columns = series_columns(state_.interface_names);
  progress_.start_time_s = state_.time_s;
  if (restart_)
    resume_output_dir(outdir_, deck_text_);
  else
    prepare_output_dir(outdir_, options.force);
  frames_ = FrameSeries{outdir_, deck_.name, {}, {}};
  if (restart_) resume_frame_series(frames_, record_.frame_times);  // before anything is written
  write_file_atomically(outdir_ + "/deck.toml", deck_text_);
  start_log();
  if (deck_.mechanics) right_end_ = right_end_corners(state_);
  cracks_csv_ = {outdir_ + "/cracks.csv", kCracksCsvHeader, record_.cracks_rows};
  surface_csv_ = {outdir_ + "/surface.csv", kSurfaceCsvHeader, record_.surface_rows};
  reactions_csv_ = {outdir_ + "/reactions.csv", kReactionsCsvHeader, record_.reactions_rows};
  network_ = deck_.plan_view && deck_.mechanics;
  network_csv_ = {outdir_ + "/network.csv", kNetworkCsvHeader, record_.network_rows};
  cells_csv_ = {outdir_ + "/cells.csv", kCellsCsvHeader, record_.cells_rows};
  junctions_csv_ = {outdir_ + "/junctions.csv", kJunctionsCsvHeader, record_.junctions_rows};
  // surface.csv profiles the boundary named "top", the soil's free surface.
  const auto top = state_.boundary_edges.find("top");
  if (deck_.mechanics && top != state_.boundary_edges.end()) surface_edges_ = &top->second;
  if (deck_.mechanics && !surface_edges_ && !restart_) log_.info("no surface.csv: the mesh has no boundary named \"top\"");
  if (restart_)
    write_files_of_checkpoint();
  else
    write_row(false);
  checkpoint_steps_ = state_.coupling_steps;
  checkpoint_wall_s_ = progress_.wall_s();
}

void RunSession::start_log() {
  log_.open(outdir_ + "/log.txt", options_.quiet, restart_);
  if (restart_) {
    log_restart(log_, state_, options_.restart_path, checkpoint_.ydry_version, outdir_);
  } else {
    record_.max_step_s = coupling_step_limit(state_, deck_);
    log_set_up(log_, state_, deck_, record_.max_step_s, outdir_);
  }
}

void RunSession::write_files_of_checkpoint() {
  write_series_csv(outdir_ + "/series.csv", record_.series);
  if (deck_.mechanics) {
    reactions_csv_.write();
    cracks_csv_.write();
  }
  if (surface_edges_) surface_csv_.write();
  if (network_)
    for (const CsvTable* table : {&network_csv_, &cells_csv_, &junctions_csv_}) table->write();
  write_summary(record_.finished, deck_.mechanics ? take_crack_census(state_, deck_.crack_width_threshold_m).closed : 0);
}

void RunSession::write_row(bool completed) {
  const State& s = state_;
  // A plan view's network at every row (doc/outputs.md "network.csv"); its cells and
  // junctions at every frame.
  const NetworkCensus network = network_ ? take_network_census(s.nodes, s.triangles, s.joints, s.materials,
                                                               s.material_names.size())
                                         : NetworkCensus{};
  if (network_) network_csv_.append(network_csv_row(s.time_s, network));
  if (s.time_s >= double(record_.next_frame) * deck_.output_interval_s * (1.0 - 1e-12) || completed) {
    // The fragments the broken joints cut the solid into, for ParaView to colour.
    write_frame(frames_, s, s.time_s,
                network_ ? network.cell_of_triangle
                         : deck_.mechanics ? fragment_cells(s.triangles, s.joints, s.materials) : std::vector<index_t>{});
    if (surface_edges_) surface_csv_.append(surface_csv_rows(s.time_s, surface_profile(s.nodes, *surface_edges_)));
    if (network_) {
      cells_csv_.append(cells_csv_rows(s.time_s, network));
      junctions_csv_.append(junctions_csv_rows(s.time_s, network));
    }
    record_.next_frame = std::uint64_t(std::lround(std::floor(s.time_s / deck_.output_interval_s * (1.0 + 1e-12)))) + 1;
  }
  const CrackCensus census = deck_.mechanics ? take_crack_census(s, deck_.crack_width_threshold_m) : CrackCensus{};
  record_.series.rows.push_back(series_row(s, deck_, right_end_, census.open));
  write_series_csv(outdir_ + "/series.csv", record_.series);
  if (deck_.mechanics) {
    reactions_csv_.append(reactions_csv_rows(s.time_s, s.nodes, s.mechanics_boundaries));
    cracks_csv_.append(cracks_csv_rows(s.time_s, census.open));
    warn_capped_relaxations();
  }
  write_summary(completed, census.closed);
}

void RunSession::warn_capped_relaxations() {
  const std::uint64_t capped = state_.mechanics.capped_relaxations;
  if (capped <= record_.capped_reported) return;
  std::ostringstream w;
  w << capped - record_.capped_reported << " relaxation(s) up to t = " << state_.time_s
    << " s stopped at the step cap (solver.relaxation_max_steps = " << deck_.relaxation_max_steps
    << ") above the tolerance; last residual " << state_.mechanics.last_residual;
  log_.warning(w.str());
  record_.capped_reported = capped;
}

void RunSession::write_summary(bool completed, int closed_cracks) {
  write_file_atomically(outdir_ + "/summary.json",
                        summary_json(deck_, state_, record_.series, closed_cracks, progress_.wall_s(), completed).dump());
}

bool RunSession::checkpoint_due() const {
  return (options_.checkpoint_every_steps > 0 &&
          state_.coupling_steps >= checkpoint_steps_ + options_.checkpoint_every_steps) ||
         (options_.checkpoint_every_s > 0 && progress_.wall_s() >= checkpoint_wall_s_ + options_.checkpoint_every_s);
}

std::string RunSession::write_checkpoint() {
  record_.frame_times = frames_.times;
  record_.cracks_rows = cracks_csv_.rows;
  record_.surface_rows = surface_csv_.rows;
  record_.network_rows = network_csv_.rows;
  record_.cells_rows = cells_csv_.rows;
  record_.junctions_rows = junctions_csv_.rows;
  record_.reactions_rows = reactions_csv_.rows;
  const std::string path = checkpoint_path(outdir_, deck_.name, state_.coupling_steps);
  std::filesystem::create_directories(outdir_ + "/checkpoints");
  write_file_atomically(path, checkpoint_bytes(deck_, deck_text_, state_, record_));
  checkpoint_steps_ = state_.coupling_steps;
  checkpoint_wall_s_ = progress_.wall_s();
  return path;
}

bool RunSession::advance_to_row(double row_time_s) {
  while (state_.time_s < row_time_s) {
    // Advance in chunks so the progress line stays live on long intervals. A chunk that a
    // checkpoint cut is continued to its end, where the solid relaxes, as it would have been.
    if (!(record_.chunk_until_s > state_.time_s))
      record_.chunk_until_s = std::min(row_time_s, state_.time_s + 1000 * record_.max_step_s);
    record_.max_step_s = advance_to(state_, deck_, record_.chunk_until_s, record_.max_step_s,
                                    [&] { return interrupt_signal() != 0 || checkpoint_due(); },
                                    [&](std::int64_t steps, double residual) {
                                      progress_.relaxing(state_.time_s, state_.coupling_steps, steps, residual);
                                    });
    progress_.update(state_.time_s, state_.coupling_steps);
    if (interrupt_signal() != 0) return false;
    if (checkpoint_due()) write_checkpoint();
  }
  return true;
}

int RunSession::stop_interrupted() {
  const std::string path = write_checkpoint();
  progress_.finish(state_.time_s, state_.coupling_steps);
  std::ostringstream w;
  w << (interrupt_signal() == SIGINT ? "SIGINT" : "SIGTERM") << " at t = " << state_.time_s
    << " s: stopped after coupling step " << state_.coupling_steps << ", checkpoint " << path
    << "; the frames and rows up to t = " << record_.series.rows.back()[0]
    << " s are written; continue with: ydry --restart " << path;
  log_.warning(w.str());
  return 130;
}

int RunSession::stop_failed(const NumericalFailure& failure) {
  // The state as it failed, for inspection: a last frame and a row, summary completed = false.
  progress_.finish(state_.time_s, state_.coupling_steps);
  log_.warning(std::string(failure.what()) + "; the state as it failed is the last frame of " + outdir_ + "/" +
               deck_.name + ".pvd");
  record_.next_frame = 0;
  write_row(false);
  return 3;
}

void RunSession::finish() {
  const std::string final_checkpoint = write_checkpoint();
  progress_.finish(state_.time_s, state_.coupling_steps);
  log_end(log_, state_, deck_, progress_.wall_s(),
          outdir_ + "/" + deck_.name + ".pvd, series.csv, " + (deck_.mechanics ? "cracks.csv, reactions.csv, " : "") +
              (surface_edges_ ? "surface.csv, " : "") + (network_ ? "network.csv, cells.csv, junctions.csv, " : "") +
              "summary.json, deck.toml, log.txt, " + final_checkpoint);
}

int RunSession::run_to_end() {
  try {
    while (!record_.finished) {
      if (!advance_to_row(std::min(deck_.end_time_s, double(record_.row) * deck_.series_interval_s)))
        return stop_interrupted();
      write_row(state_.time_s >= deck_.end_time_s);
      record_.finished = state_.time_s >= deck_.end_time_s;
      ++record_.row;
    }
  } catch (const NumericalFailure& failure) {
    return stop_failed(failure);
  }
  finish();
  return 0;
}

}  // namespace ydry
