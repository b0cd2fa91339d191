// The solid's energy ledger, logged and written to series.csv (energies.cpp;
// doc/measures.md "Energies and water balance").
#pragma once

#include "ycore/state/state.h"

namespace ydry {

struct Energies {
  double kinetic_J = 0;      // physical masses and velocities
  double elastic_J = 0;      // strain energy of the triangles
  double joint_work_J = 0;   // work done on all joints since t = 0
  double fracture_J = 0;     // work done on the joints that broke (all of it dissipated)
  double contact_work_J = 0; // work done on the contacts: friction and the normal dashpot
                             // dissipate it, the penalty stores some of it
  double substrate_elastic_J = 0;     // stored by the plan view's substrate tractions
  double substrate_slide_work_J = 0;  // dissipated by its slides since t = 0
  double external_work_J = 0;  // through fixed and driven boundaries
  double gravity_work_J = 0;
};

// Reads the nodes, triangles, joints, materials and the work books of the mechanics, contact
// and boundaries: most of the solid, so it takes the state.
Energies energies(const State& state);

}  // namespace ydry
