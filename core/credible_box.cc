// Credible boxes (credible_box.h): per component, the weighted quantiles of
// the particles, found by selecting the few values in each tail.
#include "core/credible_box.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>

namespace icp {

double WeightedQuantile(const std::vector<double>& values, const std::vector<double>& weights,
                        double q) {
  if (values.size() != weights.size())
    throw std::invalid_argument("WeightedQuantile: one weight per value");
  std::vector<std::size_t> order;
  double total = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (weights[i] > 0) {
      order.push_back(i);
      total += weights[i];
    }
  if (order.empty()) throw std::invalid_argument("WeightedQuantile: no positive weight");
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  double cumulative = 0;
  for (std::size_t i : order) {
    cumulative += weights[i];
    if (cumulative > q * total) return values[i];
  }
  return values[order.back()];
}

namespace {

// WeightedQuantile of (value, weight) pairs, the weights positive and
// summing to total, at the weight `target` (q times total) by selection
// rather than sorting: each round splits at the place where the target would
// fall if the weights were equal, so equal weights need one or two rounds
// and any weights an expected linear time. Reorders pairs.
double SelectQuantile(std::vector<std::pair<double, double>>& pairs, double total, double target) {
  // A strict weak order whatever the values: NaN after every number.
  auto by_value = [](const auto& a, const auto& b) {
    return a.first < b.first || (std::isnan(b.first) && !std::isnan(a.first));
  };
  std::size_t lo = 0, hi = pairs.size();
  double below = 0;         // the weight of the pairs ordered before lo
  double inside = total;    // the weight of those in [lo, hi)
  while (hi - lo > 16) {
    const double guess = (target - below) / inside * static_cast<double>(hi - lo);
    const std::size_t mid =
        lo + std::min(hi - lo - 1, static_cast<std::size_t>(std::clamp(guess, 0.0, 1e18)));
    std::nth_element(pairs.begin() + lo, pairs.begin() + mid, pairs.begin() + hi, by_value);
    double left = 0;
    for (std::size_t i = lo; i < mid; ++i) left += pairs[i].second;
    if (below + left > target) {
      hi = mid;
      inside = left;
    } else if (below + left + pairs[mid].second > target) {
      return pairs[mid].first;
    } else {
      below += left + pairs[mid].second;
      inside -= left + pairs[mid].second;
      lo = mid + 1;
    }
  }
  std::sort(pairs.begin() + lo, pairs.begin() + hi, by_value);
  for (std::size_t i = lo; i < hi; ++i) {
    below += pairs[i].second;
    if (below > target) return pairs[i].first;
  }
  // Only rounding or target >= the total gets here: the greatest value.
  return std::max_element(pairs.begin(), pairs.end(), by_value)->first;
}

// WeightedQuantile at tail and at 1 - tail (tail < 1/2) of the particles'
// values in one component, from the few smallest and largest of them: the
// tail's count and 2 more (8 of a filter's 458 live particles at level 95 in
// 3 components), no sort of them all. Keep answers false when there would be
// more than 64 of them or a value is not finite, Quantiles nullopt when the
// few do not hold the tails' weight (with equal weights they do); then
// SelectQuantile over them all.
//
// The few are kept in one pass: a value beyond the last kept is moved into
// place by a shift without branches, ties in the order of the particles.
// Branches are what costs here: a filter's cloud is new at every step, so
// any that depends on the values (a binary search, a sort, nth_element) is
// mispredicted about half the time. (The region with nth_element cost 3
// times in the filter what a benchmark repeating one cloud said.)
class Tails {
 public:
  explicit Tails(double tail) : tail_(tail) {}

  bool Keep(const double* value, std::size_t stride, const std::vector<double>& weights,
            const std::vector<std::uint32_t>& positive) {
    constexpr std::size_t kMostKept = 64;
    count_ = positive.size();
    const std::size_t k =
        std::min(count_, 2 + static_cast<std::size_t>(std::ceil(tail_ * static_cast<double>(count_))));
    if (k > kMostKept) return false;
    low_value_.assign(k, kInf);
    low_weight_.assign(k, 0.0);
    high_value_.assign(k, -kInf);
    high_weight_.assign(k, 0.0);
    bool finite = true;
    for (std::uint32_t i : positive) {
      const double v = value[i * stride], w = weights[i];
      finite &= std::isfinite(v);
      if (v < low_value_[k - 1]) ShiftInto(low_value_.data(), low_weight_.data(), k, v, w, std::less<double>());
      if (v > high_value_[k - 1])
        ShiftInto(high_value_.data(), high_weight_.data(), k, v, w, std::greater<double>());
    }
    return finite;
  }

