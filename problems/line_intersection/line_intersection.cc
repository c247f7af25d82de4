#include "problems/line_intersection/line_intersection.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "core/constraint_system.h"
#include "core/random.h"
#include "problems/planar.h"

namespace icp {

void Describe(LineIntersectionParams& p, ParamSet& set) {
  set.Add("lines", &p.lines, "number of lines m", Range::Closed(2, 100000));
  set.Add("outliers", &p.outliers, "number of outlier lines k; must be < lines",
          Range::Closed(0, 100000));
  set.Add("radius", &p.radius, "search box [-radius, radius]^2; truth in its inner half",
          Range::Positive(1e6));
  set.Add("offset_error", &p.offset_error, "half-width of each line's offset interval",
          Range::Positive(1e6));
}

LineIntersectionParams ParseLineIntersection(const std::string& owner, const ParamMap& values) {
  auto p = ParseParams<LineIntersectionParams>(owner, values);
  if (p.outliers >= p.lines)
    throw ParamError(owner + ".outliers = " + std::to_string(p.outliers) + ": must be < lines (" +
                     std::to_string(p.lines) + ")");
  return p;
}

ParamMap ResolveLineIntersection(const std::string& owner, const ParamMap& values) {
  ParseLineIntersection(owner, values);
  return ResolveParams<LineIntersectionParams>(owner, values);
}

Step MakeLineIntersectionStep(const LineIntersectionParams& p, std::uint64_t seed) {
  RandomEngine rng(seed);
  const double r = p.radius, e = p.offset_error;
  const std::vector<double> truth = {UniformReal(rng, -r / 2, r / 2),
                                     UniformReal(rng, -r / 2, r / 2)};
  const std::vector<bool> outliers = DrawOutliers(p.lines, p.outliers, rng);
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", Interval(-r, r));
  Expr y = csp.AddVariable("y", Interval(-r, r));
  for (int i = 0; i < p.lines; ++i) {
    const double a = UniformReal(rng, 0, std::numbers::pi);
    const double ca = std::cos(a), sa = std::sin(a);
    double c = ca * truth[0] + sa * truth[1];
    if (outliers[i]) {
      const double shift = e + UniformReal(rng, r / 10, r / 2);
      c += UniformInt(rng, 0, 1) == 0 ? -shift : shift;
    } else {
      c += UniformReal(rng, -e / 2, e / 2);
    }
    csp.AddConstraint(ca * x + sa * y, Interval(c) + Interval(-e, e));
  }
  return MakePlanarStep(0, csp, truth, outliers, {});
}

std::unique_ptr<Problem> MakeLineIntersection(const ParamMap& params, std::uint64_t seed) {
  return std::make_unique<SingleStepProblem>(
      "line-intersection", [p = ParseLineIntersection("line-intersection", params), seed] {
        return MakeLineIntersectionStep(p, seed);
      });
}

}  // namespace icp
