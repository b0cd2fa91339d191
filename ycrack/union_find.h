// Union-find over dense indices. The smaller root always wins, so a set's root is its
// smallest member whatever the order of the unions.
#pragma once

#include <algorithm>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

inline index_t find_root(std::vector<index_t>& parent, index_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

inline void unite(std::vector<index_t>& parent, index_t a, index_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

}  // namespace ydry
