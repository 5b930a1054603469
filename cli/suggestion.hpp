#pragma once

#include <optional>
#include <string>
#include <vector>

namespace radarpr::cli {

// The candidate a mistyped word most likely meant, for "did you mean ...?": the closest by edit
// distance (insertions, deletions, substitutions and swaps of neighbours), when it is close
// enough to be a typo (about one edit per three letters), else the only candidate the word
// begins (`sim` for `simulate`). Leading dashes count as letters, so an option is matched
// against options. nullopt when nothing is close.
std::optional<std::string> closest_match(const std::string& word,
                                         const std::vector<std::string>& candidates);

}  // namespace radarpr::cli
