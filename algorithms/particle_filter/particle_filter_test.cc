#include "algorithms/particle_filter/particle_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <variant>

#include "algorithms/registry.h"
#include "core/credible_box.h"
#include "problems/beacon_ranges/beacon_ranges.h"
#include "problems/car_track/car_track.h"

namespace icp {
namespace {

constexpr double kPi = std::numbers::pi;

// What the tests look at of one step.
struct Seen {
  std::vector<double> centre, truth;
  Box region;
  bool contained = false;
  Properties properties;
};

const Property& Get(const Properties& properties, const std::string& name) {
  for (const Property& p : properties)
    if (p.name == name) return p;
  throw std::runtime_error("no property " + name);
}

// The filter over every step of problem; truth moved, on periodic
// components, to the region's frame as the harness does.
std::vector<Seen> RunFilter(Problem& problem, const ParamMap& params, std::uint64_t seed) {
  std::unique_ptr<Estimator> filter = MakeParticleFilter(params, seed);
  std::vector<Seen> out;
  Step step;
  while (problem.Next(&step)) {
    StepResult r = filter->Step(step.views, StopCondition());
    Seen s;
    s.centre = r.estimate->Centre();
    s.region = r.estimate->Hull();
    s.truth = step.truth;
    for (int c = 0; c < step.views.space.size(); ++c) {
      const double period = step.views.space.Period(c);
      if (period > 0) {
        const double mid = (s.region[c].lo() + s.region[c].hi()) / 2;
        s.truth[c] += period * std::round((mid - s.truth[c]) / period);
      }
    }
    s.contained = r.estimate->Contains(s.truth);
    s.properties = r.properties;
    for (const Property& p : r.estimate->Extras()) s.properties.push_back(p);
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Seen> CarTrack(const ParamMap& problem, const ParamMap& params, std::uint64_t seed) {
  std::unique_ptr<Problem> p = MakeCarTrack(problem, 7);
  return RunFilter(*p, params, seed);
}

TEST(SystematicResampleTest, KnownWeightsGiveKnownCounts) {
  // Positions 0.05, 0.15, ..., 0.95 over the cumulative 0.1, 0.3, 0.6, 1.
  const std::vector<std::size_t> index = SystematicResample({0.1, 0.2, 0.3, 0.4}, 10, 0.5);
  EXPECT_EQ(index, (std::vector<std::size_t>{0, 1, 1, 2, 2, 2, 3, 3, 3, 3}));
  // Not normalised, zero weights never drawn.
  EXPECT_EQ(SystematicResample({0, 2, 0, 2}, 4, 0.999), (std::vector<std::size_t>{1, 1, 3, 3}));
  EXPECT_EQ(SystematicResample({0, 0, 5}, 3, 0), (std::vector<std::size_t>{2, 2, 2}));
  EXPECT_THROW(SystematicResample({0, 0}, 2, 0.5), std::invalid_argument);
  EXPECT_THROW(SystematicResample({1, -1}, 2, 0.5), std::invalid_argument);
  EXPECT_THROW(SystematicResample({1, 1}, 2, 1.0), std::invalid_argument);
}

TEST(SystematicResampleTest, EachCountIsTheFloorOrTheCeilingOfNTimesItsWeight) {
  RandomEngine rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t m = 1 + UniformIndex(rng, 30), n = 1 + UniformIndex(rng, 100);
    std::vector<double> w(m);
    double total = 0;
    for (double& x : w) total += x = UniformIndex(rng, 4) == 0 ? 0 : UniformReal(rng, 0, 1);
    if (total == 0) w[0] = total = 1;
    const std::vector<std::size_t> index = SystematicResample(w, n, UniformReal(rng, 0, 1));
    ASSERT_EQ(index.size(), n);
    ASSERT_TRUE(std::is_sorted(index.begin(), index.end()));
    for (std::size_t j = 0; j < m; ++j) {
      const double expected = static_cast<double>(n) * w[j] / total;
      const auto count = static_cast<double>(std::count(index.begin(), index.end(), j));
      EXPECT_GE(count, std::floor(expected - 1e-9)) << trial << " " << j;
      EXPECT_LE(count, std::ceil(expected + 1e-9)) << trial << " " << j;
    }
  }
}

TEST(MultinomialResampleTest, DrawsInProportionAndNeverAZeroWeight) {
  RandomEngine rng(5);
  const std::vector<std::size_t> index = MultinomialResample({1, 0, 3}, 4000, rng);
  ASSERT_EQ(index.size(), 4000u);
  EXPECT_EQ(std::count(index.begin(), index.end(), 1u), 0);
  EXPECT_NEAR(std::count(index.begin(), index.end(), 2u) / 4000.0, 0.75, 0.03);
}

TEST(ParticleFilterTest, RegisteredWithItsParameters) {
  const AlgorithmInfo& info = FindAlgorithm("particle-filter");
  EXPECT_EQ(info.needs, View::kProbabilistic);
  const ParamMap defaults = info.resolve("particle-filter", {});
  EXPECT_EQ(defaults.at("particles"), "600");
  EXPECT_EQ(defaults.at("resampling"), "systematic");
  EXPECT_EQ(defaults.at("region"), "95");
  EXPECT_THROW(info.resolve("particle-filter", {{"resampling", "residual"}}), ParamError);
  EXPECT_THROW(info.resolve("particle-filter", {{"inject", "0.9"}}), ParamError);
  EXPECT_THROW(info.resolve("particle-filter", {{"particles", "0"}}), ParamError);
}

TEST(ParticleFilterTest, DeterministicForASeed) {
  const ParamMap problem = {{"steps", "60"}};
  const ParamMap params = {{"particles", "200"}};
  const std::vector<Seen> a = CarTrack(problem, params, 1), b = CarTrack(problem, params, 1);
  const std::vector<Seen> c = CarTrack(problem, params, 2);
  ASSERT_EQ(a.size(), 60u);
  int differ = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].centre, b[k].centre) << k;
    EXPECT_EQ(a[k].region, b[k].region) << k;
    differ += a[k].centre != c[k].centre;
  }
  EXPECT_GT(differ, 50);
  // The multinomial scheme too.
  const ParamMap multinomial = {{"particles", "200"}, {"resampling", "multinomial"}};
  EXPECT_EQ(CarTrack(problem, multinomial, 4).back().centre,
            CarTrack(problem, multinomial, 4).back().centre);
}

