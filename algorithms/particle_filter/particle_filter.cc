#include "algorithms/particle_filter/particle_filter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

#include <opencv2/core.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/credible_box.h"

namespace icp {

void Describe(ParticleFilterParams& p, ParamSet& set) {
  set.Add("particles", &p.particles, "number of particles", Range::Closed(1, 10000000));
  set.Add("resampling", &p.resampling, "resampling scheme", {"systematic", "multinomial"});
  set.Add("resample_threshold", &p.resample_threshold,
          "resample when ESS < this fraction of the particles (1: every step, 0: never)",
          Range::Closed(0, 1));
  set.Add("inject", &p.inject,
          "share of particles replaced by global-prior draws at each resampling (0: none)",
          Range::Closed(0, 0.5));
  set.Add("roughen", &p.roughen,
          "jitter after resampling, in standard deviations of the cloud per component "
          "(0: none; -1: the problem's, its probabilistic view's)",
          Range::Closed(kRoughenOfView, 10));
  set.Add("region", &p.region,
          "the set's box: 95 (the 95 % credible box) or hull (every particle)",
          {"95", "hull"});
}

namespace {

// Weighing in parallel: the particles timed first, the serial time of the
// others above which they are spread over threads (waking TBB's threads
// costs tens of microseconds), and the particles per task.
constexpr std::size_t kProbe = 32;
constexpr double kParallelAbove_s = 100e-6;
constexpr std::size_t kGrain = 64;
// The level of the "95" region.
constexpr double kRegionLevel = 0.95;

// The weights normalised to sum 1; throws unless they are finite,
// non-negative and not all 0.
std::vector<double> Normalised(const std::vector<double>& weights) {
  double total = 0;
  for (double w : weights) {
    if (!(w >= 0) || !std::isfinite(w))
      throw std::invalid_argument("resampling: weights must be finite and >= 0");
    total += w;
  }
  if (!(total > 0)) throw std::invalid_argument("resampling: the weights sum to 0");
  std::vector<double> out(weights.size());
  for (std::size_t i = 0; i < weights.size(); ++i) out[i] = weights[i] / total;
  return out;
}

// The last index of positive weight: where positions past the cumulative
// sum's rounding go.
std::size_t LastPositive(const std::vector<double>& w) {
  std::size_t last = 0;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w[i] > 0) last = i;
  return last;
}

}  // namespace

std::vector<std::size_t> SystematicResample(const std::vector<double>& weights, std::size_t n,
                                            double u) {
  if (!(u >= 0 && u < 1)) throw std::invalid_argument("systematic resampling: u must be in [0, 1)");
  const std::vector<double> w = Normalised(weights);
  const std::size_t last = LastPositive(w);
  std::vector<std::size_t> out;
  out.reserve(n);
  std::size_t j = 0;
  double cumulative = w[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double position = (u + static_cast<double>(i)) / static_cast<double>(n);
    while (position >= cumulative && j < last) cumulative += w[++j];
    out.push_back(j);
  }
  return out;
}

std::vector<std::size_t> MultinomialResample(const std::vector<double>& weights, std::size_t n,
                                             RandomEngine& rng) {
  const std::vector<double> w = Normalised(weights);
  std::vector<double> cumulative(w.size());
  std::partial_sum(w.begin(), w.end(), cumulative.begin());
  const std::size_t last = LastPositive(w);
  std::vector<std::size_t> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = UniformReal(rng, 0, 1);
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), u);
    out.push_back(std::min(static_cast<std::size_t>(it - cumulative.begin()), last));
  }
  std::sort(out.begin(), out.end());
  return out;
}

void Jitter(std::vector<double>& state, const std::vector<double>& sd, double h, RandomEngine& rng) {
  const double half_width = std::sqrt(3.0) * h;  // uniform on [-a, a]: sd a / sqrt(3)
  for (std::size_t c = 0; c < sd.size(); ++c) state[c] += half_width * sd[c] * UniformReal(rng, -1, 1);
}

namespace {

using State = std::vector<double>;

class ParticleFilter : public Estimator {
 public:
  ParticleFilter(const ParticleFilterParams& p, std::uint64_t seed) : p_(p), rng_(seed) {}

  StepResult Step(const Views& views, const StopCondition&) override {
    if (!views.probabilistic)
      throw std::invalid_argument("particle-filter needs the probabilistic view");
    const ProbabilisticView& view = *views.probabilistic;
    if (!view.sample_prior || !view.log_likelihood)
      throw std::invalid_argument("particle-filter: the view lacks sample_prior or log_likelihood");
    const std::size_t n = static_cast<std::size_t>(p_.particles);
    const bool first = particles_.empty();
    if (first) {
      Draw(view.sample_prior);
    } else if (view.sample_motion) {
      for (State& s : particles_) view.sample_motion(s, rng_);
    }
    CheckSizes(views.space);
    Weigh(view, /*reset=*/first);

    bool reinitialised = false;
    if (*std::max_element(log_w_.begin(), log_w_.end()) == -kInf) {
      reinitialised = true;
      ++reinitialisations_;
      Draw(view.sample_global ? view.sample_global : view.sample_prior);
      CheckSizes(views.space);
      Weigh(view, /*reset=*/true);
      if (*std::max_element(log_w_.begin(), log_w_.end()) == -kInf)
        std::fill(log_w_.begin(), log_w_.end(), 0.0);
    }

    // Normalise: log-sum-exp from the largest log-weight.
    const double top = *std::max_element(log_w_.begin(), log_w_.end());
    std::vector<double> w(n);
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      log_w_[i] -= top;
      w[i] = std::exp(log_w_[i]);
      total += w[i];
    }
    double squares = 0;
    for (double& wi : w) {
      wi /= total;
      squares += wi * wi;
    }
    const double ess = 1 / squares;

