#pragma once
// The nearest of a list of names to a misspelled one, for messages that answer a typo with
// the name meant ("unknown subcommand 'rnu'; nearest: 'run'").
#include <string>
#include <string_view>
#include <vector>

namespace sg {

// Levenshtein distance: the fewest insertions, deletions and substitutions of one character
// that turn `a` into `b` (Wagner & Fischer 1974, J. ACM 21(1):168-173).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate at the smallest edit distance from `word`, ignoring case; the first of equals.
// Empty if there is no candidate.
std::string nearest_name(std::string_view word, const std::vector<std::string>& candidates);

// "a, b, c": for a list of choices in a message.
std::string join_names(const std::vector<std::string>& names);

}  // namespace sg
