// The measurement sets on which q-relaxed is compared with the reference
// fixpoint (tests/q_relaxed_fixpoint_test.cc, bench/q_relaxed_benchmark.cc):
// 16 random line sets, 16 beacon-range sets and 16 Minibex texts mixing
// lines and ranges, each with outliers and its known solution.
#ifndef ICPBENCH_TESTS_Q_RELAXED_CASES_H_
#define ICPBENCH_TESTS_Q_RELAXED_CASES_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "algorithms/relaxed/relaxed_testing.h"
#include "core/minibex_parser.h"
#include "core/random.h"
#include "problems/registry.h"

namespace icp::testing {

struct QRelaxedCase {
  std::string name;
  Views views;
  std::vector<double> truth;
  int outliers = 0;
};

inline std::string Number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A Minibex text over x, y in [-10, 10]: m measurements, the last
// `outliers` of them moved away from the truth; lines
// c x + s y = [o - 0.05, o + 0.05] and squared ranges to a beacon
// (x - bx)^2 + (y - by)^2 = [r2 - 0.3, r2 + 0.3] (r2 the squared distance
// within 0.1), alternating.
inline QRelaxedCase MinibexCase(std::uint64_t seed, int m, int outliers) {
  RandomEngine rng(seed);
  QRelaxedCase out;
  out.name = "minibex-" + std::to_string(seed);
  out.truth = {UniformReal(rng, -5, 5), UniformReal(rng, -5, 5)};
  out.outliers = outliers;
  const double x = out.truth[0], y = out.truth[1];
  std::string text = "Variables\n  x in [-10, 10];\n  y in [-10, 10];\nConstraints\n";
  std::vector<bool> is_outlier;
  for (int i = 0; i < m; ++i) {
    const bool outlier = i >= m - outliers;
    const double miss = outlier ? (UniformInt(rng, 0, 1) ? 1 : -1) * UniformReal(rng, 1.5, 5) : 0;
    if (i % 2 == 0) {
      const double a = UniformReal(rng, 0, M_PI);
      const double o = std::cos(a) * x + std::sin(a) * y + UniformReal(rng, -0.02, 0.02) + miss;
      text += "  " + Number(std::cos(a)) + " * x + " + Number(std::sin(a)) + " * y = [" + Number(o - 0.05) +
              ", " + Number(o + 0.05) + "];\n";
    } else {
      const double bx = UniformReal(rng, -10, 10), by = UniformReal(rng, -10, 10);
      const double d = std::hypot(x - bx, y - by);
      const double r = d + miss < 0 ? d - miss : d + miss;  // an outlier's range stays a range
      const double r2 = r * r + UniformReal(rng, -0.1, 0.1);
      text += "  (x - " + Number(bx) + ")^2 + (y - " + Number(by) + ")^2 = [" + Number(r2 - 0.3) + ", " +
              Number(r2 + 0.3) + "];\n";
    }
    is_outlier.push_back(outlier);
  }
  text += "end\n";
  out.views = PlaneMeasurementViews(ParseMinibex(text, out.name), std::move(is_outlier));
  return out;
}

inline QRelaxedCase BeaconCase(std::uint64_t seed, int beacons, int outliers) {
  Step step;
  FindProblem("beacon-ranges")
      .make({{"scenario", "random"}, {"beacons", std::to_string(beacons)}, {"outliers", std::to_string(outliers)}},
            seed)
      ->Next(&step);
  return {"beacons-" + std::to_string(seed), std::move(step.views), step.truth, outliers};
}

inline QRelaxedCase LinesCaseOf(std::uint64_t seed, int m, int outliers) {
  LinesCase c = Lines(seed, m, outliers);
  return {"lines-" + std::to_string(seed), std::move(c.views), c.truth, outliers};
}

// m from 8 to 38 measurements, outliers up to a third of them.
inline std::vector<QRelaxedCase> QRelaxedCases() {
  std::vector<QRelaxedCase> out;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    const int m = 8 + 2 * static_cast<int>(seed - 1);
    const int outliers = static_cast<int>(seed % 4) * m / 9;
    out.push_back(LinesCaseOf(seed, m, outliers));
    out.push_back(BeaconCase(seed, m, outliers));
    out.push_back(MinibexCase(seed, m, outliers));
  }
  return out;
}

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_Q_RELAXED_CASES_H_
