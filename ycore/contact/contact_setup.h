// Setting up the contact: the penalty, friction per material pair, the broad-phase buffer,
// and the surfaces (contact_setup.cpp; doc/physics.md "Contact and friction").
#pragma once

#include <string>
#include <vector>

#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry {

// Penalty, friction table and buffer from the deck, then the surfaces (needs
// nodes.tie_group): writes `contact`. Called by init_mechanics.
void init_contact(const Nodes& nodes, const Joints& joints, const std::vector<std::string>& material_names,
                  const Deck& deck, Contact& contact);

// Rebuilds the surfaces after joints broke (nodes.tie_group must be current) and forces a
// broad phase at the next force evaluation. Friction history of pairs that survive is kept.
void refresh_contact_surfaces(const Nodes& nodes, const Joints& joints, Contact& contact);

// Upper bound of the stiffness one node can get from contact, N/m (for the stable step).
double contact_stiffness_bound(const Mechanics& mechanics, const Contact& contact);

}  // namespace ydry
