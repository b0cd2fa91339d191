#include "ycore/solid/solid_forces.h"

#include "ycore/solid/element_forces.h"
#include "ycore/solid/joint_forces.h"
#include "ycore/solid/joint_work.h"
#include "ycore/solid/substrate.h"
#include "ycore/state/blocked_sum.h"
#include "ycore/state/stage_timing.h"

namespace ydry {
namespace {

// Adds the joint and contact forces to the node forces (through each node's joint slots and
// contact gather list) and measures; the Rayleigh numerator's -v.f only (compute_forces adds
// v.f_previous).
ForceMeasures gather_interaction_forces(const Joints& joints, const Contact& c, const Ownership& ownership, Nodes& n,
                                        bool fire_measures) {
  const std::vector<double>& jf = joints.force;
  const bool contact = !c.gather_offset.empty();
  const auto sums = blocked_sum<6>(n.size(), [&](std::size_t i, std::array<double, 6>& sum) {
    double fx = n.fx[i], fy = n.fy[i];
    sum[1] += fx * fx + fy * fy;
    for (int k = 0; k < 2; ++k) {
      const index_t slot = n.joint_slot[2 * i + k];
      if (slot == kNoIndex) continue;
      fx += jf[2 * std::size_t(slot)];
      fy += jf[2 * std::size_t(slot) + 1];
    }
    if (contact)
      for (index_t k = c.gather_offset[i]; k < c.gather_offset[i + 1]; ++k) {
        fx += c.pair_force[2 * std::size_t(c.gather_entry[k])];
        fy += c.pair_force[2 * std::size_t(c.gather_entry[k]) + 1];
      }
    n.fx[i] = fx;
    n.fy[i] = fy;
    const auto measure = [&](double f, double u) {
      sum[0] += f * f;
      sum[2] -= u * f;
      sum[3] += n.m[i] * u * u;
      if (fire_measures) {  // a division per component: only where FIRE reads them
        sum[4] += f * u;
        sum[5] += f * f / n.m[i];
      }
    };
    if (!(n.constraint[i] & kFixX)) measure(fx, n.vx[i]);
    if (!(n.constraint[i] & kFixY)) measure(fy, n.vy[i]);
  }, ownership.node_begin);
  return {sums[0], sums[1], sums[2], sums[3], sums[4], sums[5]};
}

// Element forces and gravity (with `move`, the nodes first moved in the same pass), then the
// substrate's; returns the moved components' v.f_previous.
double element_stage(State& s, const VelocityUpdate* move) {
  StageClock clock;
  const double power_before = element_forces(s.triangles, s.mechanics, s.ownership, s.materials, s.nodes, move);
  add_substrate_forces(s.substrate, s.ownership, s.nodes);
  clock.lap(s.wall.elements);
  return power_before;
}

// The joints' and contacts' forces gathered onto the element forces, with the measures.
ForceMeasures interaction_stage(State& s, bool fire_measures) {
  StageClock clock;
  joint_forces(s.nodes, s.mechanics, s.ownership, s.materials, s.joints, s.joints.force);
  clock.lap(s.wall.joints);
  contact_forces(s.nodes, s.triangles, s.mechanics, s.contact, s.material_names.size(), s.contact.pair_force);
  clock.lap(s.wall.contact);
  const ForceMeasures measures = gather_interaction_forces(s.joints, s.contact, s.ownership, s.nodes, fire_measures);
  clock.lap(s.wall.gather);
  return measures;
}

}  // namespace

ForceMeasures compute_forces(State& s, bool fire_measures) {
  const double power_before = element_stage(s, nullptr);
  ForceMeasures measures = interaction_stage(s, fire_measures);
  measures.rayleigh_numerator += power_before;
  return measures;
}

ForceMeasures explicit_step(State& s, const VelocityUpdate* move, double dt, FrictionUpdate friction,
                            bool fire_measures, ForcesBefore& before) {
  const double power_before = element_stage(s, move);
  StageClock contact_phases;
  update_contact_pairs(s.nodes, s.ownership, s.contact);
  keep_contact_forces(s.contact, before.contact);
  advance_friction_slip(s.nodes, dt, s.contact);
  contact_phases.lap(s.wall.contact);
  // The joint kernel writes every joint of a material with mechanics; the others' forces are 0
  // in both buffers, so the two can change places instead of being copied.
  before.joint.resize(s.joints.force.size());
  before.joint.swap(s.joints.force);
  ForceMeasures measures = interaction_stage(s, fire_measures);
  measures.rayleigh_numerator += power_before;
  StageClock booking;
  book_joint_step_work(s.nodes, s.materials, before.joint, dt, s.joints);
  booking.lap(s.wall.joints);
  book_contact_work(s.nodes, before.contact, dt, s.contact);
  if (friction == FrictionUpdate::every_step)
    commit_friction_slip(s.nodes, s.triangles, s.mechanics, s.material_names.size(), s.contact);
  booking.lap(s.wall.contact);
  return measures;
}

}  // namespace ydry
