#include "problems/marina_sonar/marina_sonar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "algorithms/registry.h"
#include "core/contractor_algebra.h"
#include "core/random.h"
#include "problems/marina_sonar/marina_map.h"
#include "problems/marina_sonar/sonar_contractor.h"
#include "problems/registry.h"

namespace icp {
namespace {

constexpr double kPi = std::numbers::pi;

const MarinaMap& Shipped() {
  static const MarinaMap map = LoadMarinaMap(ShippedMarinaMapPath());
  return map;
}

MarinaSonarParams Short(int steps = 60) {
  MarinaSonarParams p;
  p.steps = steps;
  return p;
}

std::vector<Step> Drive(const ParamMap& params, std::uint64_t seed) {
  return ProblemSteps("marina-sonar", params, seed);
}

Box Around(const std::vector<double>& p, double r) {
  return Box({Interval(p[0] - r, p[0] + r), Interval(p[1] - r, p[1] + r)});
}

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("marina_sonar_test_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

// --- the map ----------------------------------------------------------------

TEST(MarinaMapTest, ShippedPngIsTheDrawnMapInItsDocumentedFrame) {
  const MarinaMap& map = Shipped();
  const cv::Mat drawn = DrawMarinaMap() != 0;
  ASSERT_EQ(map.image->rows(), 560);
  ASSERT_EQ(map.image->cols(), 920);
  EXPECT_EQ(cv::countNonZero((map.image->pixels() != 0) != drawn), 0)
      << "data/marina.png differs from DrawMarinaMap(): rerun the marina_map tool";
  EXPECT_EQ(map.image->frame().origin_x, 0);
  EXPECT_EQ(map.image->frame().origin_y, 0);
  EXPECT_EQ(map.image->frame().pixel_size, 0.5);
  const Box b = map.image->Bounds();
  EXPECT_LE(b[0].lo(), 0);
  EXPECT_GE(b[0].hi(), 460);
  EXPECT_LE(b[1].lo(), 0);
  EXPECT_GE(b[1].hi(), 280);
  EXPECT_LT(b.MaxWidth(), 460.001);
  // Walls where the README says: the canal's north wall at y = 150-150.5 m,
  // the west quay at x = 19.5-20 m, water in the canal and the basin.
  EXPECT_TRUE(InsideWallPixel(*map.image, 300, 150.25, 0));
  EXPECT_TRUE(InsideWallPixel(*map.image, 19.75, 150, 0));
  EXPECT_FALSE(InsideWallPixel(*map.image, 300, 140, 0));
  EXPECT_FALSE(InsideWallPixel(*map.image, 100, 100, 0));
  EXPECT_LT(std::filesystem::file_size(ShippedMarinaMapPath()), 50000u);
}

TEST(MarinaMapTest, DistanceFieldMeasuresMetres) {
  const MarinaMap& map = Shipped();
  // In the canal at y = 140, the side walls' pixel centres are 9.75 m away.
  EXPECT_NEAR(WallDistance(map, 300.25, 140.25), 9.75, 0.3);
  EXPECT_NEAR(WallDistance(map, 300.25, 150.25), 0, 1e-6);
}

TEST(MarinaMapTest, FrameReaderRejectsBadSidecars) {
  const std::string path = TempPath("frame.yaml");
  auto fails_with = [&](const std::string& text, const std::string& what) {
    std::ofstream(path) << text;
    try {
      ReadMapFrame(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  fails_with("origin_x: 0\norigin_y: 0\n", "lacks the key 'pixel_size'");
  fails_with("origin_x: 0\norigin_y: 0\npixel_size: 0\n", ":3: pixel_size must be > 0");
  fails_with("origin_x: a\n", ":1: origin_x: 'a' is not a finite number");
  fails_with("# c\norigin_z: 1\n", ":2: unknown key 'origin_z'");
  fails_with("origin_x: 1\norigin_x: 1\n", ":2: key 'origin_x' repeated");
  fails_with("origin_x 1\n", ":1: expected 'key: value'");
  std::ofstream(path) << "# frame\norigin_x: -10  # m\norigin_y: 5\npixel_size: 0.25\n";
  const ImageFrame f = ReadMapFrame(path);
  EXPECT_EQ(f.origin_x, -10);
  EXPECT_EQ(f.origin_y, 5);
  EXPECT_EQ(f.pixel_size, 0.25);
  std::filesystem::remove(path);
}

TEST(MarinaMapTest, RayCastFindsTheFirstWallLikeFineStepping) {
  const MarinaMap& map = Shipped();
  RandomEngine rng(7);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const double x = UniformReal(rng, 25, 225), y = UniformReal(rng, 45, 245);
    if (InsideWallPixel(*map.image, x, y, 0)) continue;
    const double a = UniformReal(rng, -kPi, kPi);
    const std::optional<double> t = CastRay(*map.image, x, y, a, 60);
    // Fine stepping: the first sample clearly inside a wall pixel.
    double first = kInf;
    for (double s = 0; s <= 60; s += 0.005)
      if (InsideWallPixel(*map.image, x + s * std::cos(a), y + s * std::sin(a), 1e-3)) {
        first = s;
        break;
      }
    if (!t) {
      EXPECT_EQ(first, kInf) << x << " " << y << " " << a;
      continue;
    }
    ++hits;
    EXPECT_TRUE(InsideWallPixel(*map.image, x + *t * std::cos(a), y + *t * std::sin(a), 1e-6));
    EXPECT_LE(*t, first + 1e-3 + 1e-9) << x << " " << y << " " << a;
    EXPECT_GE(*t, first - 0.01) << x << " " << y << " " << a;
  }
  EXPECT_GT(hits, 100);
}

// --- the simulator ------------------------------------------------------------

TEST(MarinaSimulatorTest, RouteIsAbout600MetresWithALoopAndTheCanal) {
  const MarinaSonarParams p;
  const std::vector<MarinaRecord> drive = SimulateMarinaSonar(p, Shipped(), 1);
  ASSERT_GT(drive.size(), 1100u);
  ASSERT_LE(drive.size(), 1200u);
  double length = 0, min_x = kInf, max_x = -kInf, min_y = kInf, max_y = -kInf, canal = 0;
  for (std::size_t k = 0; k < drive.size(); ++k) {
    const MarinaRecord& r = drive[k];
    ASSERT_TRUE(r.has_truth);
    if (k > 0) {
      const double step = std::hypot(r.truth_x - drive[k - 1].truth_x, r.truth_y - drive[k - 1].truth_y);
      length += step;
      if (r.truth_x > 232) canal += step;
    }
    min_x = std::min(min_x, r.truth_x);
    max_x = std::max(max_x, r.truth_x);
    min_y = std::min(min_y, r.truth_y);
    max_y = std::max(max_y, r.truth_y);
    if (r.truth_x > 232) {
      EXPECT_NEAR(r.truth_y, 140, 3) << "step " << k;
    }
    EXPECT_GT(WallDistance(Shipped(), r.truth_x, r.truth_y), 5) << "step " << k;
  }
  EXPECT_GT(length, 570);
  EXPECT_LT(length, 630);
  EXPECT_GT(canal, 180);  // the straight run along the canal
  EXPECT_GT(max_x, 400);
  EXPECT_LT(min_x, 90);  // the loop round the basin
  EXPECT_LT(min_y, 105);
  EXPECT_GT(max_y, 175);
}

TEST(MarinaSimulatorTest, SeededAndDeterministic) {
  const MarinaSonarParams p = Short();
  EXPECT_EQ(SimulateMarinaSonar(p, Shipped(), 3), SimulateMarinaSonar(p, Shipped(), 3));
  EXPECT_NE(SimulateMarinaSonar(p, Shipped(), 3), SimulateMarinaSonar(p, Shipped(), 4));
}

// Constraints 6.8 at the true wall point H of every inlier return.
TEST(MarinaSimulatorTest, TruthSatisfiesEveryInlierReturn) {
  MarinaSonarParams p;  // the full default drive, out-of-range readings kept
  p.out_of_range = "outlier";
  int inliers = 0, outliers = 0, out_of_range = 0;
  for (std::uint64_t seed : {1, 2}) {
    for (const MarinaRecord& r : SimulateMarinaSonar(p, Shipped(), seed)) {
      EXPECT_EQ(static_cast<int>(r.returns.size()), p.returns_per_step);
      for (const MarinaReturn& s : r.returns) {
        ASSERT_TRUE(s.has_outlier_flag);
        if (s.outlier) {
          ++outliers;
          out_of_range += s.range == p.max_range;
          EXPECT_FALSE(s.has_hit);
          continue;
        }
        ++inliers;
        ASSERT_TRUE(s.has_hit);
        const Interval d = SonarRangeInterval(s.range, s.range_error);
        const Interval a = SonarAngleInterval(r.heading, r.heading_error, s.beam_angle, s.beam_half_width);
        const double dx = s.hit_x - r.truth_x, dy = s.hit_y - r.truth_y;
        EXPECT_TRUE(d.Contains(std::hypot(dx, dy))) << "t " << r.t;
        const double arg = std::atan2(dy, dx);
        const double turns = std::round((a.Mid() - arg) / (2 * kPi));
        EXPECT_TRUE(a.Contains(arg + turns * 2 * kPi)) << "t " << r.t;
        EXPECT_TRUE(InsideWallPixel(*Shipped().image, s.hit_x, s.hit_y, 1e-7)) << "t " << r.t;
        EXPECT_LE(s.range, p.max_range + 4 * p.range_error);
      }
    }
  }
  EXPECT_GT(inliers, 8000);
  EXPECT_GT(outliers, 1000);
  EXPECT_GT(out_of_range, 100);
}

TEST(MarinaSimulatorTest, NoOutliersWhenNoneAreAsked) {
  MarinaSonarParams p = Short(200);
  p.outlier_rate = 0;
  p.out_of_range = "drop";
  for (const MarinaRecord& r : SimulateMarinaSonar(p, Shipped(), 5))
    for (const MarinaReturn& s : r.returns) EXPECT_FALSE(s.outlier);
}

// --- the views ----------------------------------------------------------------

TEST(MarinaSonarViewsTest, EveryInlierContractorKeepsTheTruth) {
  int contracted = 0;
  for (std::uint64_t seed : {1, 2}) {
    for (const Step& step : Drive({{"steps", "60"}}, seed)) {
      const MeasurementSetView& m = *step.views.measurement_set;
      ASSERT_EQ(m.outliers.size(), m.measurements.size());
      for (std::size_t i = 0; i < m.measurements.size(); ++i) {
        if (m.outliers[i]) continue;
        for (double r : {0.0, 0.5, 20.0, 300.0}) {
          Box box = Around(step.truth, r);
          const Box before = box;
          ContractContext context;
          m.measurements[i]->Contract(box, context);
          EXPECT_TRUE(box.Contains(step.truth)) << "step " << step.views.step << " return " << i << " r " << r;
          EXPECT_TRUE(box.IsSubsetOf(before));
          contracted += r == 20.0 && !(box == before);
        }
      }
    }
  }
  EXPECT_GT(contracted, 250);  // the returns bite
}

TEST(MarinaSonarViewsTest, PriorsAndPredictHoldTheTruth) {
  for (const std::string start : {"known", "unknown"}) {
    const std::vector<Step> steps = Drive({{"steps", "60"}, {"start", start}}, 2);
    ASSERT_EQ(steps.size(), 60u);
    Box reckoned;  // dead reckoning from the first prior
    for (const Step& step : steps) {
      const MeasurementSetView& m = *step.views.measurement_set;
      EXPECT_TRUE(m.prior.Contains(step.truth));
      if (step.views.step == 0) {
        EXPECT_FALSE(m.predict);
        EXPECT_EQ(m.prior.MaxWidth() < 3, start == "known");
        reckoned = m.prior;
        continue;
      }
      ASSERT_TRUE(m.predict);
      reckoned = m.predict(reckoned);
      EXPECT_TRUE(reckoned.Contains(step.truth)) << "step " << step.views.step;
      EXPECT_GT(m.prior.MaxWidth(), 400);  // later priors: the whole map
    }
  }
  // One step from a point at the previous truth.
  const std::vector<Step> steps = Drive({{"steps", "200"}}, 4);
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const Box next = steps[k].views.measurement_set->predict(Around(steps[k - 1].truth, 0));
    EXPECT_TRUE(next.Contains(steps[k].truth)) << "step " << k;
    EXPECT_LT(next.MaxWidth(), 0.1);
  }
}

TEST(MarinaSonarViewsTest, CspDeadReckoningKeepsTheTruth) {
  const AlgorithmInfo& hc4 = FindAlgorithm("hc4");
  for (const std::string start : {"known", "unknown"}) {
    for (const Step& step : Drive({{"steps", "40"}, {"w", "10"}, {"start", start}}, 3)) {
      const CspView& v = *step.views.csp;
      const int window = std::min(step.views.step, 10) + 1;
      ASSERT_EQ(v.csp.num_variables(), 2 * window);
      ASSERT_EQ(static_cast<int>(v.csp.constraints().size()), 2 * (window - 1));
      ASSERT_EQ(step.csp_truth.size(), static_cast<std::size_t>(2 * window));
      EXPECT_TRUE(v.csp.domains().Contains(step.csp_truth));
      Box box = v.csp.domains();
      ContractContext context;
      hc4.contractor({}, v.csp)->Contract(box, context);
      EXPECT_TRUE(box.Contains(step.csp_truth)) << start << " step " << step.views.step;
      const Box newest = NewestState(v, box, 2);
      EXPECT_TRUE(newest.Contains(step.truth));
      if (start == "known" && step.views.step <= 10) {
        EXPECT_LT(newest.MaxWidth(), 3);
      }
    }
  }
}

// The repeated q-intersection as a filter over the views: prior ∩
// predict(previous hull), then Fixpoint(QIntersection(returns, q_k)).
Box Filter(const Step& step, const Box& previous, int q) {
  const MeasurementSetView& m = *step.views.measurement_set;
  Box box = m.prior;
  if (m.predict && !previous.IsEmpty()) box = Intersect(box, m.predict(previous));
  FixpointContractor fixpoint(std::make_shared<QIntersectionContractor>(m.measurements, q), 1e-3, 100);
  ContractContext context;
  fixpoint.Contract(box, context);
  return box;
}

int TrueOutliers(const Step& step) {
  const auto& o = step.views.measurement_set->outliers;
  return static_cast<int>(std::count(o.begin(), o.end(), true));
}

TEST(MarinaSonarViewsTest, ZeroOutliersTheIntersectionAlwaysHoldsTheTruth) {
  Box hull;
  double width = 0;
  const std::vector<Step> steps =
      Drive({{"steps", "60"}, {"outlier_rate", "0"}, {"out_of_range", "drop"}}, 6);
  for (const Step& step : steps) {
    ASSERT_EQ(TrueOutliers(step), 0);
    hull = Filter(step, hull, 0);
    ASSERT_TRUE(hull.Contains(step.truth)) << "step " << step.views.step;
    width = std::max(width, hull.MaxWidth());
  }
  EXPECT_LT(width, 5);
  // And through the registered algorithm.
  auto q_relaxed = FindAlgorithm("q-relaxed").make({{"q", "0"}, {"auto_q", "false"}}, 0);
  for (const Step& step : steps)
    EXPECT_TRUE(q_relaxed->Step(step.views, StopCondition()).estimate->Contains(step.truth))
        << "step " << step.views.step;
}

TEST(MarinaSonarViewsTest, WithQAtLeastTheTrueOutliersAlwaysHoldsTheTruth) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const std::vector<Step> steps = Drive({{"steps", "60"}, {"outlier_rate", "0.2"}}, seed);
    Box hull;
    int most = 0;
    for (const Step& step : steps) {
      hull = Filter(step, hull, TrueOutliers(step));
      ASSERT_TRUE(hull.Contains(step.truth)) << "seed " << seed << " step " << step.views.step;
      most = std::max(most, TrueOutliers(step));
    }
    EXPECT_GT(most, 0);
    auto q_relaxed =
        FindAlgorithm("q-relaxed").make({{"q", std::to_string(most)}, {"auto_q", "false"}}, 0);
    for (const Step& step : steps)
      EXPECT_TRUE(q_relaxed->Step(step.views, StopCondition()).estimate->Contains(step.truth))
          << "seed " << seed << " step " << step.views.step;
  }
}

// The probabilistic view's state: (x, y) and the zero biases.
std::vector<double> WithZeroBiases(const std::vector<double>& xy) { return {xy[0], xy[1], 0, 0, 0}; }

TEST(MarinaSonarViewsTest, ProbabilisticViewDrawsWithinTheBounds) {
  const std::vector<Step> steps = Drive({{"steps", "30"}}, 8);
  RandomEngine rng(1);
  const Box bounds = Shipped().image->Bounds();
  const MarinaSonarParams defaults;
  int better = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const ProbabilisticView& pv = *steps[k].views.probabilistic;
    const std::vector<double> start = pv.sample_prior(rng);
    ASSERT_EQ(start.size(), 5u);
    EXPECT_TRUE(Around(steps[0].truth, 1).Contains({start[0], start[1]}));
    EXPECT_LE(std::fabs(start[kMarinaBiasU]), defaults.dvl_error);
    EXPECT_LE(std::fabs(start[kMarinaBiasV]), defaults.dvl_error);
    EXPECT_LE(std::fabs(start[kMarinaBiasHeading]), defaults.compass_error);
    const std::vector<double> global = pv.sample_global(rng);
    EXPECT_TRUE(bounds.Contains({global[0], global[1]}));
    if (k > 0) {
      // With zero biases the drawn motion stays within the bounded errors.
      const Box reach = steps[k].views.measurement_set->predict(Around(steps[k - 1].truth, 0));
      for (int i = 0; i < 20; ++i) {
        std::vector<double> s = WithZeroBiases(steps[k - 1].truth);
        pv.sample_motion(s, rng);
        EXPECT_TRUE(reach.Contains({s[0], s[1]}));
      }
    }
    const double at_truth = pv.log_likelihood(WithZeroBiases(steps[k].truth));
    EXPECT_TRUE(std::isfinite(at_truth));
    better += at_truth > pv.log_likelihood(
                             WithZeroBiases({steps[k].truth[0] + 7, steps[k].truth[1] - 5}));
  }
  EXPECT_GE(better, 20);
  // Off the map the robot cannot be.
  EXPECT_EQ(steps[0].views.probabilistic->log_likelihood(
                WithZeroBiases({bounds[0].hi() + 1, bounds[1].Mid()})),
            -std::numeric_limits<double>::infinity());
  const std::vector<Step> global = Drive({{"steps", "2"}, {"start", "unknown"}}, 8);
  EXPECT_GT(global[0].views.measurement_set->prior.MaxWidth(), 400);
}

// The outlier component: a return whose end point is far from every wall
// costs the true position at most the uniform's share, kSonarTemper log(eps
// / max_range), where the Gaussian alone would all but zero it.
TEST(MarinaSonarViewsTest, AWildReturnNeverZeroesThePosition) {
  MarinaSonarParams p;
  p.steps = 1;
  MarinaRecord r = SimulateMarinaSonar(p, Shipped(), 3).at(0);
  ASSERT_FALSE(r.returns.empty());
  const double x = r.truth_x, y = r.truth_y;
  const double clean = MarinaLogLikelihood(Shipped(), r, p.max_range, 0.1, x, y);
  MarinaReturn wild = r.returns[0];
  double far = 0;
  for (double range = 1; range < p.max_range && far < 8; range += 0.5) {
    const double a = r.heading + wild.beam_angle;
    wild.range = range;
    far = WallDistance(Shipped(), x + range * std::cos(a), y + range * std::sin(a));
  }
  ASSERT_GE(far, 8);
  r.returns.push_back(wild);
  const double with_wild = MarinaLogLikelihood(Shipped(), r, p.max_range, 0.1, x, y);
  EXPECT_LT(with_wild, clean);
  EXPECT_GE(with_wild - clean, kSonarTemper * std::log(0.1 / p.max_range) - 1e-12);
  // Nearly without the outlier component the same return costs several
  // times more (its end point is 8 m or more from every wall).
  MarinaRecord without = r;
  without.returns.pop_back();
  EXPECT_LT(MarinaLogLikelihood(Shipped(), r, p.max_range, 1e-12, x, y) -
                MarinaLogLikelihood(Shipped(), without, p.max_range, 1e-12, x, y),
            4 * kSonarTemper * std::log(0.1 / p.max_range));
  // At the smallest floor the parameter accepts, floor / max_range
  // underflows to 0, and so does the Gaussian far from the walls: the cost
  // stays the floor's, finite (it was log 0 = -inf, and every particle fell).
  const double tiniest = std::numeric_limits<double>::denorm_min();
  const double cost = MarinaLogLikelihood(Shipped(), r, p.max_range, tiniest, x, y) -
                      MarinaLogLikelihood(Shipped(), without, p.max_range, tiniest, x, y);
  EXPECT_TRUE(std::isfinite(cost)) << cost;
  EXPECT_GE(cost, kSonarTemper * (std::log(tiniest) - std::log(p.max_range)) - 1e-9);
}

// --- the log ------------------------------------------------------------------

TEST(MarinaLogTest, WriteThenReadGivesTheSameSteps) {
  const std::vector<MarinaRecord> drive = SimulateMarinaSonar(Short(50), Shipped(), 9);
  std::stringstream text;
  WriteMarinaLog(drive, text, "seed 9\nsteps 50");
  EXPECT_EQ(ReadMarinaLog(text, "mem"), drive);
  // Through the problem: the same truths and measurements as the simulator.
  const std::string path = TempPath("log.csv");
  {
    std::ofstream out(path);
    WriteMarinaLog(drive, out);
  }
  const std::vector<Step> simulated = Drive({{"steps", "50"}}, 9);
  const std::vector<Step> read = Drive({{"steps", "50"}, {"log", path}}, 123);
  ASSERT_EQ(read.size(), simulated.size());
  for (std::size_t k = 0; k < read.size(); ++k) {
    EXPECT_EQ(read[k].truth, simulated[k].truth);
    EXPECT_EQ(read[k].views.measurement_set->outliers, simulated[k].views.measurement_set->outliers);
    EXPECT_EQ(read[k].views.csp->csp.domains(), simulated[k].views.csp->csp.domains());
  }
  std::filesystem::remove(path);
}

// --- the registry -----------------------------------------------------------

TEST(MarinaRegistryTest, RegisteredWithThreeViewsAndCheckedParameters) {
  const ProblemInfo& info = FindProblem("marina-sonar");
  EXPECT_EQ(info.offers,
            (std::vector<View>{View::kCsp, View::kMeasurementSet, View::kProbabilistic}));
  const ParamMap resolved = info.resolve("marina-sonar", {});
  EXPECT_EQ(resolved.at("start"), "known");
  EXPECT_EQ(resolved.at("steps"), "1200");
  EXPECT_THROW(info.resolve("marina-sonar", {{"start", "maybe"}}), ParamError);
  EXPECT_THROW(info.resolve("marina-sonar", {{"outlier_rate", "1.5"}}), ParamError);
  EXPECT_THROW(info.resolve("marina-sonar", {{"map", ShippedMarinaMapPath()}}), ParamError);
  EXPECT_THROW(info.resolve("marina-sonar", {{"log", "/nonexistent.csv"}}), std::invalid_argument);
  // A log without truth cannot start known.
  const std::string path = TempPath("notruth.csv");
  std::ofstream(path) << "step,0,0.5,0,0.02,1.5,0.01,,\n";
  EXPECT_THROW(info.resolve("marina-sonar", {{"log", path}}), ParamError);
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"log", path}, {"start", "unknown"}}));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace icp