// The weighted mean stays within the GPS half-width of the truth, on x and
// on y, on most steps of a drive with a fix at every step and the heading
// unknown at the start. Measured (300 particles, 400 steps, drive seed 7,
// filter seeds 1-3): 97.75 to 98.25 % of the steps (the misses are the
// first steps, while the heading is still unknown). The containment rate is
// reported, not tested: the default region held the truth on 48.5 to 71 %
// of the steps, the hull on 54.75 to 72.5 % (a cloud this small loses the
// true heading after a start with the heading unknown, and is drawn anew
// from the GPS box when every particle has left it).
TEST(ParticleFilterTest, MeanStaysWithinTheGpsBoundOnTheCarTrack) {
  const double gps_error = CarTrackParams().gps_error;
  for (std::uint64_t seed : {1, 2, 3}) {
    for (const char* region : {"95", "hull"}) {
      const std::vector<Seen> steps =
          CarTrack({{"steps", "400"}}, {{"particles", "300"}, {"region", region}}, seed);
      int within = 0, contained = 0;
      for (const Seen& s : steps) {
        ASSERT_EQ(s.centre.size(), 3u);
        within += std::fabs(s.centre[0] - s.truth[0]) <= gps_error &&
                  std::fabs(s.centre[1] - s.truth[1]) <= gps_error;
        contained += s.contained;
        EXPECT_TRUE(std::isfinite(s.centre[2]));
      }
      const double within_rate = within / static_cast<double>(steps.size());
      const double containment = contained / static_cast<double>(steps.size());
      std::cout << "seed " << seed << " region " << region << ": mean within the GPS bound on "
                << within_rate * 100 << " % of the steps; region holds the truth on "
                << containment * 100 << " %\n";
      ::testing::Test::RecordProperty("within_gps_bound_" + std::to_string(seed) + "_" + region,
                                      std::to_string(within_rate));
      ::testing::Test::RecordProperty("containment_" + std::to_string(seed) + "_" + region,
                                      std::to_string(containment));
      EXPECT_GE(within_rate, 0.95) << seed << " " << region;
    }
  }
}

