#include "core/view.h"

#include <algorithm>
#include <stdexcept>

#include "core/contractor_algebra.h"

namespace icp {

std::string_view ToString(View view) {
  switch (view) {
    case View::kCsp: return "csp";
    case View::kMeasurementSet: return "measurement-set";
    case View::kProbabilistic: return "probabilistic";
    case View::kLandmarkObservations: return "landmark-observations";
  }
  return "?";
}

Box NewestState(const CspView& view, const Box& box, int size) {
  Box newest(static_cast<std::size_t>(size));
  std::vector<bool> found(newest.size(), false);
  for (std::size_t i = 0; i < view.states.size(); ++i) {
    const StateRef& s = view.states[i];
    if (s.is_landmark() || s.time != view.newest) continue;
    newest[s.component] = box[i];
    found[s.component] = true;
  }
  if (std::find(found.begin(), found.end(), false) != found.end())
    throw std::invalid_argument("the CSP view lacks a variable for some component of the newest state");
  return newest;
}

std::unique_ptr<Contractor> ComposeWithCspView(std::unique_ptr<Contractor> csp_contractor,
                                               const CspView& view) {
  if (view.extra_contractors.empty()) return csp_contractor;
  SharedContractors parts = {std::shared_ptr<Contractor>(std::move(csp_contractor))};
  parts.insert(parts.end(), view.extra_contractors.begin(), view.extra_contractors.end());
  return std::make_unique<FixpointContractor>(
      std::make_shared<SequenceContractor>(std::move(parts)), 0.01, kCspViewFixpointIterations);
}

bool Views::Offers(View view) const {
  switch (view) {
    case View::kCsp: return csp.has_value();
    case View::kMeasurementSet: return measurement_set.has_value();
    case View::kProbabilistic: return probabilistic.has_value();
    case View::kLandmarkObservations: return landmark_observations.has_value();
  }
  return false;
}

}  // namespace icp
