#include "ycore/driver/run_log.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "version.h"
#include "ycore/solid/energies.h"
#include "ycore/solid/strength_heterogeneity.h"
#include "ycore/state/stage_timing.h"
#include "ymoist/moisture_step.h"

namespace ydry {
namespace {

// A material's strength heterogeneity: the distribution asked for and what the joints drew.
std::string strength_factor_line(const State& s, std::size_t material, std::int64_t seed) {
  const double cv = s.materials[material].strength_heterogeneity;
  const StrengthFactorRange r = strength_factor_range(s.joints, std::uint16_t(material));
  std::ostringstream line;
  line << "materials." << s.material_names[material] << ": strength factors of " << r.joints
       << " joints (Weibull, mean 1, coefficient of variation " << cv << ", modulus "
       << 1.0 / unit_mean_weibull(cv).inverse_shape << ", seed " << seed << "): min " << r.min << ", mean "
       << r.mean << ", max " << r.max;
  return line.str();
}

// A bonded interface: its joints and the properties they carry (doc/physics.md "Interface joints").
std::string interface_line(const State& s, std::size_t interface) {
  const std::size_t id = s.material_names.size() + interface;
  const std::size_t joints = std::size_t(std::count(s.joints.law.begin(), s.joints.law.end(), std::uint16_t(id)));
  const MaterialModel& m = s.materials[id];
  std::ostringstream line;
  line << "interfaces." << s.interface_names[interface] << ": " << joints << " bonded joints, tensile strength "
       << m.tensile_strength << " Pa, cohesion " << m.cohesion << " Pa, friction angle "
       << std::atan(m.tan_friction) * 180.0 / M_PI << " degrees, gf_I " << m.gf_I << " J/m^2, gf_II " << m.gf_II
       << " J/m^2, penalty " << m.penalty << " Pa";
  return line.str();
}

std::string steps_line(const State& state, const Deck& deck, double max_step_s) {
  std::ostringstream steps;
  steps << "coupling step " << max_step_s << " s (moisture safety " << deck.moisture_safety << ")";
  if (deck.mechanics)
    steps << "; mechanical pseudo-step " << state.mechanics.step_s << " s, joint penalty "
          << deck.joint_penalty << " E, "
          << (deck.dynamic                                     ? "no"
              : deck.relaxation == RelaxationMethod::fire   ? "FIRE"
              : deck.relaxation == RelaxationMethod::newton ? "Newton"
                                                            : "viscous")
          << " relaxation, tolerance " << deck.relaxation_tolerance << ", cap "
          << deck.relaxation_max_steps << " steps, relaxation every " << deck.mechanics_interval_s
          << " s of moisture time (0: every step); initial equilibrium in " << state.mechanics.steps
          << " steps, residual " << state.mechanics.last_residual << "; contact penalty "
          << state.contact.penalty_pa << " Pa, damping " << state.contact.damping_ratio << " of critical, "
          << state.contact.surface_edge.size() << " surface edges"
          << (deck.dynamic ? "; dynamic: the solid moves in real time" : "");
  return steps.str();
}

}  // namespace

std::string ydry_version_text() { return std::string(YDRY_VERSION) + " (" + YDRY_COMMIT + ")"; }

void log_set_up(Log& log, const State& state, const Deck& deck, double max_step_s, const std::string& outdir) {
  std::ostringstream head;
  head << "ydry " << ydry_version_text() << ", deck " << deck.path << ", " << omp_get_max_threads() << " threads\n"
       << "mesh: " << state.triangles.size() << " triangles, " << state.joints.size() << " joints, "
       << state.moisture.size() << " moisture nodes";
  log.info(head.str());
  std::vector<std::uint8_t> material_used(state.material_names.size(), 0);
  for (const std::uint16_t m : state.triangles.material) material_used[m] = 1;
  for (std::size_t m = 0; m < material_used.size(); ++m)
    if (!material_used[m])
      log.warning("[materials." + state.material_names[m] + "] is not used by any triangle of the mesh");
  if (deck.mechanics)
    for (std::size_t m = 0; m < state.materials.size(); ++m)
      if (state.materials[m].strength_heterogeneity > 0.0) log.info(strength_factor_line(state, m, deck.seed));
  for (std::size_t i = 0; i < state.interface_names.size(); ++i) log.info(interface_line(state, i));
  log.info(steps_line(state, deck, max_step_s) + "; output to " + outdir);
}

void log_restart(Log& log, const State& state, const std::string& checkpoint_path,
                 const std::string& checkpoint_version, const std::string& outdir) {
  std::ostringstream line;
  line << "ydry " << ydry_version_text() << ", " << omp_get_max_threads() << " threads: restart from "
       << checkpoint_path << " at t = " << state.time_s << " s (coupling step " << state.coupling_steps
       << "); output to " << outdir;
  log.info(line.str());
  if (checkpoint_version != ydry_version_text())
    log.warning("the checkpoint was written by ydry " + checkpoint_version + ", this is " + ydry_version_text() +
                ": the run may not go on as it would have");
}

void log_end(Log& log, const State& state, const Deck& deck, double wall_s, const std::string& outputs) {
  std::ostringstream tail;
  tail << "done: t = " << state.time_s << " s, " << state.coupling_steps << " coupling steps, "
       << "mean moisture " << mean_moisture(state.moisture) << ", water balance error "
       << water_balance_error(state.moisture, state.water)
       << ", wall " << wall_s << " s\n";
  if (deck.mechanics) {
    const Energies e = energies(state);
    tail << "solid: " << state.mechanics.steps << " mechanical steps, "
         << std::count(state.joints.broken.begin(), state.joints.broken.end(), 1) << " broken joints; energies (J): "
         << "elastic " << e.elastic_J << ", joint work " << e.joint_work_J << " (fracture " << e.fracture_J
         << "), external work " << e.external_work_J << ", gravity work " << e.gravity_work_J << ", kinetic "
         << e.kinetic_J << "\n";
    if (!deck.dynamic) {
      tail << "equilibria: " << state.mechanics.capped_relaxations << " relaxation(s) stopped at the step cap, worst "
           << "residual " << state.mechanics.worst_residual << ", " << state.mechanics.friction_slide_relaxations
           << " with the friction sliding at every step after solver.relaxation_slide_after = "
           << deck.relaxation_slide_after << " steps";
      if (deck.relaxation == RelaxationMethod::newton)
        tail << ", " << state.mechanics.newton_fallbacks << " Newton relaxation(s) finished by FIRE";
      tail << "\n";
    }
  }
  tail << wall_by_stage_text(state.wall, wall_s) << "\n" << "outputs: " << outputs;
  log.info(tail.str());
}

}  // namespace ydry
