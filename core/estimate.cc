#include "core/estimate.h"

#include <cmath>
#include <stdexcept>

#include "core/credible_box.h"
#include "core/rounding.h"

namespace icp {

std::string_view TypeName(const Property& p) {
  switch (p.value.index()) {
    case 0: return "int";
    case 1: return "real";
    default: return "text";
  }
}

std::optional<std::int64_t> IntProperty(const Properties& properties, std::string_view name) {
  for (const Property& p : properties)
    if (p.name == name && std::holds_alternative<std::int64_t>(p.value))
      return std::get<std::int64_t>(p.value);
  return std::nullopt;
}

std::optional<double> NumberProperty(const Properties& properties, std::string_view name) {
  for (const Property& p : properties) {
    if (p.name != name) continue;
    if (const auto* i = std::get_if<std::int64_t>(&p.value)) return static_cast<double>(*i);
    if (const auto* d = std::get_if<double>(&p.value)) return *d;
  }
  return std::nullopt;
}

std::vector<double> Estimate::Centre() const {
  const Box hull = Hull();
  if (hull.IsEmpty()) return {};
  std::vector<double> centre;
  for (const Interval& c : hull) centre.push_back((c.lo() + c.hi()) / 2);
  return centre;
}

double BoxArea(const Box& box, int x, int y) {
  if (box.IsEmpty()) return 0;
  return ExactRounding().mul_up(box[x].Width(), box[y].Width());
}

double BoxEstimate::Area(int x, int y) const { return BoxArea(box_, x, y); }

namespace {
// The hull of boxes; an empty box of dimension n when there are none.
Box HullOf(const std::vector<const std::vector<Box>*>& lists, std::size_t n) {
  Box hull(n);
  hull.SetEmpty();
  for (const auto* list : lists)
    for (const Box& b : *list) {
      if (b.IsEmpty()) continue;
      for (std::size_t i = 0; i < n; ++i) hull[i] = Hull(hull[i], b[i]);
    }
  return hull;
}
}  // namespace

Box PavingEstimate::Hull() const {
  return HullOf({&inner_, &boundary_}, dimension_);
}

bool PavingEstimate::Contains(const std::vector<double>& point) const {
  for (const auto* list : {&inner_, &boundary_})
    for (const Box& b : *list)
      if (b.Contains(point)) return true;
  return false;
}

double PavingEstimate::Area(int x, int y) const {
  ExactRounding rnd;
  double area = 0;
  for (const auto* list : {&inner_, &boundary_})
    for (const Box& b : *list) area = rnd.add_up(area, BoxArea(b, x, y));
  return area;
}

std::string PavingEstimate::Malformed(const std::vector<std::string>& names) const {
  for (const auto& [list, kind] : {std::pair{&inner_, "inner"}, std::pair{&boundary_, "boundary"}})
    for (std::size_t k = 0; k < list->size(); ++k) {
      const Box& b = (*list)[k];
      const std::string which = std::string("the paving's ") + kind + " box " + std::to_string(k);
      if (b.size() != dimension_)
        return which + " has " + std::to_string(b.size()) + " components, not " + std::to_string(dimension_);
      if (const int c = FirstNaNComponent(b); c >= 0)
        return which + ": " + ComponentName(names, c) + " has a NaN bound";
    }
  return "";
}

Properties PavingEstimate::Extras() const {
  return {{"boxes", static_cast<std::int64_t>(inner_.size() + boundary_.size())},
          {"inner_boxes", static_cast<std::int64_t>(inner_.size())},
          {"boundary_boxes", static_cast<std::int64_t>(boundary_.size())}};
}

AccumulatorEstimate::AccumulatorEstimate(cv::Mat counts, Box search, int x, int y, int threshold)
    : counts_(std::move(counts)),
      grid_(std::move(search), x, y, std::max(counts_.cols, 1), std::max(counts_.rows, 1)),
      threshold_(threshold) {
  if (counts_.type() != CV_32S || counts_.dims != 2 || counts_.empty())
    throw std::invalid_argument("AccumulatorEstimate: counts must be a non-empty CV_32S matrix");
}

Box AccumulatorEstimate::Hull() const {
  Box hull = grid_.search();
  Interval hx = Interval::Empty(), hy = Interval::Empty();
  for (int r = 0; r < counts_.rows; ++r)
    for (int c = 0; c < counts_.cols; ++c)
      if (counts_.at<std::int32_t>(r, c) >= threshold_) {
        hx = icp::Hull(hx, grid_.CellX(c));
        hy = icp::Hull(hy, grid_.CellY(r));
      }
  hull[grid_.x()] = hx;
  hull[grid_.y()] = hy;
  if (hx.IsEmpty()) hull.SetEmpty();
  return hull;
}

bool AccumulatorEstimate::Contains(const std::vector<double>& point) const {
  const Box& search = grid_.search();
  const int x = grid_.x(), y = grid_.y();
  for (int i = 0; i < static_cast<int>(search.size()); ++i)
    if (i != x && i != y && !search[i].Contains(point[i])) return false;
  // A point on a cell border belongs to every cell it touches.
  const auto [c0, c1] = grid_.ColsMeeting(Interval(point[x]));
  const auto [r0, r1] = grid_.RowsMeeting(Interval(point[y]));
  for (int r = r0; r < r1; ++r)
    for (int c = c0; c < c1; ++c)
      if (counts_.at<std::int32_t>(r, c) >= threshold_) return true;
  return false;
}

double AccumulatorEstimate::Area(int x, int y) const {
  if (!((x == grid_.x() && y == grid_.y()) || (x == grid_.y() && y == grid_.x())))
    throw std::invalid_argument("AccumulatorEstimate: area over components other than its grid's");
  ExactRounding rnd;
  double area = 0;
  for (int r = 0; r < counts_.rows; ++r)
    for (int c = 0; c < counts_.cols; ++c)
      if (counts_.at<std::int32_t>(r, c) >= threshold_)
        area = rnd.add_up(area, rnd.mul_up(grid_.CellX(c).Width(), grid_.CellY(r).Width()));
  return area;
}

Properties AccumulatorEstimate::Extras() const {
  double max_count = 0;
  cv::minMaxLoc(counts_, nullptr, &max_count);
  // Counted in place: a mask would take a quarter of the grid's memory again.
  std::int64_t cells = 0;
  for (int r = 0; r < counts_.rows; ++r) {
    const std::int32_t* row = counts_.ptr<std::int32_t>(r);
    for (int c = 0; c < counts_.cols; ++c) cells += row[c] >= threshold_;
  }
  return {{"max_count", static_cast<std::int64_t>(max_count)},
          {"threshold", static_cast<std::int64_t>(threshold_)},
          {"cells", cells}};
}

ParticleEstimate::ParticleEstimate(cv::Mat particles, std::vector<double> weights)
    : particles_(std::move(particles)), weights_(std::move(weights)) {
  if (particles_.type() != CV_64F || particles_.rows != static_cast<int>(weights_.size()))
    throw std::invalid_argument("ParticleEstimate: one CV_64F row and one weight per particle");
}

ParticleEstimate::ParticleEstimate(cv::Mat particles, std::vector<double> weights, Box region,
                                   std::vector<double> centre)
    : ParticleEstimate(std::move(particles), std::move(weights)) {
  const auto components = static_cast<std::size_t>(particles_.cols);
  if (region.size() != components || (!centre.empty() && centre.size() != components))
    throw std::invalid_argument("ParticleEstimate: the region and the centre need one entry per component");
  region_ = std::move(region);
  centre_ = std::move(centre);
}

std::string ParticleEstimate::Malformed(const std::vector<std::string>& names) const {
  for (int i = 0; i < particles_.rows; ++i) {
    if (!(weights_[i] >= 0)) return "particle " + std::to_string(i) + "'s weight is NaN or negative";
    for (int c = 0; c < particles_.cols; ++c)
      if (std::isnan(particles_.at<double>(i, c)))
        return "particle " + std::to_string(i) + ": " + ComponentName(names, c) + " is NaN";
  }
  if (const int c = region_ ? FirstNaNComponent(*region_) : -1; c >= 0)
    return "the region: " + ComponentName(names, c) + " has a NaN bound";
  for (std::size_t c = 0; c < centre_.size(); ++c)
    if (std::isnan(centre_[c])) return "the centre: " + ComponentName(names, c) + " is NaN";
  return "";
}

Box ParticleEstimate::ParticleHull() const {
  Box hull(static_cast<std::size_t>(particles_.cols));
  hull.SetEmpty();
  for (int i = 0; i < particles_.rows; ++i) {
    if (!(weights_[i] > 0)) continue;
    for (int c = 0; c < particles_.cols; ++c)
      hull[c] = icp::Hull(hull[c], Interval(particles_.at<double>(i, c)));
  }
  return hull;
}

Box ParticleEstimate::Hull() const { return region_ ? *region_ : ParticleHull(); }

double ParticleEstimate::Area(int x, int y) const { return BoxArea(Hull(), x, y); }

std::vector<double> ParticleEstimate::Centre() const {
  if (!centre_.empty()) return Hull().IsEmpty() ? std::vector<double>() : centre_;
  double total = 0;
  std::vector<double> centre(static_cast<std::size_t>(particles_.cols), 0.0);
  for (int i = 0; i < particles_.rows; ++i) {
    if (!(weights_[i] > 0)) continue;
    total += weights_[i];
    for (int c = 0; c < particles_.cols; ++c) centre[c] += weights_[i] * particles_.at<double>(i, c);
  }
  if (!(total > 0)) return {};
  for (double& v : centre) v /= total;
  return centre;
}

std::optional<Box> ParticleEstimate::CredibleRegion(double level) const {
  for (double w : weights_)
    if (w > 0) return CredibleBox(particles_, weights_, level);
  Box empty(static_cast<std::size_t>(particles_.cols));
  empty.SetEmpty();
  return empty;
}

Properties ParticleEstimate::Extras() const {
  double total = 0, squares = 0;
  for (double w : weights_)
    if (w > 0) total += w;
  for (double w : weights_)
    if (w > 0) squares += (w / total) * (w / total);
  return {{"particles", static_cast<std::int64_t>(weights_.size())},
          {"effective_sample_size", squares > 0 ? 1 / squares : 0.0}};
}

}  // namespace icp
