// Suggesting the name meant when an unknown one is given (a misspelt spec
// key, parameter, algorithm or problem).
#ifndef ICPBENCH_CORE_NEAR_NAMES_H_
#define ICPBENCH_CORE_NEAR_NAMES_H_

#include <string>
#include <string_view>
#include <vector>

namespace icp {

// "; did you mean 'x'?" for the candidate x closest to name in edit
// distance (insertions, deletions, substitutions and swaps of neighbours),
// when it is a likely misspelling: at most a third of name's letters off,
// and at least 1. Empty when no candidate is that close, or two are.
std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace icp

#endif  // ICPBENCH_CORE_NEAR_NAMES_H_
