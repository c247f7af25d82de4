// The median over a group's runs with its distribution-free 95 % interval,
// and paired ratios of two groups by seed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "harness/metrics.h"
#include "report/report.h"

namespace icp {

namespace {

constexpr double kLevel = 0.95;

// P(Binomial(n, 1/2) < k), summed in log space so large n cannot underflow
// 2^-n.
double BinomialHalfBelow(int n, int k) {
  double sum = 0;
  for (int i = 0; i < k; ++i)
    sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) -
                    n * std::log(2.0));
  return sum;
}

}  // namespace

MedianInterval MedianWithInterval(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
               values.end());
  MedianInterval m;
  m.n = static_cast<int>(values.size());
  if (values.empty()) return m;
  std::sort(values.begin(), values.end());
  m.median = Quantile(values, 0.5);
  // The largest k whose [x_(k), x_(n+1-k)] still covers the median at kLevel;
  // the coverage only falls as k grows.
  int best = 0;
  double coverage = 0;
  for (int k = 1; 2 * k <= m.n; ++k) {
    const double c = 1 - 2 * BinomialHalfBelow(m.n, k);
    if (c < kLevel) break;
    best = k;
    coverage = c;
  }
  if (best > 0) {
    m.lo = values[best - 1];
    m.hi = values[m.n - best];
    m.coverage = coverage;
  }
  return m;
}

MedianInterval RunMedian(const GroupSummary& group,
                         const std::function<double(const RunRecord&)>& value) {
  std::vector<double> values;
  for (const RunRecord* r : group.ok_runs) values.push_back(value(*r));
  return MedianWithInterval(std::move(values));
}

MedianInterval PairedRatio(const GroupSummary& a, const GroupSummary& b,
                           const std::function<double(const RunRecord&)>& value) {
  std::map<std::uint64_t, double> denominators;
  for (const RunRecord* r : b.ok_runs) denominators[r->spec.seed] = value(*r);
  std::vector<double> ratios;
  for (const RunRecord* r : a.ok_runs) {
    const auto d = denominators.find(r->spec.seed);
    if (d != denominators.end() && d->second != 0) ratios.push_back(value(*r) / d->second);
  }
  return MedianWithInterval(std::move(ratios));
}

double RunMeanTime(const RunRecord& run) { return run.metrics.time_mean_s; }
double RunMeanArea(const RunRecord& run) { return run.metrics.mean_area; }

}  // namespace icp