// Moving beacon ranges with 2 outliers of 6 per step, started anywhere in
// the search box: after the first steps the mean tracks the truth.
// Measured (600 particles, seeds 1-3): within 0.5 of the truth on all of
// steps 10-49, the worst error 0.05, 0.46 and 0.04.
TEST(ParticleFilterTest, TracksTheMovingBeaconRangesWithOutliers) {
  for (std::uint64_t seed : {1, 2, 3}) {
    std::unique_ptr<Problem> problem =
        MakeBeaconRanges({{"scenario", "moving"}, {"steps", "50"}, {"outliers", "2"}}, seed);
    const std::vector<Seen> steps = RunFilter(*problem, {}, seed);
    ASSERT_EQ(steps.size(), 50u);
    int close = 0;
    double worst = 0;
    for (std::size_t k = 10; k < steps.size(); ++k) {
      const double error = std::hypot(steps[k].centre[0] - steps[k].truth[0],
                                      steps[k].centre[1] - steps[k].truth[1]);
      close += error < 0.5;
      worst = std::max(worst, error);
    }
    std::cout << "beacon seed " << seed << ": within 0.5 of the truth on " << close << " of 40 steps, worst "
              << worst << "\n";
    EXPECT_GE(close, 36) << seed;
  }
}

// A view whose states are one periodic angle about pi, and a likelihood
// that only f allows.
StateSpace Angle() {
  StateSpace space;
  space.names = {"th"};
  space.periods = {2 * kPi};
  return space;
}

TEST(ParticleFilterTest, CircularMeanAcrossTheCut) {
  Views views;
  views.space = Angle();
  ProbabilisticView view;
  // Angles within 0.2 of pi, drawn on both sides of the cut at +-pi.
  view.sample_prior = [](RandomEngine& rng) {
    const double a = UniformReal(rng, kPi - 0.2, kPi + 0.2);
    return std::vector<double>{a > kPi ? a - 2 * kPi : a};
  };
  view.log_likelihood = [](const std::vector<double>&) { return 0.0; };
  views.probabilistic = view;
  std::unique_ptr<Estimator> filter = MakeParticleFilter({{"particles", "500"}}, 1);
  const StepResult r = filter->Step(views, StopCondition());
  const std::vector<double> centre = r.estimate->Centre();
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_NEAR(std::cos(centre[0]), -1, 1e-3);
  const Box region = r.estimate->Hull();
  EXPECT_LT(region[0].Width(), 0.41);
  EXPECT_TRUE(region[0].Contains(centre[0]));
  EXPECT_LT(std::get<double>(Get(r.properties, "cov_th_th").value), 0.02);
}

