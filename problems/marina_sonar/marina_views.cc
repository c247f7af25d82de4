// What each marina-sonar step offers: MarinaSonarProblem::Next builds the
// measurement-set, CSP and probabilistic views (header comment), the last
// with the sonar's likelihood field (MarinaLogLikelihood).
#include "problems/marina_sonar/marina_sonar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/constraint_system.h"
#include "core/random.h"
#include "problems/marina_sonar/sonar_contractor.h"
#include "problems/planar.h"

namespace icp {

namespace {
const double kSqrtTwoPi = std::sqrt(2 * std::acos(-1.0));
// The particle filter's motion (header comment): the white part of each
// DVL or compass error, uniform within this share of its bound; each step
// a bias moves uniformly within this share of its bound (so that
// resampling keeps the biases diverse), staying within the bound.
constexpr double kWhiteShare = 0.5;
constexpr double kBiasWander = 0.01;
}  // namespace

double MarinaLogLikelihood(const MarinaMap& map, const MarinaRecord& r, double max_range,
                           double outlier_weight, double x, double y, double heading_bias) {
  if (!map.bounds[0].Contains(x) || !map.bounds[1].Contains(y))
    return -std::numeric_limits<double>::infinity();
  const double pixel = map.image->frame().pixel_size;
  const double outlier = outlier_weight / max_range;  // uniform over the sonar's range
  // Where the mixture underflows (a floor near the smallest double), its log
  // is the outlier part's, taken in logs: finite, as the floor promises.
  const double log_outlier = std::log(outlier_weight) - std::log(max_range);
  double sum = 0;
  for (const MarinaReturn& ret : r.returns) {
    if (!(ret.range < max_range)) continue;
    const double a = r.heading - heading_bias + ret.beam_angle;
    const double dist = WallDistance(map, x + ret.range * std::cos(a), y + ret.range * std::sin(a));
    const double sigma = std::max(
        pixel, std::hypot(ret.range_error, ret.range * (r.heading_error + ret.beam_half_width)));
    const double inlier = std::exp(-dist * dist / (2 * sigma * sigma)) / (kSqrtTwoPi * sigma);
    const double mixture = (1 - outlier_weight) * inlier + outlier;
    sum += mixture > 0 ? std::log(mixture) : log_outlier;
  }
  return kSonarTemper * sum;
}

namespace {

std::vector<double> UniformIn(const Box& box, RandomEngine& rng) {
  return {UniformReal(rng, box[0].lo(), box[0].hi()), UniformReal(rng, box[1].lo(), box[1].hi())};
}

// Uniform over box, away from walls (a few tries; the last one is kept).
std::vector<double> UniformInWater(const Box& box, const BinaryImage& map, RandomEngine& rng) {
  std::vector<double> p = UniformIn(box, rng);
  for (int i = 0; i < 64 && InsideWallPixel(map, p[0], p[1], 0); ++i) p = UniformIn(box, rng);
  return p;
}

}  // namespace

bool MarinaSonarProblem::Next(Step* step) {
  if (k_ >= num_steps_) return false;
  const int k = k_++;
  // known and area start from a box about the truth, unknown from the map.
  const bool known = params_.start != "unknown";
  const MarinaRecord& r = records_[k];
  *step = Step();
  step->views.step = k;
  step->views.space = PlanarStateSpace();

  // The measurement set.
  MeasurementSetView set;
  set.prior = k == 0 && known ? start_box_ : map_.bounds;
  bool flags_known = true;
  std::vector<bool> outliers;
  // From this step back: carried holds the displacement from step j to k.
  Displacement carried{Interval(0), Interval(0)};
  for (int j = k; j >= std::max(0, k - params_.sonar_window); --j) {
    if (j < k) carried = {carried.dx + motion_[j + 1].dx, carried.dy + motion_[j + 1].dy};
    const MarinaRecord& at = records_[j];
    for (const MarinaReturn& ret : at.returns) {
      set.measurements.push_back(std::make_shared<SonarContractor>(
          map_.image, SonarRangeInterval(ret.range, ret.range_error),
          SonarAngleInterval(at.heading, at.heading_error, ret.beam_angle, ret.beam_half_width),
          carried.dx, carried.dy));
      outliers.push_back(ret.outlier);
      flags_known = flags_known && ret.has_outlier_flag;
    }
  }
  if (flags_known) set.outliers = std::move(outliers);
  if (k > 0)
    set.predict = [m = motion_[k]](const Box& previous) {
      if (previous.size() != 2)
        throw std::invalid_argument("marina-sonar predict: the box must be (x, y)");
      return Box({previous[0] + m.dx, previous[1] + m.dy});
    };
  step->views.measurement_set = std::move(set);

  // The CSP: dead reckoning over the window.
  const int oldest = std::max(0, k - params_.w);
  CspView view;
  ConstraintSystem& csp = view.csp;
  std::optional<Expr> xp, yp;
  bool truth_known = true;
  for (int j = oldest; j <= k; ++j) {
    const std::string index = "[" + std::to_string(j) + "]";
    const Box& domain = j == 0 && known ? start_box_ : map_.bounds;
    Expr xj = csp.AddVariable("x" + index, domain[0]);
    Expr yj = csp.AddVariable("y" + index, domain[1]);
    view.states.push_back({j, 0});
    view.states.push_back({j, 1});
    if (j > oldest) {
      csp.AddConstraint(xj, Relation::kEq, *xp + csp.Constant(motion_[j].dx));
      csp.AddConstraint(yj, Relation::kEq, *yp + csp.Constant(motion_[j].dy));
    }
    xp = xj;
    yp = yj;
    truth_known = truth_known && records_[j].has_truth;
  }
  view.newest = k;
  step->views.csp = std::move(view);
  if (r.has_truth) step->truth = {r.truth_x, r.truth_y};
  if (truth_known)
    for (int j = oldest; j <= k; ++j)
      step->csp_truth.insert(step->csp_truth.end(), {records_[j].truth_x, records_[j].truth_y});

  // The probabilistic view: (x, y) and the hidden biases.
  ProbabilisticView pv;
  const Box prior = known ? start_box_ : map_.bounds;
  auto image = map_.image;
  const double dvl_bound = r.dvl_error, compass_bound = r.heading_error;
  auto with_biases = [dvl_bound, compass_bound](std::vector<double> s, RandomEngine& rng) {
    s.push_back(UniformReal(rng, -dvl_bound, dvl_bound));
    s.push_back(UniformReal(rng, -dvl_bound, dvl_bound));
    s.push_back(UniformReal(rng, -compass_bound, compass_bound));
    return s;
  };
  pv.sample_prior = [prior, image, with_biases](RandomEngine& rng) {
    return with_biases(UniformInWater(prior, *image, rng), rng);
  };
  pv.sample_global = [bounds = map_.bounds, image, with_biases](RandomEngine& rng) {
    return with_biases(UniformInWater(bounds, *image, rng), rng);
  };
  if (k == 0) {
    pv.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  } else {
    const MarinaRecord& before = records_[k - 1];
    pv.sample_motion = [u = before.dvl_u, v = before.dvl_v, e = before.dvl_error,
                        th = before.heading, te = before.heading_error,
                        dt = r.t - before.t](std::vector<double>& s, RandomEngine& rng) {
      for (int i = kMarinaBiasU; i <= kMarinaBiasHeading; ++i) {
        const double bound = i == kMarinaBiasHeading ? te : e;
        s[i] = std::clamp(s[i] + UniformReal(rng, -kBiasWander, kBiasWander) * bound, -bound, bound);
      }
      const double du = u - s[kMarinaBiasU] + UniformReal(rng, -kWhiteShare, kWhiteShare) * e;
      const double dv = v - s[kMarinaBiasV] + UniformReal(rng, -kWhiteShare, kWhiteShare) * e;
      const double h = th - s[kMarinaBiasHeading] + UniformReal(rng, -kWhiteShare, kWhiteShare) * te;
      s[0] += dt * (du * std::cos(h) - dv * std::sin(h));
      s[1] += dt * (du * std::sin(h) + dv * std::cos(h));
    };
  }
  pv.log_likelihood = [map = map_, record = r, max_range = params_.max_range,
                       outlier = params_.likelihood_floor](const std::vector<double>& s) {
    return MarinaLogLikelihood(map, record, max_range, outlier, s[0], s[1], s[kMarinaBiasHeading]);
  };
  step->views.probabilistic = std::move(pv);
  return true;
}

}  // namespace icp