  // The two quantiles for weights summing to total.
  std::optional<Interval> Quantiles(double total) const {
    // Lower: the least value whose weight at or below exceeds tail * total.
    std::optional<double> lo;
    double cumulative = 0;
    for (std::size_t j = 0; j < low_value_.size(); ++j) {
      cumulative += low_weight_[j];
      if (cumulative > tail_ * total) {
        lo = low_value_[j];
        break;
      }
    }
    // Upper: the least value whose weight at or below exceeds (1 - tail) *
    // total; going down from the largest, ties together, the weight at or
    // below a value is total minus the weight strictly above it.
    std::optional<double> hi;
    const double target = (1 - tail_) * total;
    double above = 0;
    const std::size_t kept = high_value_.size();
    for (std::size_t j = 0; j < kept;) {
      std::size_t k = j;
      double group = 0;
      while (k < kept && high_value_[k] == high_value_[j]) group += high_weight_[k++];
      if (k == kept && kept < count_) break;  // the ties may go on
      if (!(total - above > target)) break;  // target >= total: left to SelectQuantile
      if (!(total - above - group > target)) {
        hi = high_value_[j];
        break;
      }
      above += group;
      j = k;
    }
    if (!lo || !hi) return std::nullopt;
    return Interval(*lo, *hi);
  }

 private:
  // Shifts (v, w) into the k slots sorted by `before`, after the ties: slot
  // j takes slot j - 1's pair when v goes before it, v itself when v goes
  // between them, else keeps its own; selected by bit masks, not branches.
  template <typename Before>
  static void ShiftInto(double* values, double* weights, std::size_t k, double v, double w, Before before) {
    auto pick = [](bool take, double a, double b) {
      const std::uint64_t mask = -static_cast<std::uint64_t>(take);
      return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) |
                                   (std::bit_cast<std::uint64_t>(b) & ~mask));
    };
    for (std::size_t j = k - 1; j > 0; --j) {
      const bool previous = before(v, values[j - 1]), here = before(v, values[j]);
      weights[j] = pick(previous, weights[j - 1], pick(here, w, weights[j]));
      values[j] = pick(previous, values[j - 1], pick(here, v, values[j]));
    }
    const bool first = before(v, values[0]);
    weights[0] = pick(first, w, weights[0]);
    values[0] = pick(first, v, values[0]);
  }

  double tail_;
  std::size_t count_ = 0;
  // The kept least values, ascending, and greatest, descending, with their
  // weights (Keep fills them).
  std::vector<double> low_value_, low_weight_, high_value_, high_weight_;
};

}  // namespace

double CredibleTail(double level, int d) {
  if (!(level > 0 && level < 1)) throw std::invalid_argument("CredibleTail: level must be in (0, 1)");
  if (d < 1) throw std::invalid_argument("CredibleTail: no component");
  return (1 - std::pow(level, 1.0 / d)) / 2;
}

Box CredibleBox(const cv::Mat& cloud, const std::vector<double>& weights, double level) {
  if (cloud.type() != CV_64F || cloud.rows != static_cast<int>(weights.size()) ||
      !cloud.isContinuous())
    throw std::invalid_argument("CredibleBox: one continuous CV_64F row and one weight per particle");
  const std::size_t n = weights.size();
  const int d = cloud.cols;
  const double tail = CredibleTail(level, d);
  std::vector<std::uint32_t> positive;  // the particles of positive weight (n <= 1e7)
  double total = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (weights[i] > 0) {
      positive.push_back(static_cast<std::uint32_t>(i));
      total += weights[i];
    }
  if (positive.empty()) throw std::invalid_argument("CredibleBox: no positive weight");
  Box box(static_cast<std::size_t>(d));
  for (int c = 0; c < d; ++c) {
    Tails tails(tail);
    std::optional<Interval> quantiles;
    if (tails.Keep(cloud.ptr<double>(0) + c, static_cast<std::size_t>(d), weights, positive))
      quantiles = tails.Quantiles(total);
    if (!quantiles) {
      std::vector<std::pair<double, double>> pairs;
      for (std::uint32_t i : positive) pairs.emplace_back(cloud.at<double>(static_cast<int>(i), c), weights[i]);
      const double lo = SelectQuantile(pairs, total, tail * total);
      quantiles = Interval(lo, SelectQuantile(pairs, total, (1 - tail) * total));
    }
    box[c] = *quantiles;
  }
  return box;
}

}  // namespace icp
