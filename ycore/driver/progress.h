// Progress on stderr: simulated time, percent, steps, wall time and ETA (at the pace of this
// process, which a restart begins part way). On a terminal one line updated in place (at most
// 5 times a second); otherwise a plain line every `every_s`.
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
  void finish(double time_s, std::uint64_t steps);
  double wall_s() const;
};

}  // namespace ydry
