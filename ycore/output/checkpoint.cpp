#include "ycore/output/checkpoint.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "version.h"
#include "ycore/output/reactions_csv.h"
#include "ycore/contact/contact_search.h"
#include "ycore/state/state_fields.h"

namespace ydry {
namespace {

// Totals added to the state after checkpoint format 1 was first written: a checkpoint without
// one (written before) restores it as 0, its value until the code that counts it ran.
const std::set<std::string> kTotalsAddedToFormat1 = {"mechanics.newton_fallbacks", "mechanics.worst_residual",
                                                     "mechanics.friction_slide_relaxations"};
// Record fields added after checkpoint format 1 was first written: the plan view's tables,
// which a checkpoint written before (of a vertical section, which has none) restores empty.
const std::set<std::string> kRecordFieldsAddedToFormat1 = {"record.network_rows", "record.cells_rows",
                                                           "record.junctions_rows"};
// The fields of the Newton chord matrix (state_fields.h) start so: they are as large as the
// checkpoint holds, and an older checkpoint has none.
constexpr const char* kChordFieldPrefix = "mechanics.chord_";

template <class R, class Field>
void for_each_record_field(R& r, Field&& field) {
  field("record.row", r.row);
  field("record.chunk_until_s", r.chunk_until_s);
  field("record.max_step_s", r.max_step_s);
  field("record.next_frame", r.next_frame);
  field("record.capped_reported", r.capped_reported);
  field("record.finished", r.finished);
  field("record.cracks_rows", r.cracks_rows);
  field("record.surface_rows", r.surface_rows);
  field("record.network_rows", r.network_rows);
  field("record.cells_rows", r.cells_rows);
  field("record.junctions_rows", r.junctions_rows);
  field("record.frame_times", r.frame_times);
}

void require_finite(const Checkpoint& c, const std::vector<double>& v, const char* name) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw InputError(c.source + ": field '" + name + "' holds a non-finite value at " + std::to_string(i));
}

// The restored pairs must be what a broad phase makes: sorted by (corner, edge), no two
// alike, each a surface corner against a surface edge, with a slip and six force components
// each; then the gather lists follow from them.
void check_contact_pairs(const State& s, const Checkpoint& checkpoint) {
  const Contact& c = s.contact;
  const std::size_t np = c.pair_node.size(), surfaces = c.is_surface_edge.size();  // 0 without mechanics
  if (c.pair_edge.size() != np || c.pair_slip.size() != np || c.pair_force.size() != 6 * np)
    throw InputError(checkpoint.source + ": contact pairs: node, edge, slip and force lists of different lengths");
  for (std::size_t k = 0; k < np; ++k) {
    const index_t i = c.pair_node[k], e = c.pair_edge[k];
    const bool in_order = k == 0 || c.pair_node[k - 1] < i || (c.pair_node[k - 1] == i && c.pair_edge[k - 1] < e);
    if (i >= surfaces || e >= surfaces || !c.is_surface_edge[e] || !(c.is_surface_edge[i] || c.is_surface_edge[previous_corner(i)]) ||
        !in_order)
      throw InputError(checkpoint.source + ": contact pair " + std::to_string(k) + " (corner " + std::to_string(i) + ", edge " +
                       std::to_string(e) + ") is not a surface corner against a surface edge, in order");
  }
}

// The restored chord matrix must be one: n + 1 column starts from 0 to its entries, rows below
// n, over n free components of the nodes.
void check_chord_matrix(const State& s, const Checkpoint& checkpoint) {
  const Mechanics& m = s.mechanics;
  const std::size_t n = m.chord_components.size(), entries = m.chord_values.size();
  bool valid = m.chord_inner.size() == entries && (n == 0 ? m.chord_outer.empty() && entries == 0
                                                          : m.chord_outer.size() == n + 1 && m.chord_outer.front() == 0 &&
                                                                m.chord_outer.back() == entries);
  for (std::size_t k = 1; valid && k < m.chord_outer.size(); ++k) valid = m.chord_outer[k - 1] <= m.chord_outer[k];
  for (std::size_t k = 0; valid && k < entries; ++k) valid = m.chord_inner[k] < n;
  for (std::size_t k = 0; valid && k < n; ++k) valid = m.chord_components[k] < 2 * s.nodes.size();
  if (!valid) throw InputError(checkpoint.source + ": the Newton chord matrix (mechanics.chord_*) is not a matrix over free components");
}

}  // namespace

