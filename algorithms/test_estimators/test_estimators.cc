#include "algorithms/test_estimators/test_estimators.h"

#include <functional>
#include <stdexcept>

#include "algorithms/hc4/hc4.h"
#include "algorithms/window/window_estimator.h"
#include "core/random.h"

namespace icp {

void Describe(TestPavingParams& p, ParamSet& set) {
  set.Add("splits", &p.splits, "boxes per axis (x and y)", Range::Closed(1, 100));
}
void Describe(TestAccumulatorParams& p, ParamSet& set) {
  set.Add("cells", &p.cells, "grid cells per axis", Range::Closed(1, 1000));
}
void Describe(TestParticlesParams& p, ParamSet& set) {
  set.Add("particles", &p.particles, "number of particles", Range::Closed(1, 1000000));
}

namespace {

// box: HC4's newest-state box; domains: the newest state's initial domains.
using Convert = std::function<std::unique_ptr<Estimate>(const Box& box, const Box& domains,
                                                         const StateSpace& space)>;

// HC4 over the window, then the box converted to another kind of estimate.
class ConvertingEstimator : public Estimator {
 public:
  explicit ConvertingEstimator(Convert convert)
      : hc4_(&MakeHC4, {}, Carry::kFirst), convert_(std::move(convert)) {}
  StepResult Step(const Views& views, const StopCondition& stop) override {
    StepResult result = hc4_.Step(views, stop);
    const Box box = result.estimate->Hull();
    if (!box.IsEmpty()) {
      if (views.space.x < 0 || views.space.y < 0)
        throw std::invalid_argument("test estimators need a planar position (x, y)");
      if (!(box[views.space.x].Width() < kInf) || !(box[views.space.y].Width() < kInf))
        throw std::runtime_error("unbounded x-y box at step " + std::to_string(views.step));
      result.estimate = convert_(box, NewestState(*views.csp, views.csp->csp.domains(), views.space.size()),
                                  views.space);
    }
    return result;
  }
  Properties RunProperties() const override { return hc4_.RunProperties(); }

 private:
  WindowEstimator hc4_;
  Convert convert_;
};

// The n pieces of x split evenly, outward rounded so they cover x.
std::vector<Interval> Split(const Interval& x, int n) {
  std::vector<Interval> out;
  const Interval step = (Interval(x.hi()) - Interval(x.lo())) / Interval(n);
  for (int i = 0; i < n; ++i) {
    const double lo = i == 0 ? x.lo() : (Interval(x.lo()) + step * Interval(i)).lo();
    const double hi = i == n - 1 ? x.hi() : (Interval(x.lo()) + step * Interval(i + 1.0)).hi();
    out.emplace_back(lo, hi);
  }
  return out;
}

}  // namespace

std::unique_ptr<Estimator> MakeTestPaving(const ParamMap& params, std::uint64_t) {
  const auto p = ParseParams<TestPavingParams>("test-paving", params);
  return std::make_unique<ConvertingEstimator>([p](const Box& box, const Box&, const StateSpace& space) {
    std::vector<Box> boundary;
    for (const Interval& x : Split(box[space.x], p.splits))
      for (const Interval& y : Split(box[space.y], p.splits)) {
        Box piece = box;
        piece[space.x] = x;
        piece[space.y] = y;
        boundary.push_back(piece);
      }
    return std::make_unique<PavingEstimate>(box.size(), std::vector<Box>{}, std::move(boundary));
  });
}

std::unique_ptr<Estimator> MakeTestAccumulator(const ParamMap& params, std::uint64_t) {
  const auto p = ParseParams<TestAccumulatorParams>("test-accumulator", params);
  return std::make_unique<ConvertingEstimator>([p](const Box& box, const Box& domains,
                                                               const StateSpace& space) {
    Box search = box;
    for (int c : {space.x, space.y})
      search[c] = Intersect(box[c] + Interval(-0.5, 0.5) * Interval(box[c].Width()), domains[c]);
    cv::Mat counts(p.cells, p.cells, CV_32S, cv::Scalar(1));
    const std::vector<Interval> xs = Split(search[space.x], p.cells);
    const std::vector<Interval> ys = Split(search[space.y], p.cells);
    for (int r = 0; r < p.cells; ++r)
      for (int c = 0; c < p.cells; ++c)
        if (!Intersect(xs[c], box[space.x]).IsEmpty() && !Intersect(ys[r], box[space.y]).IsEmpty())
          counts.at<std::int32_t>(r, c) = 2;
    return std::make_unique<AccumulatorEstimate>(counts, search, space.x, space.y, 2);
  });
}

std::unique_ptr<Estimator> MakeTestParticles(const ParamMap& params, std::uint64_t seed) {
  const auto p = ParseParams<TestParticlesParams>("test-particles", params);
  auto rng = std::make_shared<RandomEngine>(seed);
  return std::make_unique<ConvertingEstimator>([p, rng](const Box& box, const Box&, const StateSpace&) {
    cv::Mat particles(p.particles, static_cast<int>(box.size()), CV_64F);
    for (int i = 0; i < p.particles; ++i)
      for (int c = 0; c < particles.cols; ++c) {
        const Interval& b = box[c];
        const double lo = std::isfinite(b.lo()) ? b.lo() : -1e6;
        const double hi = std::isfinite(b.hi()) ? b.hi() : 1e6;
        particles.at<double>(i, c) = UniformReal(*rng, lo, hi);
      }
    return std::make_unique<ParticleEstimate>(particles, std::vector<double>(p.particles, 1.0));
  });
}

}  // namespace icp
