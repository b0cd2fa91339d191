// Strength heterogeneity ([materials.NAME] strength_heterogeneity, doc/physics.md "Strength
// heterogeneity"): every joint of a breakable material carries a random factor on its tensile
// strength and cohesion, Weibull-distributed with mean 1 and the material's coefficient of
// variation.
//
// A factor is a pure function of run.seed and the joint's mesh edge (its two vertex ids,
// sorted) through the splitmix64 hash: no generator state is carried from joint to joint, so
// the factors do not depend on the order in which joints are stored or visited, nor on the
// thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

// The Weibull distribution of mean 1, sampled as scale (-ln U)^inverse_shape for U uniform
// in (0, 1).
struct UnitMeanWeibull {
  double inverse_shape = 0;  // 1 / k, k the Weibull modulus; 0: every factor is exactly 1
  double scale = 1;          // 1 / Gamma(1 + 1/k): the mean is 1
};

// The one whose coefficient of variation is cv, in [0, 1] (so k >= 1).
UnitMeanWeibull unit_mean_weibull(double cv);

// The factor of the joint on the mesh edge between vertex_a and vertex_b (either order).
double strength_factor(std::uint64_t seed, index_t vertex_a, index_t vertex_b, const UnitMeanWeibull& weibull);

// joints.strength_factor of every joint: drawn where the joint's law is breakable with a
// strength_heterogeneity above 0, exactly 1 elsewhere. The vertex ids are nodes.vertex.
void set_strength_factors(Joints& joints, const Nodes& nodes, const std::vector<MaterialModel>& materials,
                          std::uint64_t seed);

// The factors of one material's joints, for the log.
struct StrengthFactorRange {
  std::size_t joints = 0;
  double min = 0, mean = 0, max = 0;
};
StrengthFactorRange strength_factor_range(const Joints& joints, std::uint16_t material);

}  // namespace ydry