std::uint64_t deck_hash(const Deck& deck) { return fnv1a64(resolved_deck_values(deck)); }

std::uint64_t setup_fingerprint(const State& s) {
  std::uint64_t hash = fnv1a64(nullptr, 0);
  hash_array(hash, s.nodes.x0);
  hash_array(hash, s.nodes.y0);
  hash_array(hash, s.nodes.m);
  hash_array(hash, s.nodes.constraint);
  hash_array(hash, s.triangles.material);
  hash_array(hash, s.joints.node);
  hash_array(hash, s.joints.strength_factor);
  return fnv1a64(reinterpret_cast<const char*>(&s.mechanics.step_s), sizeof s.mechanics.step_s, hash);
}

std::string checkpoint_bytes(const Deck& deck, const std::string& deck_text, const State& state,
                             const RunRecord& record) {
  CheckpointWriter out;
  const auto put = [&](const std::string& name, const auto& value) { out.put(name, value); };
  out.put("deck.toml", deck_text);
  out.put("setup_fingerprint", setup_fingerprint(state));
  for_each_history_field(state, put);
  for_each_record_field(record, put);
  std::vector<double> rows;
  for (const std::vector<double>& row : record.series.rows) rows.insert(rows.end(), row.begin(), row.end());
  out.put("record.series", rows);
  out.put("record.reactions_csv", kReactionsCsvHeader + ("\n" + record.reactions_rows));  // the whole file, header included
  return checkpoint_file_bytes(std::string(YDRY_VERSION) + " (" + YDRY_COMMIT + ")", deck_hash(deck), out.payload);
}

