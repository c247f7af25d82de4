// Test helpers shared by the car-track test sources (car_track_test.cc,
// car_track_log_test.cc): making the problem, running HC4 over it, comparing
// two problems' steps and catching an error's message.
#ifndef ICPBENCH_PROBLEMS_CAR_TRACK_CAR_TRACK_TESTING_H_
#define ICPBENCH_PROBLEMS_CAR_TRACK_CAR_TRACK_TESTING_H_

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "algorithms/registry.h"
#include "problems/registry.h"

namespace icp::testing {

inline std::unique_ptr<Problem> Make(const ParamMap& params, std::uint64_t seed) {
  return FindProblem("car-track").make(params, seed);
}

// Runs HC4 (carry=first) on every step; calls visit(step, the newest
// state's box) after each.
inline void RunHC4(Problem& problem, const std::function<void(const Step&, const Box&)>& visit) {
  auto hc4 = FindAlgorithm("hc4").make({}, 1);
  Step step;
  while (problem.Next(&step)) visit(step, hc4->Step(step.views, StopCondition()).estimate->Hull());
}

inline const ConstraintSystem& Csp(const Step& step) { return step.views.csp->csp; }

// The two problems give the same steps: CSPs, truths and number of steps.
inline void ExpectSameSteps(Problem& a, Problem& b) {
  Step sa, sb;
  while (a.Next(&sa)) {
    ASSERT_TRUE(b.Next(&sb));
    ASSERT_EQ(Csp(sa).domains(), Csp(sb).domains()) << "step " << sa.views.step;
    ASSERT_EQ(Csp(sa).constraints().size(), Csp(sb).constraints().size());
    for (std::size_t c = 0; c < Csp(sa).constraints().size(); ++c)
      ASSERT_EQ(Csp(sa).ConstraintToString(c), Csp(sb).ConstraintToString(c));
    ASSERT_EQ(sa.truth, sb.truth);
    ASSERT_EQ(sa.csp_truth, sb.csp_truth);
  }
  EXPECT_FALSE(b.Next(&sb));
}

// Message of the std::invalid_argument thrown by f, or "" if none.
inline std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace icp::testing

#endif  // ICPBENCH_PROBLEMS_CAR_TRACK_CAR_TRACK_TESTING_H_
