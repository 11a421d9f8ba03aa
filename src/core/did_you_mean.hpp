// "Did you mean ...?" suggestions for misspelt keys, choices and names.
#pragma once

#include <string>
#include <vector>

namespace si {

// Levenshtein distance (insertions, deletions, substitutions), case-sensitive.
int edit_distance(const std::string& a, const std::string& b);

// " (did you mean 'x'?)" for the closest candidate when it is close enough to be a likely typo
// (at most a third of the word's letters wrong, at least one), otherwise "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace si
