// Helpers for the tests of claims files (paper/*claims_test.cc).
#ifndef ICPBENCH_PAPER_CLAIMS_TESTING_H_
#define ICPBENCH_PAPER_CLAIMS_TESTING_H_

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "paper/comparison.h"

namespace icp::testing {

// The row of claim `id`; a test failure and an empty row when there is none.
inline const ComparisonRow& ClaimRow(const std::vector<ComparisonRow>& rows,
                                     const std::string& id) {
  for (const ComparisonRow& r : rows)
    if (r.id == id) return r;
  static const ComparisonRow kNone{"(no such row)", "", "", "", Verdict::kNoData, ""};
  ADD_FAILURE() << "no row " << id;
  return kNone;
}

}  // namespace icp::testing

#endif  // ICPBENCH_PAPER_CLAIMS_TESTING_H_
