#include "ycore/driver/setup.h"

#include <algorithm>

#include "ycore/driver/coupling.h"
#include "ycore/input/input_error.h"
#include "ycore/output/checkpoint.h"
#include "ycore/solid/mechanics_setup.h"
#include "ycore/state/build_state.h"
#include "ycrack/node_sharing.h"
#include "ycrack/precracks.h"
#include "ymoist/moisture_setup.h"
#include "ymoist/shrinkage.h"

namespace ydry {

State prepare_state(const Deck& deck) {
  State s = build_state(load_mesh(deck), deck);
  break_joints_along_cracks(s.nodes, deck.cracks, s.joints);
  const std::vector<std::uint8_t> has_moisture = triangles_with_moisture(s, deck);
  const bool moisture = std::any_of(has_moisture.begin(), has_moisture.end(), [](std::uint8_t h) { return h != 0; });
  if (!moisture && !deck.mechanics)
    throw InputError(deck.path + ": materials: no material of the mesh has moisture_conductivity, "
                                 "so a moisture-only run has nothing to compute");
  group_moisture_nodes(s.joints, s.triangles, has_moisture, s.nodes, s.moisture);
  if (moisture)
    init_moisture(moisture_mesh(s), deck, s.moisture,
                  s.moisture_elements, s.water);
  if (deck.mechanics) {
    init_mechanics(s, deck);
    update_shrinkage_strain(s.nodes, s.moisture, s.materials, s.triangles);
  }
  return s;
}

State setup_state(const Deck& deck) {
  State s = prepare_state(deck);
  // A dynamic run starts at rest in the mesh's geometry; a quasi-static one in equilibrium.
  if (deck.mechanics && !deck.dynamic) equilibrate_and_break(s, deck, 0.0);
  return s;
}

State state_from_checkpoint(const Deck& deck, const Checkpoint& checkpoint) {
  State s = prepare_state(deck);
  const std::vector<std::uint8_t> broken_at_set_up = s.joints.broken;
  restore_broken_joints(s, checkpoint);
  // Every break was followed by a split, whose result depends on the broken joints alone.
  if (s.joints.broken != broken_at_set_up) split_across_broken_joints(s, deck);
  restore_state(s, checkpoint);
  return s;
}

}  // namespace ydry
