// Credible boxes (credible_box.h): per component, the weighted quantiles of
// the particles, found by selecting the few values in each tail.
#include "core/credible_box.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  auto by_value = [](const auto& a, const auto& b) { return a.first < b.first; };
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
// values in one component, from the few smallest and largest of them: no
// sort of them all. Quantiles answers when those few hold the tails' weight
// (with equal weights they do), else nullopt (then SelectQuantile over them
// all).
class Tails {
 public:
  Tails(std::size_t n, double tail)
      : m_(std::min(n, 8 + 2 * static_cast<std::size_t>(std::ceil(tail * static_cast<double>(n))))),
        tail_(tail) {}

  // Keeps the m_ least and the m_ greatest (value, weight) pairs of
  // value[i * stride] over the particles i in `positive` (those of positive
  // weight), each in its order. For few kept (a
  // filter's cloud: m_ is 20 for 600 particles and 3 components), one pass
  // that inserts into the kept pairs only what beats the last of them: most
  // values are rejected by one comparison. For many, std::nth_element then
  // a sort of the few, O(n + m_ log m_) (insertion is O(n m_) at worst, and
  // m_ grows with n).
  void Select(const double* value, std::size_t stride, const std::vector<double>& weights,
              const std::vector<std::uint32_t>& positive) {
    constexpr std::size_t kInsertAtMost = 64;
    count_ = positive.size();
    // A strict weak order whatever the values: NaN after every number.
    auto less = [](const auto& a, const auto& b) {
      return a.first < b.first || (std::isnan(b.first) && !std::isnan(a.first));
    };
    auto greater = [](const auto& a, const auto& b) {
      return a.first > b.first || (std::isnan(b.first) && !std::isnan(a.first));
    };
    const std::size_t k = std::min(m_, positive.size());
    low_.clear();
    high_.clear();
    if (m_ <= kInsertAtMost) {
      auto insert = [k](auto before, std::vector<std::pair<double, double>>& kept, const auto& p) {
        if (kept.size() == k) {
          if (!before(p, kept.back())) return;
          kept.pop_back();
        }
        kept.insert(std::upper_bound(kept.begin(), kept.end(), p, before), p);
      };
      for (std::uint32_t i : positive) {
        const std::pair<double, double> p(value[i * stride], weights[i]);
        insert(less, low_, p);
        insert(greater, high_, p);
      }
      return;
    }
    pairs_.clear();
    for (std::uint32_t i : positive) pairs_.emplace_back(value[i * stride], weights[i]);
    auto keep = [&](auto before, std::vector<std::pair<double, double>>& kept) {
      const auto end = pairs_.begin() + static_cast<std::ptrdiff_t>(k);
      if (k < pairs_.size()) std::nth_element(pairs_.begin(), end, pairs_.end(), before);
      std::sort(pairs_.begin(), end, before);
      kept.assign(pairs_.begin(), end);
    };
    keep(less, low_);
    keep(greater, high_);
  }

  // The two quantiles for weights summing to total.
  std::optional<Interval> Quantiles(double total) const {
    // Lower: the least value whose weight at or below exceeds tail * total.
    std::optional<double> lo;
    double cumulative = 0;
    for (const auto& [value, weight] : low_) {
      cumulative += weight;
      if (cumulative > tail_ * total) {
        lo = value;
        break;
      }
    }
    // Upper: the least value whose weight at or below exceeds (1 - tail) *
    // total; going down from the largest, ties together, the weight at or
    // below a value is total minus the weight strictly above it.
    std::optional<double> hi;
    const double target = (1 - tail_) * total;
    double above = 0;
    for (std::size_t j = 0; j < high_.size();) {
      std::size_t k = j;
      double group = 0;
      while (k < high_.size() && high_[k].first == high_[j].first) group += high_[k++].second;
      if (k == high_.size() && high_.size() < count_) break;  // the ties may go on
      if (!(total - above > target)) break;  // target >= total: left to SelectQuantile
      if (!(total - above - group > target)) {
        hi = high_[j].first;
        break;
      }
      above += group;
      j = k;
    }
    if (!lo || !hi) return std::nullopt;
    return Interval(*lo, *hi);
  }

 private:
  std::size_t m_;
  double tail_;
  std::size_t count_ = 0;
  std::vector<std::pair<double, double>> pairs_, low_, high_;
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
    Tails tails(n, tail);
    tails.Select(cloud.ptr<double>(0) + c, static_cast<std::size_t>(d), weights, positive);
    std::optional<Interval> quantiles = tails.Quantiles(total);
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
