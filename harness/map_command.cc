#include "harness/map_command.h"

#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include "harness/landmark_metrics.h"
#include "harness/results_store.h"

namespace icp {

LandmarkMap MapOfSteps(const std::vector<StepRecord>& steps, const std::string& run_key,
                       std::vector<int>* left_out) {
  // Each landmark's bounds from the last step that reports it.
  std::map<int, std::array<double, 6>> bounds;
  for (const StepRecord& s : steps)
    for (const auto& [n, b] : LandmarkBoxesOf(s.properties)) bounds[n] = b;
  if (bounds.empty())
    throw std::invalid_argument("run " + run_key +
                                " reports no landmark (a teach run of visual-landmarks does)");
  LandmarkMap map;
  for (const auto& [n, b] : bounds) {
    bool bounded = true;
    for (int axis = 0; axis < 3; ++axis)
      bounded = bounded && b[2 * axis] <= b[2 * axis + 1] && std::isfinite(b[2 * axis]) &&
                std::isfinite(b[2 * axis + 1]);
    if (!bounded) {
      left_out->push_back(n);
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) map[n][axis] = Interval(b[2 * axis], b[2 * axis + 1]);
  }
  if (map.empty())
    throw std::invalid_argument("run " + run_key + ": no landmark's box is bounded: no map");
  return map;
}

namespace {
// Whether key contains term, a number in the term ending where one in the
// key does: '|seed=1' and 'w=2' do not match seed=10 or w=20.
bool ContainsTerm(const std::string& key, const std::string& term) {
  const bool ends_in_digit = !term.empty() && std::isdigit(static_cast<unsigned char>(term.back()));
  for (std::size_t at = key.find(term); at != std::string::npos; at = key.find(term, at + 1)) {
    const std::size_t next = at + term.size();
    if (!ends_in_digit || next == key.size() ||
        !(std::isdigit(static_cast<unsigned char>(key[next])) || key[next] == '.' || key[next] == 'e'))
      return true;
  }
  return false;
}
}  // namespace

LandmarkMap MapOfStoredRun(const std::string& dir, const std::vector<std::string>& terms,
                           std::string* run_key, std::vector<int>* left_out) {
  const auto store = ResultsStore::OpenReadOnly(StorePath(dir));
  std::vector<std::string> matches;
  for (const std::string& key : store->RunKeys()) {
    bool all = true;
    for (const std::string& t : terms) all = all && ContainsTerm(key, t);
    if (all) matches.push_back(key);
  }
  if (matches.size() != 1) {
    std::string list;
    for (std::size_t i = 0; i < matches.size() && i < 10; ++i) list += "\n  " + matches[i];
    throw std::invalid_argument(std::to_string(matches.size()) + " runs of " + StorePath(dir) +
                                " match the terms; give terms that single out one" + list);
  }
  for (const RunRecord& run : store->LoadRuns(true)) {
    if (run.spec.Key() != matches[0]) continue;
    if (run.status != RunStatus::kOk)
      throw std::invalid_argument("run " + matches[0] + " is " + std::string(ToString(run.status)) +
                                  ": " + run.reason);
    *run_key = matches[0];
    return MapOfSteps(run.steps, matches[0], left_out);
  }
  throw std::invalid_argument("run " + matches[0] + " vanished from " + StorePath(dir));
}

}  // namespace icp
