#include "harness/coverage.h"

#include <string>
#include <variant>

namespace icp {

void CoverageCounter::Add(const Step& step, const Estimate& estimate, Properties* properties) {
  const Properties covered = CoverageProperties(step, estimate);
  if (covered.size() != std::size(kCoverageLevels)) return;
  ++judged_;
  for (std::size_t i = 0; i < covered.size(); ++i) {
    covered_[i] += std::get<std::int64_t>(covered[i].value);
    properties->push_back(covered[i]);
  }
}

void CoverageCounter::AppendRunProperties(Properties* properties) const {
  if (judged_ == 0) return;
  for (std::size_t i = 0; i < std::size(kCoverageLevels); ++i)
    properties->push_back({"coverage_" + std::to_string(kCoverageLevels[i]),
                           static_cast<double>(covered_[i]) / static_cast<double>(judged_)});
}

}  // namespace icp
