// The line-intersection problem of paper 003 §5.1.4 (Fig. 5.2): m lines in
// the plane, m - k of which pass through a common true point p, the other k
// (the outliers) missing it by a clear margin; find the point where most
// lines meet. Line i is the constraint
//   cos(a_i) x + sin(a_i) y in [c_i - e, c_i + e]
// with a_i uniform in [0, pi) and e = offset_error. An inlier's offset c_i is
// its line's true offset plus noise within ±e/2, so p satisfies it with a
// margin of e/2; an outlier's offset is moved beyond the band by a uniform
// amount in [radius/10, radius/2], so p violates it by at least radius/10.
// One static step, seeded by the run seed; it offers the measurement-set view
// (one contractor per line) and the CSP view (all lines, empty for ICP once
// k > 0).
#ifndef ICPBENCH_PROBLEMS_LINE_INTERSECTION_LINE_INTERSECTION_H_
#define ICPBENCH_PROBLEMS_LINE_INTERSECTION_LINE_INTERSECTION_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "problems/problem.h"

namespace icp {

struct LineIntersectionParams {
  // Number of lines m (20 in Fig. 5.2).
  int lines = 20;
  // Number of outlier lines k, below lines (7 in Fig. 5.2).
  int outliers = 7;
  // The search box is [-radius, radius]^2; the truth is drawn in its inner
  // half, [-radius/2, radius/2]^2.
  double radius = 10;
  // Half-width e of each offset interval, in the units of radius.
  double offset_error = 0.05;
};
void Describe(LineIntersectionParams& p, ParamSet& set);

// Parses and validates (outliers < lines); throws ParamError.
LineIntersectionParams ParseLineIntersection(const std::string& owner, const ParamMap& values);
ParamMap ResolveLineIntersection(const std::string& owner, const ParamMap& values);

// The lines the seed draws: line i is cos(angle) x + sin(angle) y in
// [offset - offset_error, offset + offset_error]. For figures, which draw
// the lines; the step's constraints are these.
struct DrawnLine {
  double angle = 0;
  double offset = 0;
  bool outlier = false;
};
struct LineIntersectionScene {
  std::vector<double> truth;  // (x, y)
  std::vector<DrawnLine> lines;
};
LineIntersectionScene DrawLineIntersection(const LineIntersectionParams& params,
                                           std::uint64_t seed);

// The single step for the given seed.
Step MakeLineIntersectionStep(const LineIntersectionParams& params, std::uint64_t seed);

std::unique_ptr<Problem> MakeLineIntersection(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_LINE_INTERSECTION_LINE_INTERSECTION_H_
