#include "tests/test_support.h"

#include <sys/wait.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

namespace ydry_test {

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

}  // namespace ydry_test