Checkpoint read_checkpoint_file(const std::string& path) {
  std::optional<std::string> bytes = read_file(path);
  if (!bytes) throw InputError(path + ": checkpoint file not found or not readable");
  try {
    Checkpoint c = read_checkpoint(std::move(*bytes));
    c.source = path;
    return c;
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

std::string checkpoint_deck_text(const Checkpoint& checkpoint) {
  std::string text;
  checkpoint.take("deck.toml", text);
  return text;
}

Deck checkpoint_deck(const Checkpoint& checkpoint, const std::string& path, const std::string& deck_path,
                     const std::vector<std::string>& overrides) {
  Deck deck = read_deck(checkpoint_deck_text(checkpoint), path + " (its deck.toml)", {});
  if (deck_hash(deck) != checkpoint.deck_hash)
    throw InputError(path + ": the deck it holds does not resolve to the values its header was made from");
  if (deck_path.empty()) {
    if (!overrides.empty())
      throw InputError("--set with --restart: a restart continues the checkpoint's deck as it is (give the DECK "
                       "the overrides apply to only to check that it is the same)");
    return deck;
  }
  Deck given = load_deck(deck_path, overrides);
  if (deck_hash(given) == checkpoint.deck_hash) return given;
  std::istringstream ours(resolved_deck_values(given)), theirs(resolved_deck_values(deck));
  std::string a, b;  // the first lines that differ
  for (bool more = true; more && a == b;) {
    more = bool(std::getline(ours, a)) & bool(std::getline(theirs, b));
    if (!ours) a = "(the end)";
    if (!theirs) b = "(the end)";
  }
  throw InputError(deck_path + (overrides.empty() ? "" : " with its --set overrides") + " is not the deck " + path +
                   " continues: '" + a + "' where the checkpoint has '" + b + "'");
}

void restore_broken_joints(State& s, const Checkpoint& c) {
  std::uint64_t fingerprint = 0;
  c.take("setup_fingerprint", fingerprint);
  if (fingerprint != setup_fingerprint(s))
    throw InputError(c.source + ": the deck's mesh and set-up are not those it was written from (has the mesh file "
                     "changed, or was it written by another version of ydry?)");
  std::vector<std::uint8_t> broken;
  c.take("joints.broken", broken);
  if (broken.size() != s.joints.size())
    throw InputError(c.source + ": field 'joints.broken' holds " + std::to_string(broken.size()) + " joints, the mesh " +
                     std::to_string(s.joints.size()));
  for (std::size_t j = 0; j < broken.size(); ++j)
    if (broken[j] > 1 || broken[j] < s.joints.broken[j])
      throw InputError(c.source + ": joint " + std::to_string(j) +
                       (broken[j] > 1 ? " has a broken flag that is neither 0 nor 1" : " is intact, but the deck's "
                                                                                      "pre-existing cracks break it"));
  s.joints.broken = std::move(broken);
}

void restore_state(State& s, const Checkpoint& c) {
  // The pairs are as many as the checkpoint holds; every other array has the size the set-up
  // and the topology give it.
  std::vector<index_t> pairs;
  c.take("contact.pair_node", pairs);
  for (auto* v : {&s.contact.pair_node, &s.contact.pair_edge}) v->resize(pairs.size());
  s.contact.pair_slip.resize(pairs.size());
  s.contact.pair_force.resize(6 * pairs.size());
  for_each_history_field(s, [&](const std::string& name, auto& value) {
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(value)>>) {
      if (kTotalsAddedToFormat1.count(name) && !c.fields.count(name)) return;  // an older checkpoint: 0
      c.take(name, value);
    } else if (name.rfind(kChordFieldPrefix, 0) == 0) {
      if (c.fields.count(name)) c.take(name, value);
    } else {
      const std::size_t size = value.size();
      c.take(name, value);
      if (value.size() != size)
        throw InputError(c.source + ": field '" + name + "' holds " + std::to_string(value.size()) +
                         " values; this deck and mesh have " + std::to_string(size));
    }
  });
  require_finite(c, s.nodes.x, "nodes.x");
  require_finite(c, s.nodes.y, "nodes.y");
  require_finite(c, s.nodes.vx, "nodes.vx");
  require_finite(c, s.nodes.vy, "nodes.vy");
  require_finite(c, s.moisture.w, "moisture.w");
  check_contact_pairs(s, c);
  check_chord_matrix(s, c);
  if (s.contact.builds > 0) index_contact_pairs(s.nodes, s.ownership, s.contact);  // a broad phase has run: the pairs are current
}

RunRecord checkpoint_record(const Checkpoint& c, const Deck& deck, const State& s) {
  RunRecord r;
  for_each_record_field(r, [&](const std::string& name, auto& value) {
    if (kRecordFieldsAddedToFormat1.count(name) && !c.fields.count(name)) return;  // an older checkpoint: none
    c.take(name, value);
  });
  std::vector<double> rows;
  c.take("record.series", rows);
  std::string reactions;
  c.take("record.reactions_csv", reactions);
  const std::string header = kReactionsCsvHeader + std::string("\n");
  if (reactions.compare(0, header.size(), header) != 0)
    throw InputError(c.source + ": field 'record.reactions_csv' does not begin with reactions.csv's header");
  r.reactions_rows = reactions.substr(header.size());
  r.series.columns = series_columns(s.interface_names);
  const std::size_t columns = r.series.columns.size();
  if (rows.size() % columns != 0)
    throw InputError(c.source + ": field 'record.series' does not hold whole rows of series.csv");
  for (std::size_t k = 0; k < rows.size(); k += columns)
    r.series.rows.emplace_back(rows.begin() + std::ptrdiff_t(k), rows.begin() + std::ptrdiff_t(k + columns));
  // Whatever the loop would trip over: a row count that is not the rows', a time or step it
  // could not go on from.
  const auto valid = [&](bool ok, const char* what) {
    if (!ok) throw InputError(c.source + ": its " + what);
  };
  valid(s.time_s >= 0.0 && s.time_s <= deck.end_time_s, "time is not within the run (0 to run.end_time)");
  valid(r.row >= 1 && r.series.rows.size() == r.row, "row count is not the number of rows of series.csv it holds");
  valid(r.frame_times.size() <= r.series.rows.size(), "frames outnumber its rows");
  valid(r.max_step_s > 0.0 && r.max_step_s <= deck.output_interval_s, "coupling step is not in (0, run.output_interval]");
  valid(std::isnan(r.chunk_until_s) || (r.chunk_until_s >= s.time_s && r.chunk_until_s <= deck.end_time_s),
        "chunk of coupling steps does not end between its time and run.end_time");
  return r;
}

std::string checkpoint_path(const std::string& outdir, const std::string& name, std::uint64_t coupling_steps) {
  char number[32];
  std::snprintf(number, sizeof number, "_%06llu.chk", static_cast<unsigned long long>(coupling_steps));
  return outdir + "/checkpoints/" + name + number;
}

}  // namespace ydry
