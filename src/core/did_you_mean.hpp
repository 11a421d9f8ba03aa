// "Did you mean ...?" suggestions for misspelt keys, choices and names.
#pragma once

#include <string>
#include <vector>

namespace si {

// Edit distance counting insertions, deletions, substitutions and swaps of two adjacent letters
// (the optimal string alignment distance, Damerau's typo classes), case-sensitive: "stpe" is one
// edit from "step", the commonest slip of the fingers (Damerau 1964, Commun. ACM 7, 171-176).
int edit_distance(const std::string& a, const std::string& b);

// " (did you mean 'x'?)" for the closest candidate when it is close enough to be a likely typo
// (at most a third of the word's letters wrong, at least one), otherwise "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace si