    StepResult result;
    result.estimate = MakeEstimate(views.space, w, &result.properties);
    const bool resample =
        p_.resample_threshold >= 1 || ess < p_.resample_threshold * static_cast<double>(n);
    std::int64_t injected = 0;
    if (resample) {
      ++resamplings_;
      injected = Resample(w, view);
      injected_ += injected;
      Roughen(p_.roughen == kRoughenOfView ? view.roughen : p_.roughen);
    }
    result.properties.push_back({"resampled", std::int64_t{resample}});
    result.properties.push_back({"reinitialised", std::int64_t{reinitialised}});
    result.properties.push_back({"injected", injected});
    return result;
  }

  Properties RunProperties() const override {
    return {{"resamplings", resamplings_},
            {"reinitialisations", reinitialisations_},
            {"injected", injected_}};
  }

 private:
  void Draw(const std::function<State(RandomEngine&)>& sample) {
    particles_.resize(static_cast<std::size_t>(p_.particles));
    for (State& s : particles_) s = sample(rng_);
  }

  void CheckSizes(const StateSpace& space) const {
    for (const State& s : particles_)
      if (static_cast<int>(s.size()) < space.size())
        throw std::invalid_argument("particle-filter: a drawn state has " + std::to_string(s.size()) +
                                    " components, fewer than the state space's " +
                                    std::to_string(space.size()));
  }

