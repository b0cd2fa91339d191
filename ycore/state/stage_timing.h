// Where a run's wall time goes, stage by stage, as LAMMPS breaks down its loop time at the end
// of every run: the stages add their own wall time as they go, and the run prints the split
// in log.txt's last lines and writes it to summary.json. Wall time only: no result depends on
// it, and a checkpoint does not keep it (a restarted run's split covers its own process, as
// its wall_s does).
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace ydry {

struct StageSeconds {
  double moisture = 0;  // moisture steps (Eqs. 1-17) and the shrinkage strain (Eq. 18)
  double elements = 0;  // the relaxation's integration and the triangles' forces
  double joints = 0;    // joint forces
  double contact = 0;   // contact search and forces
  double gather = 0;    // joint and contact forces into the nodes, and the relaxation's measures
  double solve = 0;     // Newton's tangents, sparse factorisations and solves, and its booking
                        // of the joints' work
  double cracking = 0;  // damage commit, and the node ties and moisture nodes split after breakage
  double total() const { return moisture + elements + joints + contact + gather + solve + cracking; }
};

// The stages by name, then "other": the rest of wall_s (the set-up but for its initial
// equilibrium's force passes, output, checkpoints, the relaxations' own bookkeeping).
std::vector<std::pair<std::string, double>> wall_by_stage(const StageSeconds& stages, double wall_s);

// "wall time by stage: moisture 1.23 s (3.4 %), elements ...": the end of log.txt.
std::string wall_by_stage_text(const StageSeconds& stages, double wall_s);

// Laps of the wall clock: lap(stage) adds the time since the last lap (or since the clock was
// made) to that stage. The clock is the one wall_s is read from (Progress), so the stages
// fall within it.
class StageClock {
 public:
  StageClock();
  void lap(double& stage_s);

 private:
  std::chrono::steady_clock::time_point last_;
};

}  // namespace ydry
