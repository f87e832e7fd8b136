// command_names.h - what `shpack` says when its first word is not one of its commands: the
// nearest command by edit distance, so that a typo gets a suggestion instead of a riddle.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace shpack::cli {

// The optimal string alignment distance (Levenshtein's insertions, deletions and
// substitutions, plus the transposition of two adjacent characters, each costing 1), in
// O(|a| |b|) time.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The name of `names` nearest to `word`, if it is near enough to be a typo of it: at most
// 2 edits, and fewer than half of the word's length (so "x" suggests nothing). Ties go to the
// first name. Empty if none is.
std::string nearest_name(std::string_view word, std::span<const std::string> names);

}  // namespace shpack::cli
