#include "ycore/driver/coupling.h"

#include <algorithm>

#include "ycore/contact/contact_setup.h"
#include "ycore/solid/joint_damage.h"
#include "ycore/solid/relaxation.h"
#include "ycore/state/stage_timing.h"
#include "ycrack/node_sharing.h"
#include "ymoist/moisture_setup.h"
#include "ymoist/moisture_step.h"
#include "ymoist/shrinkage.h"

namespace ydry {
namespace {

bool any_moisture(const State& s) { return s.moisture.size() > 0; }

}  // namespace

std::vector<std::uint8_t> triangles_with_moisture(const State& s, const Deck& deck) {
  std::vector<std::uint8_t> flags(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    flags[t] = deck.materials.at(s.material_names[s.triangles.material[t]]).has_moisture();
  return flags;
}

void split_across_broken_joints(State& s, const Deck& deck) {
  if (any_moisture(s)) {
    const std::vector<index_t> old_mnode = s.nodes.mnode;
    const std::vector<double> old_w = s.moisture.w;
    group_moisture_nodes(s.joints, s.triangles, triangles_with_moisture(s, deck), s.nodes, s.moisture);
    remap_moisture_nodes(moisture_mesh(s), deck, old_mnode, old_w,
                         s.moisture);
  } else {
    tie_corners(s.joints, s.nodes);
  }
  refresh_contact_surfaces(s.nodes, s.joints, s.contact);
}

double coupling_step_limit(const State& s, const Deck& deck) {
  double step = deck.output_interval_s;
  if (any_moisture(s))
    step = std::min(step, stable_moisture_step(s.moisture, s.moisture_elements, deck.moisture_safety));
  if (deck.max_coupling_step_s > 0.0) step = std::min(step, deck.max_coupling_step_s);
  return step;
}

bool equilibrate_and_break(State& s, const Deck& deck, double dt, const RelaxationReport& report) {
  // The solid's force passes book their own stages.
  std::size_t broken = 0;
  if (deck.dynamic) {
    broken = move_dynamically(s, dt).joints_broken;  // the damage committed at each of its steps
  } else {
    relax(s, {deck.relaxation_tolerance, deck.relaxation_max_steps, deck.relaxation, deck.relaxation_slide_after, report}, dt);
    StageClock commit;
    broken = commit_joint_damage(s.nodes, s.ownership, s.materials, s.joints);
    commit.lap(s.wall.cracking);
  }
  if (broken == 0) return false;
  StageClock cracking;
  split_across_broken_joints(s, deck);
  cracking.lap(s.wall.cracking);
  return true;
}

bool coupling_step(State& s, const Deck& deck, double dt, bool relax_now, const RelaxationReport& report) {
  StageClock clock;
  if (any_moisture(s)) moisture_step(s.nodes, dt, s.moisture_elements, s.moisture, s.water);  // (1) Eqs. 1-17
  clock.lap(s.wall.moisture);
  if (!deck.mechanics) return false;
  s.mechanics.unrelaxed_s += dt;
  if (!relax_now && s.mechanics.unrelaxed_s < deck.mechanics_interval_s) return false;
  update_shrinkage_strain(s.nodes, s.moisture, s.materials, s.triangles);  // (2) Eqs. 18-19
  clock.lap(s.wall.moisture);
  const bool broke = equilibrate_and_break(s, deck, s.mechanics.unrelaxed_s, report);  // (3), (4)
  s.mechanics.unrelaxed_s = 0.0;
  return broke && any_moisture(s);
}

double advance_to(State& s, const Deck& deck, double until_s, double max_step_s, const std::function<bool()>& pause,
                  const RelaxationReport& report) {
  while (s.time_s < until_s) {
    const double remaining = until_s - s.time_s;
    // The last step lands exactly on until_s (it is never longer than a stable step), and
    // the solid is in equilibrium there.
    const bool last = remaining <= max_step_s;
    const bool split = coupling_step(s, deck, last ? remaining : max_step_s, last, report);
    s.time_s = last ? until_s : s.time_s + max_step_s;
    ++s.coupling_steps;
    if (split) max_step_s = std::min(max_step_s, coupling_step_limit(s, deck));  // smaller nodes
    if (pause && pause()) break;
  }
  return max_step_s;
}

}  // namespace ydry
