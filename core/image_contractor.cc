#include "core/image_contractor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace icp {
namespace {

// An integer-valued double (a floor or ceil) as an int in [lo, hi]; the
// clamp comes first, so huge or infinite values never reach the cast.
int ClampToInt(double v, int lo, int hi) {
  if (!(v > lo)) return lo;
  if (v >= hi) return hi;
  return static_cast<int>(v);
}

// The cells [begin, end) of a line of n cells of side s starting at origin
// (cell k covers [origin + k s, origin + (k + 1) s]) whose closed extent may
// touch the closed interval x. Cell k touches x when
//   (x.lo - origin) / s - 1 <= k <= (x.hi - origin) / s,
// so the range is [ceil(u) - 1, floor(v) + 1); taking u's lower enclosure and
// v's upper one makes it wider, never narrower. A point Interval(±inf) is
// empty, so infinite bounds are handled before any arithmetic.
std::pair<int, int> CellsMeeting(const Interval& x, double origin, double s, int n) {
  if (x.IsEmpty()) return {0, 0};
  int begin = 0, end = n;
  if (x.lo() > -kInf) {
    const Interval u = (Interval(x.lo()) - Interval(origin)) / Interval(s);
    begin = ClampToInt(std::ceil(u.lo()) - 1, 0, n);
  }
  if (x.hi() < kInf) {
    const Interval v = (Interval(x.hi()) - Interval(origin)) / Interval(s);
    end = ClampToInt(std::floor(v.hi()) + 1, 0, n);
  }
  return {begin, end};
}

// [origin + begin s, origin + end s], rounded outward.
Interval CellsExtent(int begin, int end, double origin, double s) {
  const Interval o(origin), side(s);
  const double lo = (o + Interval(static_cast<double>(begin)) * side).lo();
  const double hi = (o + Interval(static_cast<double>(end)) * side).hi();
  return Interval(lo, hi);
}

// The least k in [lo, hi] at which holds, a predicate that is false then
// true as k grows and true at hi: log2(hi - lo + 1) calls.
template <typename Predicate>
int FirstTrue(int lo, int hi, Predicate holds) {
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (holds(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

Box EmptyPlaneBox() {
  Box out(2);
  out.SetEmpty();
  return out;
}

void CheckPlaneBox(const Box& xy, const char* where) {
  if (xy.size() != 2)
    throw std::invalid_argument(std::string("BinaryImage::") + where + ": the box has " +
                                std::to_string(xy.size()) + " components, must have 2 (x, y)");
}

}  // namespace

BinaryImage::BinaryImage(const cv::Mat& image, ImageFrame frame) : frame_(frame) {
  if (image.empty()) throw std::invalid_argument("BinaryImage: the image is empty");
  if (image.type() != CV_8UC1)
    throw std::invalid_argument("BinaryImage: image type " + std::to_string(image.type()) +
                                " must be CV_8UC1 (" + std::to_string(CV_8UC1) + ")");
  if (!std::isfinite(frame.origin_x) || !std::isfinite(frame.origin_y))
    throw std::invalid_argument("BinaryImage: ImageFrame origin (" +
                                std::to_string(frame.origin_x) + ", " +
                                std::to_string(frame.origin_y) + ") must be finite");
  if (!std::isfinite(frame.pixel_size) || !(frame.pixel_size > 0))
    throw std::invalid_argument("BinaryImage: ImageFrame.pixel_size = " +
                                std::to_string(frame.pixel_size) + ": must be finite and > 0");
  // ψ is CV_32S: every block count, the whole image's included, must fit.
  if (static_cast<std::int64_t>(image.rows) * image.cols > std::numeric_limits<std::int32_t>::max())
    throw std::invalid_argument("BinaryImage: " + std::to_string(image.rows) + " x " +
                                std::to_string(image.cols) + " pixels: at most 2^31 - 1");
  rows_ = image.rows;
  cols_ = image.cols;
  cv::min(image, 1, pixels_);  // nonzero -> 1; a new matrix, not a view of image
  cv::integral(pixels_, psi_, CV_32S);
}

std::int64_t BinaryImage::Count(const PixelBlock& block) const {
  const int rb = std::max(block.row_begin, 0), re = std::min(block.row_end, rows_);
  const int cb = std::max(block.col_begin, 0), ce = std::min(block.col_end, cols_);
  if (rb >= re || cb >= ce) return 0;
  const std::int32_t* top = psi_.ptr<std::int32_t>(rb);
  const std::int32_t* bottom = psi_.ptr<std::int32_t>(re);
  return static_cast<std::int64_t>(bottom[ce]) - bottom[cb] - top[ce] + top[cb];
}

bool BinaryImage::IsSet(int row, int col) const {
  if (row < 0 || row >= rows_ || col < 0 || col >= cols_) return false;
  return pixels_.ptr<std::uint8_t>(row)[col] != 0;
}

Box BinaryImage::Bounds() const { return WorldBox({0, rows_, 0, cols_}); }

Box BinaryImage::WorldBox(const PixelBlock& block) const {
  if (block.IsEmpty()) return EmptyPlaneBox();
  const double s = frame_.pixel_size;
  // Row r is cell rows - 1 - r counted up from origin_y.
  return Box{CellsExtent(block.col_begin, block.col_end, frame_.origin_x, s),
             CellsExtent(rows_ - block.row_end, rows_ - block.row_begin, frame_.origin_y, s)};
}

PixelBlock BinaryImage::BlockMeeting(const Box& xy) const {
  CheckPlaneBox(xy, "BlockMeeting");
  if (xy.IsEmpty()) return {};
  const double s = frame_.pixel_size;
  const auto [cb, ce] = CellsMeeting(xy[0], frame_.origin_x, s, cols_);
  const auto [kb, ke] = CellsMeeting(xy[1], frame_.origin_y, s, rows_);
  PixelBlock block{rows_ - ke, rows_ - kb, cb, ce};
  if (block.IsEmpty()) return {};
  return block;
}

Box BinaryImage::Contract(const Box& xy) const {
  CheckPlaneBox(xy, "Contract");
  PixelBlock b = BlockMeeting(xy);
  if (Count(b) == 0) return EmptyPlaneBox();
  // Eq. 4.90 by dichotomy on ϕ_d: the first column whose prefix of the block
  // holds a set pixel, the last one whose suffix does; then the same for the
  // rows of the narrowed block (the columns dropped hold no set pixel).
  auto in_cols = [&](int begin, int end) { return Count({b.row_begin, b.row_end, begin, end}); };
  const int first_col =
      FirstTrue(b.col_begin, b.col_end - 1, [&](int c) { return in_cols(b.col_begin, c + 1) > 0; });
  const int last_col =
      FirstTrue(first_col, b.col_end - 1, [&](int c) { return in_cols(c + 1, b.col_end) == 0; });
  b.col_begin = first_col;
  b.col_end = last_col + 1;
  auto in_rows = [&](int begin, int end) { return Count({begin, end, b.col_begin, b.col_end}); };
  const int first_row =
      FirstTrue(b.row_begin, b.row_end - 1, [&](int r) { return in_rows(b.row_begin, r + 1) > 0; });
  const int last_row =
      FirstTrue(first_row, b.row_end - 1, [&](int r) { return in_rows(r + 1, b.row_end) == 0; });
  b.row_begin = first_row;
  b.row_end = last_row + 1;
  return Intersect(xy, WorldBox(b));
}

ImageContractor::ImageContractor(std::shared_ptr<const BinaryImage> image, int x_index, int y_index)
    : image_(std::move(image)), x_index_(x_index), y_index_(y_index) {
  if (!image_) throw std::invalid_argument("ImageContractor: image is null");
  if (x_index < 0 || y_index < 0 || x_index == y_index)
    throw std::invalid_argument("ImageContractor: x_index = " + std::to_string(x_index) +
                                ", y_index = " + std::to_string(y_index) +
                                ": must be distinct and >= 0");
}

ContractSummary ImageContractor::Contract(Box& box, ContractContext&) {
  const int needed = std::max(x_index_, y_index_) + 1;
  if (static_cast<int>(box.size()) < needed)
    throw std::invalid_argument("ImageContractor: the box has " + std::to_string(box.size()) +
                                " components, x_index = " + std::to_string(x_index_) +
                                " and y_index = " + std::to_string(y_index_) + " need " +
                                std::to_string(needed));
  const Box before = box;
  ContractSummary summary;
  summary.work.revise_calls = 1;
  if (box.IsEmpty()) {
    box.SetEmpty();
  } else {
    const Box xy = image_->Contract(Box{box[x_index_], box[y_index_]});
    if (xy.IsEmpty()) {
      box.SetEmpty();
    } else {
      box[x_index_] = xy[0];
      box[y_index_] = xy[1];
    }
  }
  summary.status = StatusOf(before, box);
  return summary;
}

}  // namespace icp
