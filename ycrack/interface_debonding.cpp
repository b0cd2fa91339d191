#include "ycrack/interface_debonding.h"

namespace ydry {

std::vector<double> interface_debonded_lengths(const State& s) {
  const std::size_t nm = s.material_names.size();
  std::vector<double> length(s.interface_names.size(), 0.0);
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    if (is_interface_joint(s, j) && s.joints.broken[j]) length[s.joints.law[j] - nm] += s.joints.length0[j];
  return length;
}

}  // namespace ydry
