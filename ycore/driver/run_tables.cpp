#include "ycore/driver/run_tables.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "version.h"
#include "ycore/solid/energies.h"
#include "ycore/state/stage_timing.h"
#include "ycrack/interface_debonding.h"
#include "ymoist/moisture_step.h"

namespace ydry {

std::vector<index_t> right_end_corners(const State& s) {
  const Nodes& n = s.nodes;
  std::vector<index_t> corners;
  double best_x = -INFINITY, best_y = -INFINITY, span = 0;
  for (std::size_t i = 0; i < n.size(); ++i) span = std::max({span, std::fabs(n.x0[i]), std::fabs(n.y0[i])});
  const double tolerance = 1e-9 * span;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const MaterialModel& m = s.materials[s.triangles.material[triangle_of(index_t(i))]];
    if (!m.mechanical || !m.breakable) continue;
    const bool further = n.x0[i] > best_x + tolerance ||
                         (n.x0[i] > best_x - tolerance && n.y0[i] > best_y + tolerance);
    if (further) best_x = n.x0[i], best_y = n.y0[i], corners.clear();
    if (std::fabs(n.x0[i] - best_x) <= tolerance && std::fabs(n.y0[i] - best_y) <= tolerance)
      corners.push_back(index_t(i));
  }
  return corners;
}

std::vector<double> series_row(const State& s, const Deck& deck, const std::vector<index_t>& right_end,
                               const std::vector<Crack>& crack_list) {
  SeriesValues v;
  v.time_s = s.time_s;
  if (s.moisture.size() > 0) {
    v.mean_moisture = mean_moisture(s.moisture);
    v.water_lost_kg = s.water.initial_kg - total_water_kg(s.moisture);
    v.water_balance_error = water_balance_error(s.moisture, s.water);
  }
  if (!deck.mechanics)
    return series_csv_row(v, std::vector<double>(s.interface_names.size(), SeriesValues::kNaN));
  const CrackSummary cracks = summarize_cracks(crack_list);
  v.crack_count = double(cracks.count);
  v.mean_crack_width_m = cracks.mean_width_m;
  v.total_crack_width_m = cracks.total_width_m;
  v.mean_crack_length_m = cracks.mean_length_m;
  v.surface_crack_count = double(cracks.surface_count);
  v.mean_surface_crack_width_m = cracks.surface_mean_width_m;
  v.total_surface_crack_width_m = cracks.surface_total_width_m;
  if (!right_end.empty()) {
    v.right_end_displacement_m = 0;
    for (const index_t i : right_end) v.right_end_displacement_m += (s.nodes.x[i] - s.nodes.x0[i]) / right_end.size();
  }
  const Energies e = energies(s);
  v.kinetic_energy_J = e.kinetic_J;
  v.relaxation_residual = s.mechanics.last_residual;
  v.broken_joints = double(std::count(s.joints.broken.begin(), s.joints.broken.end(), 1));
  v.elastic_energy_J = e.elastic_J;
  v.joint_work_J = e.joint_work_J;
  v.fracture_energy_J = e.fracture_J;
  v.contact_work_J = e.contact_work_J;
  v.substrate_energy_J = e.substrate_elastic_J;
  v.substrate_slide_work_J = e.substrate_slide_work_J;
  v.external_work_J = e.external_work_J;
  v.gravity_work_J = e.gravity_work_J;
  v.mechanical_steps = double(s.mechanics.steps);
  return series_csv_row(v, interface_debonded_lengths(s));
}

JsonObject summary_json(const Deck& deck, const State& s, const Series& series, int closed_cracks, double wall_s,
                        bool completed) {
  JsonObject j;
  j.text("name", deck.name);
  j.text("version", std::string(YDRY_VERSION) + " (" + YDRY_COMMIT + ")");
  for (std::size_t c = 0; c < series.columns.size(); ++c) j.number(series.columns[c], series.rows.back()[c]);
  j.integer("threads", omp_get_max_threads());
  j.number("wall_s", wall_s);
  for (const auto& [name, seconds] : wall_by_stage(s.wall, wall_s)) j.number("wall_" + name + "_s", seconds);
  j.integer("elements", static_cast<long long>(s.triangles.size()));
  j.integer("joints", static_cast<long long>(s.joints.size()));
  j.integer("moisture_nodes", static_cast<long long>(s.moisture.size()));
  j.integer("moisture_steps", static_cast<long long>(s.coupling_steps));  // the coupling steps
  if (deck.mechanics) j.integer("closed_crack_count", closed_cracks);
  if (deck.mechanics && !deck.dynamic) {  // how well the equilibria converged
    j.integer("capped_relaxations", static_cast<long long>(s.mechanics.capped_relaxations));
    j.number("worst_relaxation_residual", s.mechanics.worst_residual);
    j.integer("friction_slide_relaxations", static_cast<long long>(s.mechanics.friction_slide_relaxations));
  }
  if (deck.relaxation == RelaxationMethod::newton)
    j.integer("newton_fallbacks", static_cast<long long>(s.mechanics.newton_fallbacks));
  j.boolean("completed", completed);
  return j;
}

}  // namespace ydry
