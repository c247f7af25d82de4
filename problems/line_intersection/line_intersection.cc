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

LineIntersectionScene DrawLineIntersection(const LineIntersectionParams& p, std::uint64_t seed) {
  RandomEngine rng(seed);
  const double r = p.radius, e = p.offset_error;
  LineIntersectionScene scene;
  scene.truth = {UniformReal(rng, -r / 2, r / 2), UniformReal(rng, -r / 2, r / 2)};
  const std::vector<bool> outliers = DrawOutliers(p.lines, p.outliers, rng);
  for (int i = 0; i < p.lines; ++i) {
    DrawnLine line;
    line.angle = UniformReal(rng, 0, std::numbers::pi);
    line.outlier = outliers[i];
    line.offset = std::cos(line.angle) * scene.truth[0] + std::sin(line.angle) * scene.truth[1];
    if (line.outlier) {
      const double shift = e + UniformReal(rng, r / 10, r / 2);
      line.offset += UniformInt(rng, 0, 1) == 0 ? -shift : shift;
    } else {
      line.offset += UniformReal(rng, -e / 2, e / 2);
    }
    scene.lines.push_back(line);
  }
  return scene;
}

Step MakeLineIntersectionStep(const LineIntersectionParams& p, std::uint64_t seed) {
  const LineIntersectionScene scene = DrawLineIntersection(p, seed);
  const double r = p.radius, e = p.offset_error;
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", Interval(-r, r));
  Expr y = csp.AddVariable("y", Interval(-r, r));
  std::vector<bool> outliers;
  for (const DrawnLine& line : scene.lines) {
    csp.AddConstraint(std::cos(line.angle) * x + std::sin(line.angle) * y,
                      Interval(line.offset) + Interval(-e, e));
    outliers.push_back(line.outlier);
  }
  return MakePlanarStep(0, csp, scene.truth, outliers, {});
}

std::unique_ptr<Problem> MakeLineIntersection(const ParamMap& params, std::uint64_t seed) {
  return std::make_unique<SingleStepProblem>(
      "line-intersection", [p = ParseLineIntersection("line-intersection", params), seed] {
        return MakeLineIntersectionStep(p, seed);
      });
}

}  // namespace icp
