#include "ycore/state/stage_timing.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace ydry {

std::vector<std::pair<std::string, double>> wall_by_stage(const StageSeconds& w, double wall_s) {
  return {{"moisture", w.moisture}, {"elements", w.elements}, {"joints", w.joints},   {"contact", w.contact},
          {"gather", w.gather},     {"solve", w.solve},       {"cracking", w.cracking},
          {"other", std::max(0.0, wall_s - w.total())}};
}

std::string wall_by_stage_text(const StageSeconds& w, double wall_s) {
  std::ostringstream text;
  text << "wall time by stage:" << std::fixed;
  const char* separator = " ";
  for (const auto& [name, seconds] : wall_by_stage(w, wall_s)) {
    text << separator << name << ' ' << std::setprecision(seconds < 10.0 ? 2 : 0) << seconds << " s ("
         << std::setprecision(1) << (wall_s > 0.0 ? 100.0 * seconds / wall_s : 0.0) << " %)";
    separator = ", ";
  }
  return text.str();
}

StageClock::StageClock() : last_(std::chrono::steady_clock::now()) {}

void StageClock::lap(double& stage_s) {
  const auto now = std::chrono::steady_clock::now();
  stage_s += std::chrono::duration<double>(now - last_).count();
  last_ = now;
}

}  // namespace ydry
