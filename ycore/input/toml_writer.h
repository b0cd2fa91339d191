// A TOML table as text, read back by toml++ to the same table: what deck.toml of a run and
// `ydry check` print (resolved_deck_text).
//
// Not toml++'s toml_formatter for the containers: in toml++ 3.3 (Debian 12) it chooses whether
// an array fits on one line with static_cast<size_t>(log10(|x|)), undefined behaviour for any
// number in an array below 0.1 in magnitude (size = [0.1, 0.01]), and negates INT64_MIN
// (tests/test_fuzz_findings.cpp). Scalars are still printed by toml++, which writes them so
// that they read back exactly.
#pragma once

#include <string>

#include <toml++/toml.h>

namespace ydry {

// Laid out as toml++'s formatter does: in each table its plain keys in key order, then its
// sub-tables as [a.b] sections, then its arrays of tables as [[a.b]]; arrays and inline
// tables on one line.
std::string toml_text(const toml::table& table);

}  // namespace ydry
