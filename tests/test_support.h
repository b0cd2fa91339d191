// Helpers shared by the unit tests: temporary folders, decks written from text, running the
// ydry executable.
#pragma once

#include <omp.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ycore/state/blocked_sum.h"
#include "ycore/input/deck.h"
#include "ycore/state/state.h"

namespace ydry_test {

// A fresh folder under the system temp directory, removed when the object goes.
struct TempDir {
  std::filesystem::path path;
  TempDir();
  ~TempDir();
  std::string file(const std::string& name) const { return (path / name).string(); }
};

// Writes `text` to `path`.
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);

// The strip of paper section 4.1 (verification/strip1d/strip1d.toml) with overrides.
ydry::Deck strip_deck(const std::vector<std::string>& overrides = {});

// A free-standing block of breakable soil (E = 1 MPa, 1000 kg/m^3), 4 x 3 mm in 1 mm cells of
// `pattern`, no gravity, no boundaries; written into `dir` and read with the overrides.
ydry::Deck block_deck(TempDir& dir, const std::string& pattern, const std::vector<std::string>& sets = {});

// The Peron deck on its 40 mm cousin tests/data/notched_layer.msh (642 triangles: soil on a
// rigid notched base, in contact and with friction from the start), the soil made to crack
// early (shrinkage coefficient 0.4, gf_I 0.02 J/m^2) and the relaxations kept short
// (tolerance 1e-4, cap 3000 steps), joints at 100 E and contact at 10 E (stiffer than the
// Peron deck's 10 E and E, at which no joint breaks by 3000 s): the first joint
// breaks by 2000 s, three by 3000 s, in some 10,000 steps; 105 coupling steps of 29.2 s,
// rows every 1000 s, frames every 1500 s.
extern const char* const kPeronDeck;
extern const std::vector<std::string> kCrackingLayer;

// A state's history and topology fields by name (ycore/state/state_fields.h), flags, indices
// and counts as doubles, and its energies.
using Snapshot = std::map<std::string, std::vector<double>>;
Snapshot state_snapshot(const ydry::State& state);

// The index of the material `name` in state.material_names; throws std::out_of_range if it has
// none.
std::uint16_t material_id(const ydry::State& state, const std::string& name);

// Whether two arrays hold the same bits.
bool same_bits(const std::vector<double>& a, const std::vector<double>& b);

// A file's text without the facts a run states about its execution: the thread count and the
// wall time (summary.json's "threads", "wall_s" and its split by stage, and the log's prose).
std::string without_run_facts(const std::string& text);
// Whether two files hold the same bytes but for the run facts.
bool same_but_run_facts(const std::filesystem::path& a, const std::filesystem::path& b);

// The files under `folder`, as paths relative to it, sorted.
std::vector<std::string> files_under(const std::filesystem::path& folder);

// Runs body(threads) on 1, then 2 OpenMP threads with every loop in parallel however short
// (parallel_minimum = 0), for the tests that results are bitwise the same on any thread
// count; the thread count and parallel_minimum are restored afterwards, even on a failure.
// Puts the thread count and parallel_minimum back as they were when it was made.
struct RestoreThreadSettings {
  std::size_t minimum = ydry::parallel_minimum;
  int threads = omp_get_max_threads();
  ~RestoreThreadSettings() {
    ydry::parallel_minimum = minimum;
    omp_set_num_threads(threads);
  }
};

template <class Body>
void on_1_and_2_threads(Body body) {
  RestoreThreadSettings restore;
  ydry::parallel_minimum = 0;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    body(threads);
  }
}

// A Gmsh 4.1 file of one triangle (sparse node tags 10, 20, 30) in surface 1 of physical
// surface "soil", and no physical curve. Line numbers: 10 the surface, 16 the second node
// tag, 19 its coordinates, 24 the element block header, 25 the element.
extern const std::string kOneTriangleMsh;

struct CommandResult {
  int exit_code;
  std::string output;  // stdout and stderr together
};
// Runs the built ydry with `arguments` (already shell-quoted).
CommandResult run_ydry(const std::string& arguments);

}  // namespace ydry_test
