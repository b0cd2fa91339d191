// Moisture diffusion on the merged-node topology (paper Eqs. 1-8), with boundary flux,
// exchange and fixed values, explicit in time.
#pragma once

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// Sets up the moisture model on a built state whose moisture nodes are grouped (ycrack):
// initial w, dry masses, triangle conductances, boundary terms from the deck's
// [[moisture.boundary]] entries and from the faces of broken joints ([moisture.cracks],
// Eqs. 10-17), fixed values, and the water balance's starting point.
void init_moisture(State& state, const Deck& deck);

// After the moisture nodes were regrouped (ycrack, when joints broke): each new node takes
// the w of the node it was part of, its share of dry mass and of the boundary terms, and the
// faces of the joints that broke get their exchange terms; the water in the soil is unchanged.
// old_mnode and old_w are nodes.mnode and moisture.w before.
void remap_moisture_nodes(State& state, const Deck& deck, const std::vector<index_t>& old_mnode,
                          const std::vector<double>& old_w);

// The largest explicit step that is stable for every moisture node, times `safety`
// (Gershgorin: dt <= 2 m_i / (K_ii + sum_j |K_ij| + exchange_i); for the usual M-matrix,
// m_i / K_ii). Infinite when nothing diffuses or exchanges.
double stable_moisture_step(const State& state, double safety);

// One explicit step of Eq. 7: corner inflows per triangle (Eq. 4), gathered per moisture node
// (Eq. 5) with its boundary terms, w advanced, fixed nodes reset; the water that crossed the
// boundary is booked in state.water. No node is written by two threads.
void moisture_step(State& state, double dt);

// Each triangle's shrinkage strain eps_sh = alpha (max(w, w_s) - w_i) from the mean moisture
// of its corners (Eq. 18); the solid turns it into the stress 3 K* eps_sh (Eq. 19).
void update_shrinkage_strain(State& state);

double total_water_kg(const State& state);
double mean_moisture(const State& state);  // water / dry mass over all moisture nodes
// |water now - water at start - net in| / max(water at start, water that crossed boundaries).
double water_balance_error(const State& state);

}  // namespace ydry
