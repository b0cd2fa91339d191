#include "ycore/solid/joint_damage.h"

#include <algorithm>

#include "ycore/solid/joint_law.h"
#include "ycore/state/blocked_sum.h"

namespace ydry {

std::size_t commit_joint_damage(const Nodes& n, const Ownership& ownership, const std::vector<MaterialModel>& materials,
                                Joints& jt) {
  const auto broke = blocked_sum<1>(jt.size(), [&](std::size_t j, std::array<double, 1>& sum) {
    const MaterialModel& m = materials[jt.law[j]];
    if (jt.broken[j] || !m.mechanical || !m.breakable) return;
    const JointKinematics k = joint_kinematics(n, &jt.node[4 * j]);
    int failed = 0;
    for (int p = 0; p < 3; ++p) {
      const double a = kJointPointShareOfEnd0[p], b = 1.0 - a;
      double& d = jt.damage[3 * j + p];
      const double o = a * k.opening[0] + b * k.opening[1], sl = a * k.slip[0] + b * k.slip[1];
      d = std::max(d, cohesive_traction(m, jt.strength_factor[j], jt.length0[j], o, sl, d).damage);
      failed += d >= 1.0;
    }
    if (failed >= 2) {
      jt.broken[j] = 1;
      sum[0] += 1.0;
    }
  }, ownership.joint_begin);
  return std::size_t(broke[0]);
}

}  // namespace ydry
