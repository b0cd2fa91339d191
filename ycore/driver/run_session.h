// A run of a deck, from its start or from a checkpoint (doc/architecture.md "The run"): the
// output folder and its files, the loop of rows and frames around the coupling steps,
// checkpoints, interruption and numerical failure.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ycore/driver/progress.h"
#include "ycore/driver/run.h"
#include "ycore/output/checkpoint.h"
#include "ycore/output/csv_table.h"
#include "ycore/output/log_file.h"
#include "ycore/output/vtk_output.h"
#include "ycore/solid/numerical_failure.h"

namespace ydry {

class RunSession {
 public:
  // Reads the deck (or the checkpoint), checks the output folder, sets up the state (its
  // initial equilibrium included) and makes the folder ready: the files of t = 0, or, on a
  // restart, the files as they were when the checkpoint was written.
  explicit RunSession(const RunOptions& options);

  // Rows of the tables every series_interval, a frame at the first row at or after each
  // multiple of output_interval, until end_time. Returns the exit code: 0 done, 130
  // interrupted (a checkpoint written), 3 numerical failure (the state as it failed written).
  int run_to_end();

 private:
  void start_log();
  void write_files_of_checkpoint();
  void write_row(bool completed);
  void warn_capped_relaxations();
  void write_summary(bool completed, int closed_cracks);
  // Coupling steps up to the row's time, with checkpoints when due; false when interrupted.
  bool advance_to_row(double row_time_s);
  bool checkpoint_due() const;
  std::string write_checkpoint();
  int stop_interrupted();
  int stop_failed(const NumericalFailure& failure);
  void finish();

  const RunOptions& options_;
  const bool restart_;
  const Checkpoint checkpoint_;
  const Deck deck_;
  const std::string deck_text_;
  const std::string outdir_;
  Progress progress_;  // its wall time counts the set-up too: it holds the initial equilibrium
  State state_;
  RunRecord record_;
  FrameSeries frames_;
  Log log_;
  std::vector<index_t> right_end_;      // corners whose x-displacement series.csv reports
  const std::vector<index_t>* surface_edges_ = nullptr;  // the edges surface.csv profiles; none: no file
  CsvTable cracks_csv_, surface_csv_, reactions_csv_;
  bool network_ = false;  // a plan view with its solid: network.csv, cells.csv, junctions.csv
  CsvTable network_csv_, cells_csv_, junctions_csv_;
  std::uint64_t checkpoint_steps_ = 0;  // coupling steps at the last checkpoint
  double checkpoint_wall_s_ = 0;        // and its wall time
};

}  // namespace ydry