// A concentrated cloud's mean is taken in the chart of the previous centre,
// without sines: across the cut it is the circular mean up to third-order
// terms in the spread, and the particles lie within half a turn of it.
TEST(ParticleFilterTest, ConcentratedCloudMeanIsTheCircularMeanAcrossTheCut) {
  Views views;
  views.space = Angle();
  ProbabilisticView view;
  view.sample_prior = [](RandomEngine& rng) { return std::vector<double>{UniformReal(rng, kPi - 0.05, kPi + 0.05)}; };
  // Turns by 0.1 +- 0.3: the cloud straddles the cut, spread below 1/16 turn.
  view.sample_motion = [](std::vector<double>& s, RandomEngine& rng) { s[0] += UniformReal(rng, -0.2, 0.4); };
  view.log_likelihood = [](const std::vector<double>& s) { return std::cos(s[0]); };
  views.probabilistic = view;
  std::unique_ptr<Estimator> filter = MakeParticleFilter({{"particles", "500"}}, 3);
  filter->Step(views, StopCondition());
  const StepResult r = filter->Step(views, StopCondition());
  const auto& estimate = dynamic_cast<const ParticleEstimate&>(*r.estimate);
  double sum_sin = 0, sum_cos = 0, total = 0;
  for (int i = 0; i < estimate.particles().rows; ++i) {
    const double a = estimate.particles().at<double>(i, 0), w = estimate.weights()[i];
    sum_sin += w * std::sin(a);
    sum_cos += w * std::cos(a);
    total += w;
  }
  const double centre = r.estimate->Centre()[0];
  const double circular = std::atan2(sum_sin, sum_cos);
  EXPECT_NEAR(std::remainder(centre - circular, 2 * kPi), 0, 1e-3);
  EXPECT_GT(std::fabs(centre), 3.0);  // near pi, not averaged to 0 across the cut
  for (int i = 0; i < estimate.particles().rows; ++i)
    EXPECT_LE(std::fabs(estimate.particles().at<double>(i, 0) - centre), kPi);
  EXPECT_GT(total, 0);
}

// After a resampling that leaves few distinct particles, roughen jitters
// each by about roughen times the weighed cloud's spread: the copies part,
// and stay near where they were. By default the view's roughen; the
// parameter overrides it (0 too).
TEST(ParticleFilterTest, RoughenPartsTheCopiesOfAResampling) {
  auto distinct_after_resampling = [](std::optional<double> roughen, double view_roughen, double* spread) {
    StateSpace space;
    space.names = {"x"};
    Views first;
    first.space = space;
    ProbabilisticView view;
    view.sample_prior = [](RandomEngine& rng) { return std::vector<double>{UniformReal(rng, 0, 1)}; };
    // Only the particles in [0.5, 0.52] survive the first weighing.
    view.log_likelihood = [](const std::vector<double>& s) {
      return s[0] >= 0.5 && s[0] <= 0.52 ? 0.0 : -std::numeric_limits<double>::infinity();
    };
    view.roughen = view_roughen;
    first.probabilistic = view;
    Views second = first;
    second.probabilistic->log_likelihood = [](const std::vector<double>&) { return 0.0; };
    ParamMap params = {{"particles", "500"}, {"inject", "0"}, {"resample_threshold", "1"}};
    if (roughen) params["roughen"] = std::to_string(*roughen);
    std::unique_ptr<Estimator> filter = MakeParticleFilter(params, 5);
    filter->Step(first, StopCondition());
    const StepResult r = filter->Step(second, StopCondition());
    const cv::Mat& cloud = dynamic_cast<const ParticleEstimate&>(*r.estimate).particles();
    std::vector<double> values(cloud.begin<double>(), cloud.end<double>());
    *spread = *std::max_element(values.begin(), values.end()) - *std::min_element(values.begin(), values.end());
    std::sort(values.begin(), values.end());
    return std::unique(values.begin(), values.end()) - values.begin();
  };
  double spread_without = 0, spread_with = 0, spread_of_view = 0, spread_overridden = 0;
  EXPECT_LE(distinct_after_resampling(0.0, 0, &spread_without), 20);  // about 10 survivors, copied
  EXPECT_LE(spread_without, 0.02);
  EXPECT_EQ(distinct_after_resampling(0.5, 0, &spread_with), 500);
  EXPECT_GT(spread_with, spread_without);
  EXPECT_LT(spread_with, 0.06);  // the survivors' 0.02 widened by about 0.5 of their sd a side
  EXPECT_EQ(distinct_after_resampling(std::nullopt, 0.5, &spread_of_view), 500);
  EXPECT_EQ(spread_of_view, spread_with);  // the same draws
  EXPECT_LE(distinct_after_resampling(0.0, 0.5, &spread_overridden), 20);
  EXPECT_THROW(MakeParticleFilter({{"roughen", "-0.5"}}, 1), ParamError);
  EXPECT_THROW(ResolveParticleFilter("particle-filter", {{"roughen", "-0.5"}}), ParamError);
  EXPECT_EQ(ResolveParticleFilter("particle-filter", {}).at("roughen"), "-1");
}