  // log_w_ += the log-likelihoods (= them, with reset); NaN counts as -inf.
  // The first particles are weighed here, timed: the others in parallel only
  // when they would take long enough to repay spreading them over threads.
  void Weigh(const ProbabilisticView& view, bool reset) {
    const std::size_t n = particles_.size();
    if (reset || log_w_.size() != n) log_w_.assign(n, 0.0);
    auto weigh = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i != end; ++i) {
        double ll = view.log_likelihood(particles_[i]);
        if (std::isnan(ll)) ll = -kInf;
        ll = std::min(ll, 1e300);  // +inf would make inf - inf
        log_w_[i] += ll;
      }
    };
    const std::size_t probe = std::min(n, kProbe);
    const auto start = std::chrono::steady_clock::now();
    weigh(0, probe);
    const double probe_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double rest_s = probe_s / static_cast<double>(probe) * static_cast<double>(n - probe);
    if (rest_s < kParallelAbove_s) {
      weigh(probe, n);
      return;
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(probe, n, kGrain),
                      [&](const tbb::blocked_range<std::size_t>& range) { weigh(range.begin(), range.end()); });
  }

  // The mean of periodic component c: in the chart of the previous centre
  // `reference` (each particle's offset from it wrapped into half a period)
  // when the cloud lies within a small arc of it, where that mean and the
  // circular one agree to second order in the spread; else the circular
  // mean (atan2 of the mean sine and cosine), in the frame of reference.
  // The chart needs no sine or cosine per particle.
  double PeriodicMean(int c, double period, const std::vector<double>& w, double reference) const {
    constexpr double kChartSpread = 1.0 / 16;  // the chart's largest standard deviation, in periods
    const std::size_t n = particles_.size();
    double offset = 0, square = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (w[i] == 0) continue;
      double delta = particles_[i][c] - reference;
      if (std::fabs(delta) > period / 2) delta -= period * std::round(delta / period);
      offset += w[i] * delta;
      square += w[i] * delta * delta;
    }
    if (square - offset * offset < kChartSpread * kChartSpread * period * period) return reference + offset;
    const double scale = 2 * std::acos(-1.0) / period;
    double sum_sin = 0, sum_cos = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (w[i] == 0) continue;
      double sin = 0, cos = 0;
      ::sincos(scale * particles_[i][c], &sin, &cos);  // glibc: both for the price of one
      sum_sin += w[i] * sin;
      sum_cos += w[i] * cos;
    }
    const double circular = std::atan2(sum_sin, sum_cos) / scale;
    return circular + period * std::round((reference - circular) / period);
  }

  // Puts each periodic component within half a period of its mean
  // (PeriodicMean, in the previous centre's frame) and returns the estimate;
  // its statistics go into properties, the standard deviations into sd_.
  // Two passes over the particles, and one or two per periodic component.
  std::unique_ptr<Estimate> MakeEstimate(const StateSpace& space, const std::vector<double>& w,
                                         Properties* properties) {
    const std::size_t n = particles_.size();
    const int d = space.size();
    const auto du = static_cast<std::size_t>(d);
    std::vector<double> period(du), linear(du, 0.0);
    for (int c = 0; c < d; ++c) period[c] = space.Period(c);
    for (std::size_t i = 0; i < n; ++i) {
      if (w[i] == 0) continue;
      const double* row = particles_[i].data();
      for (int c = 0; c < d; ++c) linear[c] += w[i] * row[c];
    }
    std::vector<double> centre = linear;
    for (int c = 0; c < d; ++c)
      if (period[c] > 0) centre[c] = PeriodicMean(c, period[c], w, centre_.size() == du ? centre_[c] : linear[c]);
    centre_ = centre;

    const bool hull = p_.region == "hull";
    Box region(du);
    if (hull) region.SetEmpty();
    cv::Mat cloud(static_cast<int>(n), d, CV_64F);  // continuous: row i at i * d
    std::vector<double> cov(du * du, 0.0), dev(du);
    for (std::size_t i = 0; i < n; ++i) {
      double* state = particles_[i].data();
      double* row = cloud.ptr<double>(static_cast<int>(i));
      for (int c = 0; c < d; ++c) {
        if (period[c] > 0 && std::fabs(state[c] - centre[c]) > period[c] / 2)
          state[c] -= period[c] * std::round((state[c] - centre[c]) / period[c]);
        row[c] = state[c];
        dev[c] = state[c] - centre[c];
      }
      if (w[i] == 0) continue;
      for (int a = 0; a < d; ++a) {
        for (int b = a; b < d; ++b) cov[a * d + b] += w[i] * dev[a] * dev[b];
        if (hull) region[a] = Hull(region[a], Interval(state[a]));
      }
    }
    if (!hull) region = CredibleBox(cloud, w, kRegionLevel);
    sd_.resize(du);
    for (int c = 0; c < d; ++c) sd_[c] = std::sqrt(std::max(0.0, cov[c * d + c]));
    for (int c = 0; c < d; ++c)
      properties->push_back({"mean_" + space.names[c], centre[c]});
    for (int a = 0; a < d; ++a)
      for (int b = a; b < d; ++b)
        properties->push_back({"cov_" + space.names[a] + "_" + space.names[b], cov[a * d + b]});
    return std::make_unique<ParticleEstimate>(cloud, w, region, centre);
  }

  // Resamples to equal weights, then injects; returns the number injected.
  std::int64_t Resample(const std::vector<double>& w, const ProbabilisticView& view) {
    const std::size_t n = particles_.size();
    const std::vector<std::size_t> index = p_.resampling == "multinomial"
                                               ? MultinomialResample(w, n, rng_)
                                               : SystematicResample(w, n, UniformReal(rng_, 0, 1));
    spare_.resize(n);
    for (std::size_t i = 0; i < n; ++i) spare_[i] = particles_[index[i]];
    std::swap(particles_, spare_);
    std::fill(log_w_.begin(), log_w_.end(), 0.0);
    if (!view.sample_global || p_.inject <= 0) return 0;
    const std::size_t k = std::min(n, static_cast<std::size_t>(std::llround(p_.inject * static_cast<double>(n))));
    // k distinct places, by a partial Fisher-Yates shuffle.
    std::vector<std::size_t> places(n);
    std::iota(places.begin(), places.end(), std::size_t{0});
    for (std::size_t i = 0; i < k; ++i) {
      std::swap(places[i], places[i + UniformIndex(rng_, n - i)]);
      particles_[places[i]] = view.sample_global(rng_);
    }
    return static_cast<std::int64_t>(k);
  }

  // Every particle jittered by h (Jitter) with the weighed cloud's standard
  // deviations sd_, its state-space components only.
  void Roughen(double h) {
    if (!(h > 0)) return;
    for (State& s : particles_) Jitter(s, sd_, h, rng_);
  }

  ParticleFilterParams p_;
  RandomEngine rng_;
  std::vector<State> particles_;
  std::vector<State> spare_;
  std::vector<double> log_w_;
  std::vector<double> centre_;  // the previous step's, for the periodic frame
  std::vector<double> sd_;      // this step's weighted standard deviations, for Roughen
  std::int64_t resamplings_ = 0;
  std::int64_t reinitialisations_ = 0;
  std::int64_t injected_ = 0;
};

// What the range of roughen cannot say: -1 or at least 0.
void CheckRoughen(const std::string& owner, double roughen) {
  if (roughen < 0 && roughen != kRoughenOfView)
    throw ParamError(owner + ".roughen = " + FormatDouble(roughen) +
                     ": must be >= 0, or -1 for the problem's");
}

}  // namespace

ParamMap ResolveParticleFilter(const std::string& owner, const ParamMap& values) {
  CheckRoughen(owner, ParseParams<ParticleFilterParams>(owner, values).roughen);
  return ResolveParams<ParticleFilterParams>(owner, values);
}

std::unique_ptr<Estimator> MakeParticleFilter(const ParamMap& params, std::uint64_t seed) {
  const auto p = ParseParams<ParticleFilterParams>("particle-filter", params);
  CheckRoughen("particle-filter", p.roughen);
  return std::make_unique<ParticleFilter>(p, seed);
}

}  // namespace icp
