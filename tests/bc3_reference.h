// A frozen copy of BC3's bound search as it was before issue 11 (commit
// 37cacc2: one edge test on the original domain, then Newton + bisection down
// to epsilon, every evaluation over the whole tape). Test-only: the search
// suite (tests/bc3_search_test.cc) checks the BoxNarrower that stops at the
// first consistent edge against it. Do not optimize this file.
#ifndef ICPBENCH_TESTS_BC3_REFERENCE_H_
#define ICPBENCH_TESTS_BC3_REFERENCE_H_

#include <memory>
#include <optional>
#include <vector>

#include "algorithms/bc3/bc3.h"
#include "core/propagation.h"

namespace icp::testing {

class ReferenceBoxNarrower {
 public:
  ReferenceBoxNarrower(double epsilon, int max_bisections)
      : epsilon_(epsilon), max_bisections_(max_bisections) {}
  bool Narrow(const Tape& tape, int var, Box& box, WorkCounters& work);

 private:
  bool Consistent(const Tape& tape, int var, const Interval& j);
  Interval Newton(const Tape& tape, int var, Interval j, WorkCounters& work);
  std::optional<double> OuterBound(const Tape& tape, int var, const Interval& x, bool leftward,
                                   WorkCounters& work);
  bool Small(const Interval& j) const;

  double epsilon_;
  int max_bisections_;
  Box work_box_;
  std::vector<Interval> slots_, dslots_;
  std::vector<Interval> stack_;
};

// BC3 and BC4 over the reference narrower (the propagation loop is shared).
class ReferenceBC3Contractor : public PropagationContractor {
 public:
  ReferenceBC3Contractor(std::shared_ptr<const CompiledSystem> system, const BC3Params& params);
  std::string_view Name() const override { return "reference-bc3"; }

 protected:
  bool Revise(int c, Box& box, WorkCounters& work, bool* idempotent) override;

 private:
  ReferenceBoxNarrower narrower_;
  std::vector<Interval> scratch_;
};

class ReferenceBC4Contractor : public PropagationContractor {
 public:
  ReferenceBC4Contractor(std::shared_ptr<const CompiledSystem> system, const BC3Params& params);
  std::string_view Name() const override { return "reference-bc4"; }

 protected:
  bool Revise(int c, Box& box, WorkCounters& work, bool* idempotent) override;

 private:
  ReferenceBoxNarrower narrower_;
  std::vector<Interval> slots_;
  std::vector<std::vector<int>> multiple_;
};

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_BC3_REFERENCE_H_
