#include "ycore/driver/progress.h"

#include <unistd.h>

#include <cstdio>

namespace ydry {
namespace {

void format_duration(char* buf, std::size_t size, double s) {
  const long total = static_cast<long>(s + 0.5);
  std::snprintf(buf, size, "%02ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
}

}  // namespace

void Progress::start(double end_time, bool quiet, double plain_every_s) {
  enabled = !quiet;
  terminal = isatty(STDERR_FILENO);
  every_s = plain_every_s;
  end_time_s = end_time;
  started = last_printed = std::chrono::steady_clock::now();
}

double Progress::wall_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void Progress::update(double time_s, std::uint64_t steps, bool force) { print(time_s, steps, force, ""); }

void Progress::relaxing(double time_s, std::uint64_t steps, std::int64_t relaxation_steps, double residual) {
  char relaxation[96];
  std::snprintf(relaxation, sizeof relaxation, "  relaxing: step %lld, out-of-balance ratio %.3g",
                static_cast<long long>(relaxation_steps), residual);
  print(time_s, steps, false, relaxation);
}

void Progress::print(double time_s, std::uint64_t steps, bool force, const char* relaxation) {
  if (!enabled) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_printed).count();
  if (!force && since < (terminal ? 0.2 : every_s)) return;
  last_printed = now;
  const double fraction = end_time_s > 0 ? time_s / end_time_s : 1.0;
  const double wall = wall_s();
  char wall_text[32], eta_text[32];
  format_duration(wall_text, sizeof wall_text, wall);
  const double done = end_time_s > 0 ? (time_s - start_time_s) / end_time_s : 0.0;  // by this process
  if (done > 0)
    format_duration(eta_text, sizeof eta_text, wall * (1.0 - fraction) / done);
  else
    std::snprintf(eta_text, sizeof eta_text, "--:--:--");
  std::fprintf(stderr, "%st = %.4g / %.4g s (%5.1f%%)  moisture steps %llu  wall %s  ETA %s%s%s",
               terminal ? "\r\033[K" : "", time_s, end_time_s, 100.0 * fraction,
               static_cast<unsigned long long>(steps), wall_text, eta_text, relaxation, terminal ? "" : "\n");
  std::fflush(stderr);
}

void Progress::finish(double time_s, std::uint64_t steps) {
  update(time_s, steps, true);
  if (enabled && terminal) std::fputc('\n', stderr);
}

}  // namespace ydry
