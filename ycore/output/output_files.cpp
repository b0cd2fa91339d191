#include "ycore/output/output_files.h"


#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "ycore/input/input_error.h"

namespace fs = std::filesystem;

namespace ydry {
namespace {

// Marks a folder as a ydry output folder, so a later run may reuse it without --force.
constexpr const char* kMarker = ".ydry-output";

}  // namespace

const std::vector<SeriesColumn> kSeriesColumns = {
    {"time_s", &SeriesValues::time_s},
    {"mean_moisture", &SeriesValues::mean_moisture},
    {"water_lost_kg", &SeriesValues::water_lost_kg},
    {"water_balance_error", &SeriesValues::water_balance_error},
    {"crack_count", &SeriesValues::crack_count},
    {"mean_crack_width_m", &SeriesValues::mean_crack_width_m},
    {"total_crack_width_m", &SeriesValues::total_crack_width_m},
    {"mean_crack_length_m", &SeriesValues::mean_crack_length_m},
    {"surface_crack_count", &SeriesValues::surface_crack_count},
    {"mean_surface_crack_width_m", &SeriesValues::mean_surface_crack_width_m},
    {"total_surface_crack_width_m", &SeriesValues::total_surface_crack_width_m},
    {"right_end_displacement_m", &SeriesValues::right_end_displacement_m},
    {"kinetic_energy_J", &SeriesValues::kinetic_energy_J},
    {"relaxation_residual", &SeriesValues::relaxation_residual},
    {"broken_joints", &SeriesValues::broken_joints},
    {"elastic_energy_J", &SeriesValues::elastic_energy_J},
    {"joint_work_J", &SeriesValues::joint_work_J},
    {"fracture_energy_J", &SeriesValues::fracture_energy_J},
    {"contact_work_J", &SeriesValues::contact_work_J},
    {"substrate_energy_J", &SeriesValues::substrate_energy_J},
    {"substrate_slide_work_J", &SeriesValues::substrate_slide_work_J},
    {"external_work_J", &SeriesValues::external_work_J},
    {"gravity_work_J", &SeriesValues::gravity_work_J},
    {"mechanical_steps", &SeriesValues::mechanical_steps}};

std::vector<std::string> series_columns(const std::vector<std::string>& interface_names) {
  std::vector<std::string> columns;
  for (const SeriesColumn& column : kSeriesColumns) columns.emplace_back(column.name);
  for (const std::string& name : interface_names) columns.push_back("debonded_length_" + name);
  return columns;
}

std::vector<double> series_csv_row(const SeriesValues& values, const std::vector<double>& debonded_lengths) {
  std::vector<double> row;
  row.reserve(kSeriesColumns.size() + debonded_lengths.size());
  for (const SeriesColumn& column : kSeriesColumns) row.push_back(values.*column.value);
  row.insert(row.end(), debonded_lengths.begin(), debonded_lengths.end());
  return row;
}

std::string format_double(double v) {
  if (std::isnan(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << content;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  fs::rename(tmp, path);
}

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void check_output_dir(const std::string& outdir, bool force) {
  const fs::path dir(outdir);
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InputError(outdir + ": output path exists and is not a folder");
  if (fs::exists(dir) && !fs::is_empty(dir) && !fs::exists(dir / kMarker) && !force)
    throw InputError(outdir + ": output folder is not empty and holds no earlier ydry run "
                              "(use --force to write into it anyway)");
}

void prepare_output_dir(const std::string& outdir, bool force) {
  check_output_dir(outdir, force);
  const fs::path dir(outdir);
  if (fs::exists(dir / kMarker)) {  // an earlier run's outputs would mix with this run's: remove them
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      const std::string ext = entry.path().extension().string();
      if (name == "frames" || name == "checkpoints" || ext == ".pvd" || ext == ".csv" ||
          ext == ".json" || name == "deck.toml" || name == "log.txt" || ext == ".tmp")
        fs::remove_all(entry.path());
    }
  }
  fs::create_directories(dir / "frames");
  write_file_atomically((dir / kMarker).string(), "This folder holds ydry output; ydry may overwrite it.\n");
}

void check_resume_dir(const std::string& outdir, const std::string& deck_text) {
  const fs::path dir(outdir);
  if (!fs::exists(dir / kMarker))
    throw InputError(outdir + ": holds no ydry run to continue (a restart writes into the run's own output folder, "
                              "which holds the frames written before the checkpoint)");
  if (read_file((dir / "deck.toml").string()) != deck_text)
    throw InputError(outdir + ": holds another run than the checkpoint's (its deck.toml is not the checkpoint's)");
}

void resume_output_dir(const std::string& outdir, const std::string& deck_text) {
  check_resume_dir(outdir, deck_text);
  const fs::path dir(outdir);
  for (const fs::path& folder : {dir, dir / "frames", dir / "checkpoints"}) {
    if (!fs::is_directory(folder)) continue;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".tmp") fs::remove(entry.path());
  }
}

void write_series_csv(const std::string& path, const Series& series) {
  std::ostringstream out;
  for (std::size_t c = 0; c < series.columns.size(); ++c) out << (c ? "," : "") << series.columns[c];
  out << "\n";
  for (const auto& row : series.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << format_double(row[c]);
    out << "\n";
  }
  write_file_atomically(path, out.str());
}

}  // namespace ydry