TEST(ParticleFilterTest, EveryParticleImpossibleReinitialisesWithoutNaN) {
  Views views;
  views.space.names = {"x", "y"};
  views.space.x = 0;
  views.space.y = 1;
  ProbabilisticView view;
  view.sample_prior = [](RandomEngine& rng) {
    return std::vector<double>{UniformReal(rng, 0, 1), UniformReal(rng, 0, 1)};
  };
  // Only x > 10 is possible: the prior never is, the global prior is.
  view.log_likelihood = [](const std::vector<double>& s) {
    return s[0] > 10 ? 0.0 : -std::numeric_limits<double>::infinity();
  };
  view.sample_global = [](RandomEngine& rng) {
    return std::vector<double>{UniformReal(rng, 11, 12), UniformReal(rng, 0, 1)};
  };
  views.probabilistic = view;
  std::unique_ptr<Estimator> filter = MakeParticleFilter({{"particles", "100"}}, 1);
  StepResult r = filter->Step(views, StopCondition());
  EXPECT_EQ(std::get<std::int64_t>(Get(r.properties, "reinitialised").value), 1);
  EXPECT_GT(r.estimate->Centre()[0], 10);
  // Nothing is ever possible: equal weights, still no NaN.
  views.probabilistic->log_likelihood = [](const std::vector<double>&) {
    return std::numeric_limits<double>::quiet_NaN();
  };
  views.probabilistic->sample_global = nullptr;
  r = filter->Step(views, StopCondition());
  EXPECT_EQ(std::get<std::int64_t>(Get(r.properties, "reinitialised").value), 1);
  for (double c : r.estimate->Centre()) EXPECT_TRUE(std::isfinite(c));
  EXPECT_FALSE(r.estimate->Hull().IsEmpty());
  EXPECT_EQ(IntProperty(filter->RunProperties(), "reinitialisations"), 2);
}

// Over every step of problem: the "95" region is the box of the weighted
// quantiles t, 1 - t of each of the d components (t = CredibleTail(0.95,
// d)), so it holds at least 1 - 2 d t of the weight; "hull" holds every
// particle.
void ExpectRegionsHoldTheirWeight(Problem& problem, Estimator& filter, const std::string& region) {
  Step step;
  while (problem.Next(&step)) {
    const StepResult r = filter.Step(step.views, StopCondition());
    const auto& estimate = dynamic_cast<const ParticleEstimate&>(*r.estimate);
    const cv::Mat& cloud = estimate.particles();
    const std::vector<double>& w = estimate.weights();
    const Box box = estimate.Hull();
    double inside = 0, total = 0;
    for (int i = 0; i < cloud.rows; ++i) {
      total += w[i];
      bool in = true;
      for (int c = 0; c < cloud.cols; ++c) in = in && box[c].Contains(cloud.at<double>(i, c));
      inside += in ? w[i] : 0;
    }
    if (region == "hull") {
      EXPECT_EQ(box, estimate.ParticleHull());
      EXPECT_EQ(inside, total);
      continue;
    }
    // Each side of each component leaves out tail of the weight: the union
    // bound.
    const double tail = CredibleTail(0.95, cloud.cols), eps = 1e-9;
    EXPECT_GE(inside, (1 - 2 * cloud.cols * tail) * total - eps) << step.views.step;
    for (int c = 0; c < cloud.cols; ++c) {
      std::vector<double> values(cloud.rows);
      for (int i = 0; i < cloud.rows; ++i) values[i] = cloud.at<double>(i, c);
      // The filter sums the weights in another order: a weight exactly at
      // the quantile may round to either side.
      EXPECT_GE(box[c].lo(), WeightedQuantile(values, w, tail - eps)) << step.views.step << " " << c;
      EXPECT_LE(box[c].lo(), WeightedQuantile(values, w, tail + eps)) << step.views.step << " " << c;
      EXPECT_GE(box[c].hi(), WeightedQuantile(values, w, 1 - tail - eps)) << step.views.step << " " << c;
      EXPECT_LE(box[c].hi(), WeightedQuantile(values, w, 1 - tail + eps)) << step.views.step << " " << c;
    }
  }
}

