// particle-filter against MRPT's particle filter (mrpt_filter.h) on the car
// track, same particle count and models: the mean centre error over seeds
// agrees within statistical noise. Skipped with a message when MRPT
// (libmrpt-bayes-dev) was not found at configure time.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "algorithms/particle_filter/particle_filter.h"
#include "problems/registry.h"

#ifdef ICPBENCH_HAVE_MRPT
#include "algorithms/particle_filter/mrpt_filter.h"
#endif

namespace icp {
namespace {

#ifdef ICPBENCH_HAVE_MRPT

constexpr int kParticles = 600;
constexpr int kSteps = 300;

// The steps of one simulated drive (seed), with the truth.
std::vector<Step> Drive(std::uint64_t seed) {
  return ProblemSteps("car-track", {{"steps", std::to_string(kSteps)}}, seed);
}

double Error(const std::vector<double>& centre, const std::vector<double>& truth) {
  return std::hypot(centre[0] - truth[0], centre[1] - truth[1]);
}

// Mean x-y centre error of particle-filter over a drive (no injection: the
// same model as MRPT's, which injects nothing).
double OursError(const std::vector<Step>& steps, std::uint64_t seed) {
  std::unique_ptr<Estimator> filter = MakeParticleFilter(
      {{"particles", std::to_string(kParticles)}, {"inject", "0"}, {"resample_threshold", "0.5"}},
      seed);
  double sum = 0;
  for (const Step& s : steps) sum += Error(filter->Step(s.views, StopCondition()).estimate->Centre(), s.truth);
  return sum / static_cast<double>(steps.size());
}

double MrptError(const std::vector<Step>& steps, std::uint64_t seed) {
  MrptFilter filter(kParticles, 0.5, seed);
  double sum = 0;
  for (const Step& s : steps) sum += Error(filter.Step(*s.views.probabilistic), s.truth);
  return sum / static_cast<double>(steps.size());
}

// Over 8 seeds (a drive and a filter seed each), the paired difference of
// the mean centre errors is within 2 standard errors (+ 2 cm) of 0.
TEST(ParticleFilterMrptTest, SameAccuracyAsMrptOnTheCarTrack) {
  std::vector<double> ours, mrpt, diff;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const std::vector<Step> steps = Drive(seed);
    ours.push_back(OursError(steps, seed));
    mrpt.push_back(MrptError(steps, seed));
    diff.push_back(ours.back() - mrpt.back());
  }
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  };
  auto standard_error = [&](const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()));
  };
  std::cout << "mean centre error over 8 seeds, " << kParticles << " particles, " << kSteps
            << " steps: particle-filter " << mean(ours) << " m (se " << standard_error(ours)
            << "), MRPT " << mean(mrpt) << " m (se " << standard_error(mrpt) << "), paired difference "
            << mean(diff) << " (se " << standard_error(diff) << ")\n";
  RecordProperty("ours_m", std::to_string(mean(ours)));
  RecordProperty("mrpt_m", std::to_string(mean(mrpt)));
  EXPECT_LE(std::fabs(mean(diff)), 2 * standard_error(diff) + 0.02);
}

#else

TEST(ParticleFilterMrptTest, SameAccuracyAsMrptOnTheCarTrack) {
  GTEST_SKIP() << "MRPT (Debian libmrpt-bayes-dev) was not found when CMake ran: no cross-check";
}

#endif

}  // namespace
}  // namespace icp
