#include "ycore/driver/run.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "version.h"
#include "ycore/state/build_state.h"
#include "ycore/output/checkpoint.h"
#include "ycore/driver/interruption.h"
#include "ycore/input/input_error.h"
#include "ycore/output/output_files.h"
#include "ycore/driver/progress.h"
#include "ycore/state/stage_timing.h"
#include "ycore/solid/strength_heterogeneity.h"
#include "ycore/output/vtk_output.h"
#include "ycore/contact/contact.h"
#include "ycore/solid/mechanics.h"
#include "ycore/solid/numerical_failure.h"
#include "ycrack/crack_statistics.h"
#include "ycrack/cracks_csv.h"
#include "ycrack/node_sharing.h"
#include "ycrack/precracks.h"
#include "ycrack/surface_profile.h"
#include "ymoist/moisture.h"

namespace ydry {
namespace {

bool any_moisture(const State& s) { return s.moisture.size() > 0; }

std::vector<std::uint8_t> triangles_with_moisture(const State& s, const Deck& deck) {
  std::vector<std::uint8_t> flags(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    flags[t] = deck.materials.at(s.material_names[s.triangles.material[t]]).has_moisture();
  return flags;
}

RelaxationControls relaxation_controls(const Deck& deck) {
  return {deck.relaxation_tolerance, deck.relaxation_max_steps, deck.relaxation};
}

// The corners of the top-right vertex of the breakable material (the largest x, then the
// largest y there): right_end_displacement_m is their mean x-displacement (DESIGN 5).
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

// The log's account of a material's strength heterogeneity: the distribution asked for and
// what the joints drew.
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

std::vector<double> series_row(const State& s, const Deck& deck, const std::vector<index_t>& right_end,
                               const std::vector<Crack>& crack_list) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool moisture = any_moisture(s);
  std::vector<double> row = {s.time_s,
                             moisture ? mean_moisture(s) : nan,
                             moisture ? s.water.initial_kg - total_water_kg(s) : nan,
                             moisture ? water_balance_error(s) : nan};
  if (!deck.mechanics) {
    row.resize(kSeriesColumns.size(), nan);
    return row;
  }
  const CrackSummary cracks = summarize_cracks(crack_list);
  double right_end_ux = nan;
  if (!right_end.empty()) {
    right_end_ux = 0;
    for (const index_t i : right_end) right_end_ux += (s.nodes.x[i] - s.nodes.x0[i]) / right_end.size();
  }
  const Energies e = energies(s);
  const double broken = double(std::count(s.joints.broken.begin(), s.joints.broken.end(), 1));
  row.insert(row.end(), {double(cracks.count), cracks.mean_width_m, cracks.total_width_m, cracks.mean_length_m,
                         double(cracks.surface_count), cracks.surface_mean_width_m, cracks.surface_total_width_m,
                         right_end_ux, e.kinetic_J, s.mechanics.last_residual, broken, e.elastic_J,
                         e.joint_work_J, e.fracture_J, e.contact_work_J, e.external_work_J, e.gravity_work_J,
                         double(s.mechanics.steps)});
  return row;
}

JsonObject summary_json(const Deck& deck, const State& s, const Series& series, int closed_cracks, double wall_s,
                        bool completed) {
  JsonObject j;
  j.text("name", deck.name);
  j.text("version", std::string(YDRY_VERSION) + " (" + YDRY_COMMIT + ")");
  for (std::size_t c = 0; c < kSeriesColumns.size(); ++c) j.number(kSeriesColumns[c], series.rows.back()[c]);
  j.integer("threads", omp_get_max_threads());
  j.number("wall_s", wall_s);
  for (const auto& [name, seconds] : wall_by_stage(s.wall, wall_s)) j.number("wall_" + name + "_s", seconds);
  j.integer("elements", static_cast<long long>(s.triangles.size()));
  j.integer("joints", static_cast<long long>(s.joints.size()));
  j.integer("moisture_nodes", static_cast<long long>(s.moisture.size()));
  j.integer("moisture_steps", static_cast<long long>(s.moisture_steps));
  if (deck.mechanics) j.integer("closed_crack_count", closed_cracks);
  j.boolean("completed", completed);
  return j;
}

// reactions.csv: per output time and [[mechanics.boundary]], the support force and the mean
// displacement of the boundary's nodes.
void append_reactions(std::string& rows, const State& s) {
  std::ostringstream csv;
  for (const MechanicsBoundary& b : s.mechanics_boundaries) {
    double ux = 0, uy = 0;
    for (const index_t i : b.nodes) {
      ux += (s.nodes.x[i] - s.nodes.x0[i]) / b.nodes.size();
      uy += (s.nodes.y[i] - s.nodes.y0[i]) / b.nodes.size();
    }
    csv << std::setprecision(17) << s.time_s << ',' << b.name << ',' << b.reaction_x << ',' << b.reaction_y
        << ',' << ux << ',' << uy << ',' << b.work_J << '\n';
  }
  rows += csv.str();
}

// Step 4 of the loop, after joints broke: the corners are tied anew, the moisture nodes split
// across the broken joints (water is conserved), and their faces become contact surfaces.
void split_across_broken_joints(State& s, const Deck& deck) {
  if (any_moisture(s)) {
    const std::vector<index_t> old_mnode = s.nodes.mnode;
    const std::vector<double> old_w = s.moisture.w;
    group_moisture_nodes(s.joints, triangles_with_moisture(s, deck), s.nodes, s.moisture);
    remap_moisture_nodes(s, deck, old_mnode, old_w);
  } else {
    tie_corners(s.joints, s.nodes);
  }
  refresh_contact_surfaces(s);
}

// The log's first lines on a new run: the code, the deck, the mesh and the steps.
void log_set_up(Log& log, const State& state, const Deck& deck, double max_step, const std::string& outdir) {
  std::ostringstream head;
  head << "ydry " << YDRY_VERSION << " (" << YDRY_COMMIT << "), deck " << deck.path << ", "
       << omp_get_max_threads() << " threads\n"
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
  std::ostringstream steps;
  steps << "coupling step " << max_step << " s (moisture safety " << deck.moisture_safety << ")";
  if (deck.mechanics)
    steps << "; mechanical pseudo-step " << state.mechanics.step_s << " s, joint penalty "
          << deck.joint_penalty << " E, "
          << (deck.dynamic ? "no" : deck.relaxation == RelaxationMethod::fire ? "FIRE" : "viscous")
          << " relaxation, tolerance " << deck.relaxation_tolerance << ", cap "
          << deck.relaxation_max_steps << " steps, relaxation every " << deck.mechanics_interval_s
          << " s of moisture time (0: every step); initial equilibrium in " << state.mechanics.steps
          << " steps, residual " << state.mechanics.last_residual << "; contact penalty "
          << state.contact.penalty_pa << " Pa, damping " << state.contact.damping_ratio << " of critical, "
          << state.contact.surface_edge.size() << " surface edges"
          << (deck.dynamic ? "; dynamic: the solid moves in real time" : "");
  log.info(steps.str() + "; output to " + outdir);
}

// A restart's output folder by default: the one that holds the checkpoint's checkpoints/.
std::string run_folder_of(const std::string& checkpoint) {
  const std::filesystem::path folder = std::filesystem::absolute(checkpoint).parent_path();
  if (folder.filename() != "checkpoints")
    throw InputError(checkpoint + ": not in a run's checkpoints/ folder; give the run's output folder with -o");
  return folder.parent_path().string();
}

}  // namespace

State prepare_state(const Deck& deck) {
  State s = build_state(load_mesh(deck), deck);
  break_joints_along_cracks(s, deck);
  const std::vector<std::uint8_t> has_moisture = triangles_with_moisture(s, deck);
  const bool moisture = std::any_of(has_moisture.begin(), has_moisture.end(), [](std::uint8_t h) { return h != 0; });
  if (!moisture && !deck.mechanics)
    throw InputError(deck.path + ": materials: no material of the mesh has moisture_conductivity, "
                                 "so a moisture-only run has nothing to compute");
  group_moisture_nodes(s.joints, has_moisture, s.nodes, s.moisture);
  if (moisture) init_moisture(s, deck);
  if (deck.mechanics) {
    init_mechanics(s, deck);
    update_shrinkage_strain(s);
  }
  return s;
}

State setup_state(const Deck& deck) {
  State s = prepare_state(deck);
  if (deck.mechanics && !deck.dynamic) {  // a dynamic run starts at rest in the mesh's geometry
    relax(s, relaxation_controls(deck), 0.0);  // the initial equilibrium
    if (commit_joint_damage(s) > 0) split_across_broken_joints(s, deck);
  }
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

int check(const RunOptions& opt) {
  if (!opt.restart_path.empty()) {
    const Checkpoint checkpoint = read_checkpoint_file(opt.restart_path);
    const Deck deck = checkpoint_deck(checkpoint, opt.restart_path, opt.deck_path, opt.overrides);
    const State state = state_from_checkpoint(deck, checkpoint);
    checkpoint_record(checkpoint, deck, state);
    std::cout << checkpoint_deck_text(checkpoint);
    std::cerr << "ydry check: " << opt.restart_path << " is a valid checkpoint of run " << deck.name << " at t = "
              << state.time_s << " s of " << deck.end_time_s << " s (coupling step " << state.moisture_steps
              << "), written by ydry " << checkpoint.ydry_version << "\n";
    return 0;
  }
  const Deck deck = load_deck(opt.deck_path, opt.overrides);
  const State state = prepare_state(deck);
  std::cout << resolved_deck_text(deck);
  std::ostringstream line;
  line << "ydry check: " << deck.path << " is valid: " << state.triangles.size() << " triangles, "
       << state.joints.size() << " joints, " << state.moisture.size() << " moisture nodes; coupling step "
       << coupling_step_limit(state, deck) << " s";
  if (deck.mechanics) line << ", mechanical pseudo-step " << state.mechanics.step_s << " s";
  std::cerr << line.str() << "\n";
  return 0;
}

double coupling_step_limit(const State& s, const Deck& deck) {
  double step = deck.output_interval_s;
  if (any_moisture(s)) step = std::min(step, stable_moisture_step(s, deck.moisture_safety));
  if (deck.max_coupling_step_s > 0.0) step = std::min(step, deck.max_coupling_step_s);
  return step;
}

bool coupling_step(State& s, const Deck& deck, double dt, bool relax_now) {
  StageClock clock;
  if (any_moisture(s)) moisture_step(s, dt);
  clock.lap(s.wall.moisture);
  if (!deck.mechanics) return false;
  s.mechanics.unrelaxed_s += dt;
  if (!relax_now && s.mechanics.unrelaxed_s < deck.mechanics_interval_s) return false;
  update_shrinkage_strain(s);
  clock.lap(s.wall.moisture);
  // The solid's force passes book their own stages (compute_forces).
  if (deck.dynamic)
    move_dynamically(s, s.mechanics.unrelaxed_s);
  else
    relax(s, relaxation_controls(deck), s.mechanics.unrelaxed_s);
  s.mechanics.unrelaxed_s = 0.0;
  StageClock cracking;
  const bool broke = commit_joint_damage(s) > 0;
  if (broke) split_across_broken_joints(s, deck);
  cracking.lap(s.wall.cracking);
  return broke && any_moisture(s);
}

double advance_to(State& s, const Deck& deck, double until_s, double max_step_s, const std::function<bool()>& pause) {
  while (s.time_s < until_s) {
    const double remaining = until_s - s.time_s;
    // The last step lands exactly on until_s (it is never longer than a stable step), and
    // the solid is in equilibrium there.
    const bool last = remaining <= max_step_s;
    const bool split = coupling_step(s, deck, last ? remaining : max_step_s, last);
    s.time_s = last ? until_s : s.time_s + max_step_s;
    ++s.moisture_steps;
    if (split) max_step_s = std::min(max_step_s, coupling_step_limit(s, deck));  // smaller nodes
    if (pause && pause()) break;
  }
  return max_step_s;
}

int run(const RunOptions& opt) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const InterruptWatch interrupts;  // SIGINT, SIGTERM: a checkpoint after the coupling step under way
  const bool restart = !opt.restart_path.empty();
  const Checkpoint checkpoint = restart ? read_checkpoint_file(opt.restart_path) : Checkpoint{};
  const Deck deck = restart ? checkpoint_deck(checkpoint, opt.restart_path, opt.deck_path, opt.overrides)
                            : load_deck(opt.deck_path, opt.overrides);
  const std::string deck_text = restart ? checkpoint_deck_text(checkpoint) : resolved_deck_text(deck);
  const std::string outdir = !opt.outdir.empty() ? opt.outdir
                             : restart           ? run_folder_of(opt.restart_path)
                                                 : "runs/" + deck.name;
  if (restart)
    check_resume_dir(outdir, deck_text);
  else
    check_output_dir(outdir, opt.force);
  Progress progress;  // wall time counts the set-up too: it holds the initial equilibrium
  progress.start(deck.end_time_s, opt.quiet, opt.progress_every_s);
  State state = restart ? state_from_checkpoint(deck, checkpoint) : setup_state(deck);
  RunRecord record = restart ? checkpoint_record(checkpoint, deck, state) : RunRecord{};
  progress.start_time_s = state.time_s;
  if (restart)
    resume_output_dir(outdir, deck_text);
  else
    prepare_output_dir(outdir, opt.force);

  FrameSeries frames{outdir, deck.name, {}, {}};
  if (restart) resume_frame_series(frames, record.frame_times);  // before anything is written
  write_file_atomically(outdir + "/deck.toml", deck_text);
  Log log;
  log.open(outdir + "/log.txt", opt.quiet, restart);
  if (restart) {
    std::ostringstream line;
    line << "ydry " << YDRY_VERSION << " (" << YDRY_COMMIT << "), " << omp_get_max_threads()
         << " threads: restart from " << opt.restart_path << " at t = " << state.time_s << " s (coupling step "
         << state.moisture_steps << "); output to " << outdir;
    log.info(line.str());
    const std::string version = std::string(YDRY_VERSION) + " (" + YDRY_COMMIT + ")";
    if (checkpoint.ydry_version != version)
      log.warning("the checkpoint was written by ydry " + checkpoint.ydry_version + ", this is " + version +
                  ": the run may not go on as it would have");
  } else {
    record.max_step_s = coupling_step_limit(state, deck);
    log_set_up(log, state, deck, record.max_step_s, outdir);
  }

  const std::vector<index_t> right_end = deck.mechanics ? right_end_corners(state) : std::vector<index_t>{};
  if (!restart) record.reactions_csv = "time_s,boundary,reaction_x_N,reaction_y_N,mean_ux_m,mean_uy_m,work_J\n";
  CracksCsv cracks_csv{outdir + "/cracks.csv", record.cracks_rows};
  // surface.csv profiles the boundary named "top" (the soil's free surface) at every frame.
  const auto top = state.boundary_edges.find("top");
  const bool surface = deck.mechanics && top != state.boundary_edges.end();
  if (deck.mechanics && !surface && !restart) log.info("no surface.csv: the mesh has no boundary named \"top\"");
  SurfaceCsv surface_csv{outdir + "/surface.csv", record.surface_rows};
  const auto write_summary = [&](bool completed, int closed_cracks) {
    write_file_atomically(outdir + "/summary.json",
                          summary_json(deck, state, record.series, closed_cracks, progress.wall_s(), completed).dump());
  };
  const auto write_outputs = [&](bool completed) {
    if (state.time_s >= double(record.next_frame) * deck.output_interval_s * (1.0 - 1e-12) || completed) {
      write_frame(frames, state, state.time_s);
      if (surface) append_surface_csv(surface_csv, state.time_s, surface_profile(state, top->second));
      record.next_frame = std::uint64_t(std::lround(std::floor(state.time_s / deck.output_interval_s * (1.0 + 1e-12)))) + 1;
    }
    const CrackCensus census = deck.mechanics ? take_crack_census(state, deck.crack_width_threshold_m) : CrackCensus{};
    const std::vector<Crack>& cracks = census.open;
    record.series.rows.push_back(series_row(state, deck, right_end, cracks));
    write_series_csv(outdir + "/series.csv", record.series);
    if (deck.mechanics) {
      append_reactions(record.reactions_csv, state);
      write_file_atomically(outdir + "/reactions.csv", record.reactions_csv);
      append_cracks_csv(cracks_csv, state.time_s, cracks);
      if (state.mechanics.capped_relaxations > record.capped_reported) {
        std::ostringstream w;
        w << state.mechanics.capped_relaxations - record.capped_reported << " relaxation(s) up to t = " << state.time_s
          << " s stopped at the step cap (solver.relaxation_max_steps = " << deck.relaxation_max_steps
          << ") above the tolerance; last residual " << state.mechanics.last_residual;
        log.warning(w.str());
        record.capped_reported = state.mechanics.capped_relaxations;
      }
    }
    write_summary(completed, census.closed);
  };
  if (restart) {  // the files as they were when the checkpoint was written
    write_series_csv(outdir + "/series.csv", record.series);
    if (deck.mechanics) {
      write_file_atomically(outdir + "/reactions.csv", record.reactions_csv);
      write_cracks_csv(cracks_csv);
    }
    if (surface) write_surface_csv(surface_csv);
    write_summary(record.finished, deck.mechanics ? take_crack_census(state, deck.crack_width_threshold_m).closed : 0);
  } else {
    write_outputs(false);
  }

  // Checkpoints: every checkpoint_every_steps coupling steps or checkpoint_every_s of wall time.
  std::uint64_t checkpoint_steps = state.moisture_steps;
  double checkpoint_wall_s = progress.wall_s();
  const auto checkpoint_due = [&] {
    return (opt.checkpoint_every_steps > 0 && state.moisture_steps >= checkpoint_steps + opt.checkpoint_every_steps) ||
           (opt.checkpoint_every_s > 0 && progress.wall_s() >= checkpoint_wall_s + opt.checkpoint_every_s);
  };
  const auto write_checkpoint = [&] {
    record.frame_times = frames.times;
    record.cracks_rows = cracks_csv.rows;
    record.surface_rows = surface_csv.rows;
    const std::string path = checkpoint_path(outdir, deck.name, state.moisture_steps);
    std::filesystem::create_directories(outdir + "/checkpoints");
    write_file_atomically(path, checkpoint_bytes(deck, deck_text, state, record));
    checkpoint_steps = state.moisture_steps;
    checkpoint_wall_s = progress.wall_s();
    return path;
  };

  // Rows of the tables every series_interval, frames at the first row at or after each
  // multiple of output_interval.
  try {
    while (!record.finished) {
      const double next_output = std::min(deck.end_time_s, double(record.row) * deck.series_interval_s);
      while (state.time_s < next_output) {
        // Advance in chunks so the progress line stays live on long intervals. A chunk that a
        // checkpoint cut is continued to its end, where the solid relaxes, as it would have been.
        if (!(record.chunk_until_s > state.time_s))
          record.chunk_until_s = std::min(next_output, state.time_s + 1000 * record.max_step_s);
        record.max_step_s = advance_to(state, deck, record.chunk_until_s, record.max_step_s,
                                       [&] { return interrupt_signal() != 0 || checkpoint_due(); });
        progress.update(state.time_s, state.moisture_steps);
        if (interrupt_signal() != 0) {
          const std::string path = write_checkpoint();
          progress.finish(state.time_s, state.moisture_steps);
          std::ostringstream w;
          w << (interrupt_signal() == SIGINT ? "SIGINT" : "SIGTERM") << " at t = " << state.time_s
            << " s: stopped after coupling step " << state.moisture_steps << ", checkpoint " << path
            << "; the frames and rows up to t = " << record.series.rows.back()[0]
            << " s are written; continue with: ydry --restart " << path;
          log.warning(w.str());
          return 130;
        }
        if (checkpoint_due()) write_checkpoint();
      }
      write_outputs(state.time_s >= deck.end_time_s);
      record.finished = state.time_s >= deck.end_time_s;
      ++record.row;
    }
  } catch (const NumericalFailure& failure) {
    // The state as it failed, for inspection: a last frame and a row, summary completed = false.
    progress.finish(state.time_s, state.moisture_steps);
    log.warning(std::string(failure.what()) + "; the state as it failed is the last frame of " + outdir + "/" +
                deck.name + ".pvd");
    record.next_frame = 0;
    write_outputs(false);
    return 3;
  }
  const std::string final_checkpoint = write_checkpoint();
  progress.finish(state.time_s, state.moisture_steps);

  const double wall_s = progress.wall_s();
  std::ostringstream tail;
  tail << "done: t = " << state.time_s << " s, " << state.moisture_steps << " moisture steps, "
       << "mean moisture " << mean_moisture(state) << ", water balance error "
       << water_balance_error(state) << ", wall " << wall_s << " s\n";
  if (deck.mechanics) {
    const Energies e = energies(state);
    tail << "solid: " << state.mechanics.steps << " mechanical steps, "
         << std::count(state.joints.broken.begin(), state.joints.broken.end(), 1) << " broken joints; energies (J): "
         << "elastic " << e.elastic_J << ", joint work " << e.joint_work_J << " (fracture " << e.fracture_J
         << "), external work " << e.external_work_J << ", gravity work " << e.gravity_work_J << ", kinetic "
         << e.kinetic_J << "\n";
  }
  tail << wall_by_stage_text(state.wall, wall_s) << "\n";
  tail
       << "outputs: " << outdir << "/" << deck.name << ".pvd, series.csv, "
       << (deck.mechanics ? "cracks.csv, reactions.csv, " : "") << (surface ? "surface.csv, " : "")
       << "summary.json, deck.toml, log.txt, " << final_checkpoint;
  log.info(tail.str());
  return 0;
}

}  // namespace ydry