TEST(ParticleFilterTest, RegionsAreTheQuantileBoxAndTheHull) {
  for (const char* region : {"95", "hull"}) {
    std::unique_ptr<Problem> problem = MakeCarTrack({{"steps", "40"}}, 3);
    std::unique_ptr<Estimator> filter = MakeParticleFilter({{"particles", "500"}, {"region", region}}, 2);
    ExpectRegionsHoldTheirWeight(*problem, *filter, region);
  }
  // Unequal weights: the moving beacon ranges' mixture likelihood.
  std::unique_ptr<Problem> problem = MakeBeaconRanges({{"scenario", "moving"}, {"steps", "20"}}, 2);
  std::unique_ptr<Estimator> filter = MakeParticleFilter({{"particles", "700"}}, 2);
  ExpectRegionsHoldTheirWeight(*problem, *filter, "95");
}

TEST(ParticleFilterTest, TheQuantileBoxOfAMillionParticlesIsASelection) {
  // Particles drawn in decreasing order, equal weights: the "95" region used
  // to insert each value into the sorted few smallest, about 0.05 n of them,
  // so n^2 / 20 moves (half a minute here; 1e7 particles, the allowed
  // maximum, took 355 s against 12 s for "hull"). The budget is 25 times
  // what a selection takes.
  const int n = 1000003;  // 0.025 n is no integer: the quantiles do not hang on a rounding
  Views views;
  views.space.names = {"x"};
  ProbabilisticView view;
  double next = 0;
  view.sample_prior = [&](RandomEngine&) { return std::vector<double>{next--}; };
  view.log_likelihood = [](const std::vector<double>&) { return 0.0; };
  views.probabilistic = view;
  std::unique_ptr<Estimator> filter =
      MakeParticleFilter({{"particles", std::to_string(n)}, {"inject", "0"}}, 1);
  const auto start = std::chrono::steady_clock::now();
  const StepResult r = filter->Step(views, StopCondition());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10) << "the region's tail selection is no longer linear";
  // Values 0, -1, ..., -(n - 1), each of weight 1 / n: the least value whose
  // weight at or below exceeds q is the (floor(q n) + 1)-th smallest.
  const Box box = r.estimate->Hull();
  EXPECT_EQ(box[0].lo(), -(n - 1) + std::floor(0.025 * n));
  EXPECT_EQ(box[0].hi(), -(n - 1) + std::floor(0.975 * n));
}

TEST(ParticleFilterTest, ResamplesAndInjectsAsTold) {
  const ParamMap problem = {{"steps", "30"}};
  const std::vector<Seen> every = CarTrack(problem, {{"particles", "100"}, {"resample_threshold", "1"}}, 1);
  for (const Seen& s : every) {
    EXPECT_EQ(std::get<std::int64_t>(Get(s.properties, "resampled").value), 1);
    EXPECT_EQ(std::get<std::int64_t>(Get(s.properties, "injected").value), 2);
  }
  const std::vector<Seen> never =
      CarTrack(problem, {{"particles", "100"}, {"resample_threshold", "0"}, {"inject", "0"}}, 1);
  for (const Seen& s : never) EXPECT_EQ(std::get<std::int64_t>(Get(s.properties, "resampled").value), 0);
  // The mean and covariance properties, one per component and pair.
  const Properties& p = every.back().properties;
  EXPECT_EQ(std::get<double>(Get(p, "mean_x").value), every.back().centre[0]);
  EXPECT_GE(std::get<double>(Get(p, "cov_y_y").value), 0);
  EXPECT_NO_THROW(Get(p, "cov_x_theta"));
  EXPECT_NO_THROW(Get(p, "effective_sample_size"));
}

TEST(ParticleFilterTest, NeedsTheProbabilisticView) {
  std::unique_ptr<Estimator> filter = MakeParticleFilter({}, 1);
  EXPECT_THROW(filter->Step(Views(), StopCondition()), std::invalid_argument);
}

}  // namespace
}  // namespace icp
