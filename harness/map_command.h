// `icpbench map DIR TERM... [-o FILE]`: the landmark map a teach run of
// visual-landmarks leaves (paper 004 §4.1), for a repeat run's `map`
// parameter: each landmark's last position box (the step properties
// L<n>_x_lo ... L<n>_z_hi of its last step that reports it), but those
// left unbounded (said on standard error). The run is the one stored run
// whose key contains every TERM (e.g. `digo` `w=10` `|seed=1`).
#ifndef ICPBENCH_HARNESS_MAP_COMMAND_H_
#define ICPBENCH_HARNESS_MAP_COMMAND_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "problems/visual_landmarks/landmark_map.h"

namespace icp {

// The map of a run's steps: each landmark's last box, but those left empty or
// unbounded (a landmark without parallax), whose identities go to left_out.
// Throws std::invalid_argument when no landmark has a bounded box.
LandmarkMap MapOfSteps(const std::vector<StepRecord>& steps, const std::string& run_key,
                       std::vector<int>* left_out);

// The map of the one run of DIR's store whose key holds every term, that
// run's key and the landmarks left out. Throws std::invalid_argument when no run or several match (listing
// them) or the run is not ok.
LandmarkMap MapOfStoredRun(const std::string& dir, const std::vector<std::string>& terms,
                           std::string* run_key, std::vector<int>* left_out);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_MAP_COMMAND_H_
