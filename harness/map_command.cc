#include "harness/map_command.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>

#include "harness/results_store.h"

namespace icp {

LandmarkMap MapOfSteps(const std::vector<StepRecord>& steps, const std::string& run_key) {
  // Each landmark's bounds from the last step that reports it.
  std::map<int, std::array<double, 6>> bounds;
  for (const StepRecord& s : steps) {
    for (const Property& p : s.properties) {
      int n = 0;
      char axis = 0;
      char end[3] = {};
      if (std::sscanf(p.name.c_str(), "L%d_%c_%2s", &n, &axis, end) != 3) continue;
      const std::string which(end);
      if ((axis != 'x' && axis != 'y' && axis != 'z') || (which != "lo" && which != "hi")) continue;
      const std::optional<double> v = NumberProperty({p}, p.name);
      if (!v) continue;
      bounds[n][2 * (axis - 'x') + (which == "hi")] = *v;
    }
  }
  if (bounds.empty())
    throw std::invalid_argument("run " + run_key +
                                " reports no landmark (a teach run of visual-landmarks does)");
  LandmarkMap map;
  for (const auto& [n, b] : bounds) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!(b[2 * axis] <= b[2 * axis + 1]) || !std::isfinite(b[2 * axis]) ||
          !std::isfinite(b[2 * axis + 1]))
        throw std::invalid_argument("run " + run_key + ": landmark " + std::to_string(n) +
                                    "'s last box is empty or unbounded: no map of it");
      map[n][axis] = Interval(b[2 * axis], b[2 * axis + 1]);
    }
  }
  return map;
}

LandmarkMap MapOfStoredRun(const std::string& dir, const std::vector<std::string>& terms,
                           std::string* run_key) {
  const auto store = ResultsStore::OpenReadOnly(StorePath(dir));
  std::vector<std::string> matches;
  for (const std::string& key : store->RunKeys()) {
    bool all = true;
    for (const std::string& t : terms) all = all && key.find(t) != std::string::npos;
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
    return MapOfSteps(run.steps, matches[0]);
  }
  throw std::invalid_argument("run " + matches[0] + " vanished from " + StorePath(dir));
}

}  // namespace icp
