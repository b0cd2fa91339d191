// Cracks: connected sets of broken joints, each measured at its mouth, for series.csv and
// cracks.csv (doc/measures.md "Crack statistics").
#pragma once

#include <vector>

#include "ycore/state/state.h"

namespace ydry {

struct Crack {
  double x_m = 0;            // current x of the mouth: mean of its corners in the crack's material
  double width_m = 0;        // normal opening at the mouth (the largest of the joints there)
  double length_m = 0;       // sum of the current lengths of its broken joints
  bool penetrating = false;  // reaches the bottom of its material's layer, or a debonding interface
  bool on_top_surface = false;  // its mouth is on the outer boundary facing up (seen from above)
  std::vector<index_t> joints;  // ascending: its broken and process-zone joints
};

// Committed damage from which a joint that has not broken belongs to the process zone of a
// crack (z(0.5) = 0.30: it carries less than a third of its strength).
constexpr double kProcessZoneDamage = 0.5;

// Every crack, however wide or closed, ordered by x_m. Open joints sharing a mesh vertex
// belong to one crack: broken joints, and joints in a crack's process zone (two of three
// points at D >= kProcessZoneDamage), which link the broken stretches of a crack that
// zig-zags; a set of open joints without a broken one is no crack. Length and penetration
// count broken joints only; the mouth and the width may lie on a process-zone joint. The mouth
// is the crack's highest vertex (by initial y; of equals, the one where a joint of the crack
// opens widest) on the top surface (an edge of one triangle whose
// outward normal is within 45 degrees of up: what an observer sees from above), else the
// highest on the rest of the outer boundary (a layer's end or underside), else the highest on
// an interface between materials (an edge two triangles share without a joint: a crack opening
// from a base), else its highest vertex (an internal crack). Penetrating: some vertex within 1e-6 of the layer height of
// the lowest initial y of the joint's material, or on a bonded interface that is debonding
// there (a broken interface joint, or one in its process zone). A bonded interface's joints
// are never part of a crack: their breaking is debonding (interface_debonded_lengths).
// O(nodes log nodes + joints), deterministic.
std::vector<Crack> find_all_cracks(const State& state);

// The cracks of find_all_cracks wider than width_threshold_m (open, ordered by x_m), and the
// number of the others (closed): closed again after opening (their faces pressed together, or
// slid along each other), or never opened past the threshold. Closed cracks still block the
// moisture and hold broken joints, but series.csv and cracks.csv do not count them.
struct CrackCensus {
  std::vector<Crack> open;
  int closed = 0;
};
CrackCensus take_crack_census(const State& state, double width_threshold_m);

// The open cracks of take_crack_census.
std::vector<Crack> find_cracks(const State& state, double width_threshold_m);

// All cracks, and those that open on the top surface: the cracks an experimenter counts and
// measures from above (paper Fig. 19: seven surface cracks; a crack rising from the base is
// seen only in section).
struct CrackSummary {
  int count = 0;
  double mean_width_m = 0, total_width_m = 0, mean_length_m = 0;  // means NaN without cracks
  int surface_count = 0;
  double surface_mean_width_m = 0, surface_total_width_m = 0;
};
CrackSummary summarize_cracks(const std::vector<Crack>& cracks);

}  // namespace ydry
