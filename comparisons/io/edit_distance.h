#pragma once
/// How far a mistyped word is from the words it may have meant: the suggestion of an unknown-key
/// error ("did you mean ...?", comparisons/io/json_reader.cpp, only_keys).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace tecido::io {

/// The optimal string alignment distance: the fewest insertions, deletions, substitutions and
/// swaps of two neighbouring characters turning `a` into `b`, no substring edited twice (so
/// "ca" -> "abc" is 3, not the 2 of unrestricted Damerau-Levenshtein). Bytes, not code points.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidates nearest to `word`, all ties in the candidates' order, when they are close enough
/// to be a typo of it: at most max(1, |word| / 3) edits (so "gravty" -> "gravity", "stiffness" ->
/// "stiffness_a" and "stiffness_b", but no guess for a word unlike every candidate). Empty if none.
std::vector<std::string> nearest_words(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace tecido::io
