#include "core/view.h"

namespace icp {

std::string_view ToString(View view) {
  switch (view) {
    case View::kCsp: return "csp";
    case View::kMeasurementSet: return "measurement-set";
    case View::kProbabilistic: return "probabilistic";
  }
  return "?";
}

bool Views::Offers(View view) const {
  switch (view) {
    case View::kCsp: return csp.has_value();
    case View::kMeasurementSet: return measurement_set.has_value();
    case View::kProbabilistic: return probabilistic.has_value();
  }
  return false;
}

}  // namespace icp
