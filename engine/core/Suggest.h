#pragma once
// "Did you mean ...?" for a mistyped name (a command, an option, a scene key,
// an enum value): the known name closest to the given one by optimal string
// alignment distance (Levenshtein's edits plus swapping two neighbours,
// Damerau 1964), when it is close enough to be a typo rather than another
// word: at most 1 edit for names up to 4 characters, 2 up to 8, then 3.

#include <string>
#include <vector>

namespace dermis {

// Edits (insert, delete, substitute, swap two adjacent characters) between a and b.
size_t editDistance(const std::string& a, const std::string& b);

// The closest of `known` within the limit above (ties: the first listed); empty when none is.
std::string closestName(const std::string& given, const std::vector<std::string>& known);

// " (did you mean 'NAME'?)" or "" (the form every message uses).
std::string didYouMean(const std::string& given, const std::vector<std::string>& known);

}  // namespace dermis
