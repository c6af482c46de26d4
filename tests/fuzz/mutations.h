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

}  // namespace sg::fuzz
