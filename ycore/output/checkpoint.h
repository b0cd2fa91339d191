// What a checkpoint holds (its bytes: ycore/output/checkpoint_file.h): the resolved deck, the state a
// run changes, and the driver's record of the loop and of the outputs written so far, so that
// `ydry --restart FILE` needs nothing else and ends in the state and files an uninterrupted
// run ends in, bit for bit.
//
// What is not stored is rebuilt from the deck and the mesh (prepare_state): the set-up, and
// what follows from the broken joints alone (moisture nodes, their dry masses and boundary
// terms, tie groups, contact surfaces, the contact pairs' gather lists). A fingerprint of the
// set-up guards against a mesh file that changed since.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ycore/output/checkpoint_file.h"
#include "ycore/input/deck.h"
#include "ycore/output/output_files.h"
#include "ycore/state/state.h"

namespace ydry {

// Where the driver's loop stands and what it has written (ycore/driver/run.cpp).
struct RunRecord {
  std::uint64_t row = 1;           // the row of the tables the loop writes next (0 is t = 0)
  double chunk_until_s = std::numeric_limits<double>::quiet_NaN();  // end of the chunk of
                                   // coupling steps under way; NaN: none
  double max_step_s = 0;           // the coupling step limit advance_to goes on with
  std::uint64_t next_frame = 0;    // a frame is due at the first row at or after next_frame
                                   // output intervals
  std::uint64_t capped_reported = 0;  // capped relaxations the log has warned about
  bool finished = false;           // the row at end_time is written
  Series series;                   // series.csv's rows
  std::string reactions_rows, cracks_rows, surface_rows;  // the rows of reactions.csv, cracks.csv and
                                   // surface.csv (CsvTable::rows)
  std::string network_rows, cells_rows, junctions_rows;  // and of a plan view's network.csv,
                                   // cells.csv and junctions.csv
  std::vector<double> frame_times; // s, the frames written
};

// FNV-1a-64 of resolved_deck_values: the header's deck hash.
std::uint64_t deck_hash(const Deck& deck);

// FNV-1a-64 of the set-up that prepare_state builds from the deck and the mesh and that a
// checkpoint does not store: initial positions, masses, joints and their strengths, the
// pseudo-step.
std::uint64_t setup_fingerprint(const State& state);

// The checkpoint file's bytes. `deck_text` is the run's deck.toml.
std::string checkpoint_bytes(const Deck& deck, const std::string& deck_text, const State& state,
                             const RunRecord& record);

// read_checkpoint of a file, its errors prefixed with the path.
Checkpoint read_checkpoint_file(const std::string& path);

// The deck the checkpoint at `path` continues: its deck.toml read back (errors name the
// checkpoint), or, when `deck_path` is given, that deck with `overrides`, which must resolve
// to the same values (InputError naming the first line that differs). --set without a deck
// is an InputError: a restart continues the checkpoint's deck as it is.
Deck checkpoint_deck(const Checkpoint& checkpoint, const std::string& path, const std::string& deck_path,
                     const std::vector<std::string>& overrides);
// The run's deck.toml, as the checkpoint holds it.
std::string checkpoint_deck_text(const Checkpoint& checkpoint);

// Restoring onto a state that prepare_state built from the checkpoint's deck, in two parts
// around the driver's regrouping of the moisture nodes and contact surfaces:
// restore_broken_joints checks the set-up fingerprint and sets joints.broken (InputError for a
// mesh that changed, or a joint broken at set-up that the checkpoint has intact); then, once
// the topology follows the broken joints, restore_state sets everything else a run changes and
// indexes the contact pairs. InputError for any field that is missing, of the wrong type or
// size, a non-finite position, velocity or moisture, or contact pairs that are not pairs of
// surface corners and edges in order.
// Both take the State: restore_broken_joints reads the whole set-up (its fingerprint) and
// writes joints.broken; restore_state writes every history and totals field (state_fields.h)
// and the contact pairs' index.
void restore_broken_joints(State& state, const Checkpoint& checkpoint);
void restore_state(State& state, const Checkpoint& checkpoint);

// The driver's record, checked against the deck and the restored state (InputError for a
// time, row count or step the loop could not go on from).
RunRecord checkpoint_record(const Checkpoint& checkpoint, const Deck& deck, const State& state);

// OUTDIR/checkpoints/NAME_NNNNNN.chk, NNNNNN the coupling step count.
std::string checkpoint_path(const std::string& outdir, const std::string& name, std::uint64_t coupling_steps);

}  // namespace ydry
