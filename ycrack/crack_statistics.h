// Cracks as DESIGN section 5 defines them: connected sets of broken joints, each measured at
// its mouth, for series.csv and cracks.csv.
#pragma once

#include <vector>

#include "ycore/state.h"

namespace ydry {

struct Crack {
  double x_m = 0;            // current x of the mouth: mean of its corners in the crack's material
  double width_m = 0;        // normal opening at the mouth (the largest of the joints there)
  double length_m = 0;       // sum of the current lengths of its joints
  bool penetrating = false;  // reaches the bottom of its material's layer
  std::vector<index_t> joints;  // ascending: its broken and process-zone joints
};

// Committed damage from which a joint that has not broken belongs to the process zone of a
// crack (z(0.5) = 0.30: it carries less than a third of its strength).
constexpr double kProcessZoneDamage = 0.5;

// The cracks wider than width_threshold_m, ordered by x_m. Open joints sharing a mesh vertex
// belong to one crack: broken joints, and joints in a crack's process zone (two of three
// points at D >= kProcessZoneDamage), which link the broken stretches of a crack that
// zig-zags; a set of open joints without a broken one is no crack. Length and penetration
// count broken joints only; the mouth and the width may lie on a process-zone joint. The mouth is the crack's highest vertex (by initial y) on a free or
// interface surface, an edge that no joint sits on; a crack touching none (internal) is
// measured at its highest vertex. Penetrating: some vertex within 1e-6 of the layer height of
// the lowest initial y of the joint's material. O(nodes + joints), deterministic.
std::vector<Crack> find_cracks(const State& state, double width_threshold_m);

struct CrackSummary {
  int count = 0;
  double mean_width_m = 0, total_width_m = 0, mean_length_m = 0;  // means NaN without cracks
};
CrackSummary summarize_cracks(const std::vector<Crack>& cracks);

}  // namespace ydry
