// The machine's memory bandwidth, the ceiling of a mechanical step on a mesh larger than the
// cache: the rectangle's step streams some 215 MB of node, triangle and joint data
// (bench/RESULTS.md, "Log": what "memory" is), so its element-steps/s are read against this
// figure. The STREAM triad a[i] = b[i] + s c[i] over three arrays of 256 MiB (far beyond any
// cache), best of five, at 1 thread and at all threads; bytes counted as STREAM counts them
// (two read, one written: 24 per index). A figure to report, never asserted.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

constexpr std::size_t kLength = std::size_t(1) << 25;  // doubles per array: 256 MiB
constexpr int kRepeats = 5;

double triad_gigabytes_per_second(int threads) {
  omp_set_num_threads(threads);
  // Left uninitialised by new[], so that the first touch is the loop below, by the threads
  // that use each part (a vector would zero them all on this thread first).
  const std::unique_ptr<double[]> a(new double[kLength]), b(new double[kLength]), c(new double[kLength]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < kLength; ++i) a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;
  double best = 1e30;
  for (int r = 0; r < kRepeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < kLength; ++i) a[i] = b[i] + 1.5 * c[i];
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (a[kLength / 2] != 4.0) {  // 1 + 1.5 x 2: a loop the compiler kept
    std::fprintf(stderr, "bench_memory: the triad computed %g, not 4\n", a[kLength / 2]);
    std::exit(1);
  }
  return 3.0 * sizeof(double) * double(kLength) / best / 1e9;
}

}  // namespace

int main() {
  const int max_threads = omp_get_max_threads();
  const double one = triad_gigabytes_per_second(1);
  const double all = triad_gigabytes_per_second(max_threads);
  std::printf("memory: STREAM triad over 3 x 256 MiB, best of %d: %.1f GB/s at 1 thread, %.1f GB/s at %d threads\n",
              kRepeats, one, all, max_threads);
  return 0;
}
