// The run's output folder, series.csv and the atomic writes every output file but the log
// goes through (a temporary name and a rename, so a crash never leaves a truncated file).
// summary.json: json_object.h; log.txt: log_file.h.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ydry {

// Writes `content` to `path` through `path`.tmp and a rename.
void write_file_atomically(const std::string& path, const std::string& content);

// The bytes of a file; nothing when it cannot be read.
std::optional<std::string> read_file(const std::string& path);

// A number as the CSV files write it: round-trip precision (%.17g), "nan" for NaN.
std::string format_double(double v);

// InputError unless OUTDIR can take a new run: absent, empty, or holding an earlier ydry run,
// or anything else with `force`. Changes nothing: run() calls it before the set-up (the
// initial equilibrium can take minutes), so a wrong -o is reported at once.
void check_output_dir(const std::string& outdir, bool force);
// Makes OUTDIR ready after check_output_dir: creates it, and removes an earlier run's outputs.
void prepare_output_dir(const std::string& outdir, bool force);

// InputError unless OUTDIR holds a ydry run whose deck.toml is `deck_text`, the run a
// checkpoint continues. Changes nothing (called before the set-up, like check_output_dir).
void check_resume_dir(const std::string& outdir, const std::string& deck_text);
// Makes a run's own OUTDIR ready for its restart after check_resume_dir: removes the temporary
// files a killed process may have left (NAME.tmp, in it, frames/ and checkpoints/), and keeps
// everything else for the restart.
void resume_output_dir(const std::string& outdir, const std::string& deck_text);

// The values of a row of series.csv that every run has, each named as its column
// (doc/outputs.md "series.csv"); NaN for what the run does not compute.
struct SeriesValues {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double time_s = kNaN, mean_moisture = kNaN, water_lost_kg = kNaN, water_balance_error = kNaN;
  double crack_count = kNaN, mean_crack_width_m = kNaN, total_crack_width_m = kNaN, mean_crack_length_m = kNaN;
  double surface_crack_count = kNaN, mean_surface_crack_width_m = kNaN, total_surface_crack_width_m = kNaN;
  double right_end_displacement_m = kNaN, kinetic_energy_J = kNaN, relaxation_residual = kNaN, broken_joints = kNaN;
  double elastic_energy_J = kNaN, joint_work_J = kNaN, fracture_energy_J = kNaN, contact_work_J = kNaN,
         substrate_energy_J = kNaN, substrate_slide_work_J = kNaN, external_work_J = kNaN, gravity_work_J = kNaN;
  double mechanical_steps = kNaN;
};

// A column of series.csv that every run has: its header and its value in a row.
struct SeriesColumn {
  const char* name;
  double SeriesValues::*value;
};

// The columns of series.csv that every run has, in order (doc/outputs.md "Files of a run");
// summary.json repeats the last row.
extern const std::vector<SeriesColumn> kSeriesColumns;
// A run's columns: kSeriesColumns, then debonded_length_NAME for each bonded interface NAME.
std::vector<std::string> series_columns(const std::vector<std::string>& interface_names);
// A row in the order of series_columns: `values` by kSeriesColumns, then the debonded
// length of each bonded interface, in the order of the names series_columns was given.
std::vector<double> series_csv_row(const SeriesValues& values, const std::vector<double>& debonded_lengths);

struct Series {
  std::vector<std::string> columns;       // series_columns of the run
  std::vector<std::vector<double>> rows;  // one per output time, in the columns' order
};
void write_series_csv(const std::string& path, const Series& series);

}  // namespace ydry
