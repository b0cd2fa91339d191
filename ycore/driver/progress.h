// Progress on stderr: simulated time, percent, steps, wall time and ETA (at the pace of this
// process, which a restart begins part way). On a terminal one line updated in place (at most
// 5 times a second); otherwise a plain line every `every_s`. A relaxation that runs on past
// that adds its step count and out-of-balance ratio to the line.
#pragma once

#include <chrono>
#include <cstdint>

namespace ydry {

struct Progress {
  bool enabled = true;
  bool terminal = false;
  double every_s = 10.0;
  double end_time_s = 0;
  double start_time_s = 0;  // simulated time this process began at (a restart's is later)
  std::chrono::steady_clock::time_point started, last_printed;

  void start(double end_time, bool quiet, double plain_every_s);
  void update(double time_s, std::uint64_t steps, bool force = false);
  // The line of update, with the relaxation under way at its `relaxation_steps`-th step.
  void relaxing(double time_s, std::uint64_t steps, std::int64_t relaxation_steps, double residual);
  void finish(double time_s, std::uint64_t steps);
  double wall_s() const;

 private:
  void print(double time_s, std::uint64_t steps, bool force, const char* relaxation);
};

}  // namespace ydry
