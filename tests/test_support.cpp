#include "tests/test_support.h"

#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "ycore/solid/energies.h"
#include "ycore/state/state_fields.h"

namespace ydry_test {

const char* const kPeronDeck = YDRY_SOURCE_DIR "/inputs/peron/peron.toml";
const std::vector<std::string> kCrackingLayer = {
    "mesh.file=\"" YDRY_SOURCE_DIR "/tests/data/notched_layer.msh\"",
    "run.end_time=3000",
    "run.output_interval=1500",
    "run.series_interval=1000",
    "solver.mechanics_interval=1000",
    "materials.soil.shrinkage_coefficient=0.4",
    "materials.soil.gf_I=0.02",
    "solver.relaxation_tolerance=1e-4",
    "solver.relaxation_max_steps=3000",
    "solver.joint_penalty=100.0",
    "contact.penalty=4.0e7"};

namespace {

// A field of the state as doubles: a number, or an array of numbers, flags or enumerators.
template <class T>
std::vector<double> as_doubles(const T& value) {
  if constexpr (std::is_arithmetic_v<T>) {
    return {double(value)};
  } else {
    std::vector<double> out;
    out.reserve(value.size());
    for (const auto v : value) out.push_back(double(v));
    return out;
  }
}

}  // namespace

Snapshot state_snapshot(const ydry::State& s) {
  Snapshot snapshot;
  const auto take = [&](const std::string& name, const auto& value) { snapshot[name] = as_doubles(value); };
  ydry::for_each_history_field(s, take);
  ydry::for_each_topology_field(s, take);
  const ydry::Energies e = ydry::energies(s);
  snapshot["energies"] = {e.kinetic_J,        e.elastic_J,           e.joint_work_J,
                          e.fracture_J,       e.contact_work_J,      e.substrate_elastic_J,
                          e.substrate_slide_work_J, e.external_work_J, e.gravity_work_J};
  return snapshot;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

std::string without_run_facts(const std::string& text) {
  static const std::regex facts(R"("threads": \d+|"wall(_[a-z]+)?_s": [^,\n]+|\d+ threads|wall [^ ,\n]+ s|wall time by stage: [^\n]*)");
  return std::regex_replace(text, facts, "<run fact>");
}

bool same_but_run_facts(const std::filesystem::path& a, const std::filesystem::path& b) {
  return without_run_facts(read_text(a.string())) == without_run_facts(read_text(b.string()));
}

std::vector<std::string> files_under(const std::filesystem::path& folder) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(std::filesystem::relative(entry.path(), folder).string());
  std::sort(files.begin(), files.end());
  return files;
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path = std::filesystem::temp_directory_path() /
         ("ydry_test_" + std::to_string(std::random_device{}()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(path);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path, ignored);
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

ydry::Deck strip_deck(const std::vector<std::string>& overrides) {
  return ydry::load_deck(YDRY_SOURCE_DIR "/verification/strip1d/strip1d.toml", overrides);
}

ydry::Deck block_deck(TempDir& dir, const std::string& pattern, const std::vector<std::string>& sets) {
  write_text(dir.file("block.toml"), R"(
[run]
name = "block"
end_time = 1.0
output_interval = 1.0
gravity = [0.0, 0.0]
[mesh]
generator = "rectangle"
size = [0.004, 0.003]
element_size = 0.001
pattern = ")" + pattern + R"("
material = "soil"
[materials.soil]
density = 1000.0
young = 1.0e6
poisson = 0.25
tensile_strength = 1.0e4
cohesion = 2.0e4
friction_angle = 30.0
gf_I = 1.0
gf_II = 3.0
)");
  return ydry::load_deck(dir.file("block.toml"), sets);
}

const std::string kOneTriangleMsh =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n1\n2 1 \"soil\"\n$EndPhysicalNames\n"
    "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 1 0\n$EndEntities\n"
    "$Nodes\n1 3 10 30\n2 1 0 3\n10\n20\n30\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
    "$Elements\n1 1 1 1\n2 1 2 1\n1 30 10 20\n$EndElements\n";

CommandResult run_ydry(const std::string& arguments) {
  const std::string command = std::string(YDRY_EXECUTABLE) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) output.append(buf, n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::uint16_t material_id(const ydry::State& state, const std::string& name) {
  const auto it = std::find(state.material_names.begin(), state.material_names.end(), name);
  if (it == state.material_names.end()) throw std::out_of_range("no material " + name);
  return std::uint16_t(it - state.material_names.begin());
}

}  // namespace ydry_test
