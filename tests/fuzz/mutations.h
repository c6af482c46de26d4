#pragma once
// Deterministic mutations of a scenario (or campaign) file's text, for the scenario fuzzer:
// every number -> 0, -1, 1e300, nan, a string; every string -> "", a path reaching out of
// the folder ("../escape"), an absolute path; every boolean -> a number; every key dropped,
// duplicated, misspelled; every table emptied; the bytes truncated at several points.
// Line-based on purpose: the mutated text need not be valid TOML.
#include <string>
#include <vector>

namespace sg::fuzz {

struct Mutation {
  std::string what;  // e.g. "line 12: number 0.08 -> 1e300"
  std::string text;  // the whole mutated file
};

// `absolute_escape` is an absolute path the fuzzer watches (it must stay unwritten).
std::vector<Mutation> mutations_of(const std::string& text, const std::string& absolute_escape);

// Mutations of a CSV data file a scenario names (grains, contour, profile; issue #26): every
// cell of the header and of the first data rows -> -0.2, 0, nan, inf, 1e400, a word, empty;
// each of those rows cut short by a cell, given a cell too many, doubled (coincident grains),
// blanked (",,,"); the header dropped; the file emptied or truncated at several points.
std::vector<Mutation> csv_mutations_of(const std::string& text);

}  // namespace sg::fuzz
