#include "core/estimate.h"

#include <cmath>
#include <stdexcept>

#include "core/rounding.h"

namespace icp {

std::string_view TypeName(const Property& p) {
  switch (p.value.index()) {
    case 0: return "int";
    case 1: return "real";
    default: return "text";
  }
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
  const std::size_t n = !inner_.empty() ? inner_[0].size() : !boundary_.empty() ? boundary_[0].size() : 0;
  return HullOf({&inner_, &boundary_}, n);
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

Properties PavingEstimate::Extras() const {
  return {{"inner_boxes", static_cast<std::int64_t>(inner_.size())},
          {"boundary_boxes", static_cast<std::int64_t>(boundary_.size())}};
}

AccumulatorEstimate::AccumulatorEstimate(cv::Mat counts, Box search, int x, int y, int threshold)
    : counts_(std::move(counts)), search_(std::move(search)), x_(x), y_(y), threshold_(threshold) {
  if (counts_.type() != CV_32S || counts_.dims != 2 || counts_.empty())
    throw std::invalid_argument("AccumulatorEstimate: counts must be a non-empty CV_32S matrix");
  if (search_.IsEmpty() || !(search_[x_].Width() < kInf) || !(search_[y_].Width() < kInf))
    throw std::invalid_argument("AccumulatorEstimate: the search box must be bounded in x and y");
}

// Cell bounds are computed outward, so the cells cover the search box.
Interval AccumulatorEstimate::CellX(int col) const {
  const Interval& sx = search_[x_];
  const Interval step = (Interval(sx.hi()) - Interval(sx.lo())) / Interval(counts_.cols);
  return Interval(sx.lo()) + step * Interval(col, col + 1.0);
}

Interval AccumulatorEstimate::CellY(int row) const {
  const Interval& sy = search_[y_];
  const Interval step = (Interval(sy.hi()) - Interval(sy.lo())) / Interval(counts_.rows);
  return Interval(sy.lo()) + step * Interval(row, row + 1.0);
}

bool AccumulatorEstimate::CellOf(double px, double py, int* row, int* col) const {
  const Interval& sx = search_[x_];
  const Interval& sy = search_[y_];
  if (!sx.Contains(px) || !sy.Contains(py)) return false;
  *col = std::min(counts_.cols - 1,
                  static_cast<int>((px - sx.lo()) / (sx.hi() - sx.lo()) * counts_.cols));
  *row = std::min(counts_.rows - 1,
                  static_cast<int>((py - sy.lo()) / (sy.hi() - sy.lo()) * counts_.rows));
  // The division may land a point on a border in the neighbouring cell.
  while (*col > 0 && px < CellX(*col).lo()) --*col;
  while (*col + 1 < counts_.cols && px > CellX(*col).hi()) ++*col;
  while (*row > 0 && py < CellY(*row).lo()) --*row;
  while (*row + 1 < counts_.rows && py > CellY(*row).hi()) ++*row;
  return true;
}

Box AccumulatorEstimate::Hull() const {
  Box hull = search_;
  Interval hx = Interval::Empty(), hy = Interval::Empty();
  for (int r = 0; r < counts_.rows; ++r)
    for (int c = 0; c < counts_.cols; ++c)
      if (counts_.at<std::int32_t>(r, c) >= threshold_) {
        hx = icp::Hull(hx, CellX(c));
        hy = icp::Hull(hy, CellY(r));
      }
  hull[x_] = Intersect(hx, search_[x_]);
  hull[y_] = Intersect(hy, search_[y_]);
  if (hull[x_].IsEmpty()) hull.SetEmpty();
  return hull;
}

bool AccumulatorEstimate::Contains(const std::vector<double>& point) const {
  for (int i = 0; i < static_cast<int>(search_.size()); ++i)
    if (i != x_ && i != y_ && !search_[i].Contains(point[i])) return false;
  int row = 0, col = 0;
  if (!CellOf(point[x_], point[y_], &row, &col)) return false;
  // A point on a cell border belongs to both cells.
  for (int r = std::max(0, row - 1); r <= std::min(counts_.rows - 1, row + 1); ++r)
    for (int c = std::max(0, col - 1); c <= std::min(counts_.cols - 1, col + 1); ++c)
      if (counts_.at<std::int32_t>(r, c) >= threshold_ && CellX(c).Contains(point[x_]) &&
          CellY(r).Contains(point[y_]))
        return true;
  return false;
}

double AccumulatorEstimate::Area(int x, int y) const {
  if (!((x == x_ && y == y_) || (x == y_ && y == x_)))
    throw std::invalid_argument("AccumulatorEstimate: area over components other than its grid's");
  const double cells = cv::countNonZero(counts_ >= threshold_);
  ExactRounding rnd;
  return rnd.mul_up(cells, rnd.mul_up(CellX(0).Width(), CellY(0).Width()));
}

Properties AccumulatorEstimate::Extras() const {
  double max_count = 0;
  cv::minMaxLoc(counts_, nullptr, &max_count);
  return {{"max_count", static_cast<std::int64_t>(max_count)},
          {"threshold", static_cast<std::int64_t>(threshold_)},
          {"cells", static_cast<std::int64_t>(cv::countNonZero(counts_ >= threshold_))}};
}

ParticleEstimate::ParticleEstimate(cv::Mat particles, std::vector<double> weights)
    : particles_(std::move(particles)), weights_(std::move(weights)) {
  if (particles_.type() != CV_64F || particles_.rows != static_cast<int>(weights_.size()))
    throw std::invalid_argument("ParticleEstimate: one CV_64F row and one weight per particle");
}

Box ParticleEstimate::Hull() const {
  Box hull(static_cast<std::size_t>(particles_.cols));
  hull.SetEmpty();
  for (int i = 0; i < particles_.rows; ++i) {
    if (!(weights_[i] > 0)) continue;
    for (int c = 0; c < particles_.cols; ++c)
      hull[c] = icp::Hull(hull[c], Interval(particles_.at<double>(i, c)));
  }
  return hull;
}

double ParticleEstimate::Area(int x, int y) const { return BoxArea(Hull(), x, y); }

std::vector<double> ParticleEstimate::Centre() const {
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
