// The threads' ranges of the solid (ycore/state/ownership.h).
#include "ycore/state/ownership.h"

#include <algorithm>

#include "ycore/state/state.h"

namespace ydry {

Ownership partition_for_threads(const Triangles& tri, const Joints& joints,
                                const std::vector<MaterialModel>& materials, std::size_t slots) {
  constexpr double kRigidShare = 0.1;  // a rigid triangle's work against a deformable one's
  const std::size_t nt = tri.size();
  std::vector<double> work(nt + 1, 0.0);  // prefix sums
  for (std::size_t t = 0; t < nt; ++t)
    work[t + 1] = work[t] + (materials[tri.material[t]].mechanical ? 1.0 : kRigidShare);
  Ownership o;
  o.triangle_begin.assign(slots + 1, nt);
  o.triangle_begin[0] = 0;
  for (std::size_t k = 1; k < slots; ++k)
    o.triangle_begin[k] =
        std::size_t(std::lower_bound(work.begin(), work.end(), work[nt] * double(k) / double(slots)) - work.begin());
  // A joint belongs with its first triangle (joints are numbered in that order; counting
  // them keeps the ranges a cut of [0, joints) whatever the order).
  std::vector<std::size_t> joints_in(slots, 0);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const std::size_t t = triangle_of(joints.node[4 * j]);
    const auto after = std::upper_bound(o.triangle_begin.begin(), o.triangle_begin.end(), t);
    ++joints_in[std::size_t(after - o.triangle_begin.begin()) - 1];
  }
  o.joint_begin.assign(slots + 1, 0);
  for (std::size_t k = 0; k < slots; ++k) o.joint_begin[k + 1] = o.joint_begin[k] + joints_in[k];
  o.node_begin.resize(slots + 1);
  for (std::size_t k = 0; k <= slots; ++k) o.node_begin[k] = 3 * o.triangle_begin[k];
  return o;
}

}  // namespace ydry
