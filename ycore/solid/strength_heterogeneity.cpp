#include "ycore/solid/strength_heterogeneity.h"

#include <algorithm>
#include <cmath>

namespace ydry {
namespace {

// Steele, Lea and Flood's splitmix64 finaliser: a bijection of 64-bit words that turns
// neighbouring inputs into statistically independent outputs (it passes BigCrush).
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Coefficient of variation of a Weibull distribution of shape 1 / x:
// CV^2 = Gamma(1 + 2x) / Gamma(1 + x)^2 - 1, written to keep its digits when x is small.
double weibull_cv(double x) { return std::sqrt(std::expm1(std::lgamma(1.0 + 2.0 * x) - 2.0 * std::lgamma(1.0 + x))); }

}  // namespace

UnitMeanWeibull unit_mean_weibull(double cv) {
  UnitMeanWeibull w;
  if (cv == 0.0) return w;
  // The CV rises monotonically from 0 at x = 0 to 1 at x = 1 (the exponential distribution).
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double x = 0.5 * (lo + hi);
    (weibull_cv(x) < cv ? lo : hi) = x;
  }
  w.inverse_shape = 0.5 * (lo + hi);
  w.scale = std::exp(-std::lgamma(1.0 + w.inverse_shape));
  return w;
}

double strength_factor(std::uint64_t seed, index_t vertex_a, index_t vertex_b, const UnitMeanWeibull& weibull) {
  const std::uint64_t bits = splitmix64(splitmix64(seed) ^ edge_key(vertex_a, vertex_b));
  const double u = (double(bits >> 12) + 0.5) * 0x1p-52;  // uniform in (0, 1), both ends excluded
  return weibull.scale * std::pow(-std::log(u), weibull.inverse_shape);
}

void set_strength_factors(Joints& jt, const Nodes& n, const std::vector<MaterialModel>& materials,
                          std::uint64_t seed) {
  std::vector<UnitMeanWeibull> weibull;
  for (const MaterialModel& m : materials)
    weibull.push_back(unit_mean_weibull(m.breakable ? m.strength_heterogeneity : 0.0));
  jt.strength_factor.assign(jt.size(), 1.0);
  for (std::size_t j = 0; j < jt.size(); ++j) {
    const UnitMeanWeibull& w = weibull[jt.law[j]];
    if (w.inverse_shape > 0.0)
      jt.strength_factor[j] = strength_factor(seed, n.vertex[jt.node[4 * j]], n.vertex[jt.node[4 * j + 1]], w);
  }
}

StrengthFactorRange strength_factor_range(const Joints& jt, std::uint16_t material) {
  StrengthFactorRange r;
  double sum = 0.0;
  for (std::size_t j = 0; j < jt.size(); ++j) {
    if (jt.law[j] != material) continue;
    const double f = jt.strength_factor[j];
    r.min = r.joints ? std::min(r.min, f) : f;
    r.max = r.joints ? std::max(r.max, f) : f;
    sum += f;
    ++r.joints;
  }
  if (r.joints) r.mean = sum / double(r.joints);
  return r;
}

}  // namespace ydry
