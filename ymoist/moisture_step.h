// The explicit moisture step (paper Eqs. 1-8 with the boundary terms of Eqs. 10-17), its
// stable step size, and the water it keeps account of (doc/physics.md "Moisture diffusion",
// "Energies and water balance").
#pragma once

#include "ycore/state/state.h"

namespace ydry {

// The largest explicit step that is stable for every moisture node, times `safety`
// (Gershgorin: dt <= 2 m_i / (K_ii + sum_j |K_ij| + exchange_i); for the usual M-matrix,
// m_i / K_ii). Infinite when nothing diffuses or exchanges.
double stable_moisture_step(const MoistureNodes& moisture, const MoistureElements& elements, double safety);

// One explicit step of Eq. 7: corner inflows per triangle (Eq. 4, into elements.corner_inflow),
// gathered per moisture node (Eq. 5) with its boundary terms, w advanced, fixed nodes reset;
// the water that crossed the boundary is booked in `water`. Reads nodes.mnode. No node is
// written by two threads (doc/threading.md "Gather, not scatter").
void moisture_step(const Nodes& nodes, double dt, MoistureElements& elements, MoistureNodes& moisture,
                   WaterBalance& water);

// The water in the soil, kg: sum of w x dry mass over the moisture nodes (compensated).
double total_water_kg(const MoistureNodes& moisture);

// Water / dry mass over all moisture nodes; NaN without dry mass.
double mean_moisture(const MoistureNodes& moisture);

// |water now - water at start - net in| / max(water at start, water that crossed boundaries).
double water_balance_error(const MoistureNodes& moisture, const WaterBalance& water);

}  // namespace ydry
