#include "core/image_contractor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/contractor_algebra.h"
#include "core/contractor_testing.h"
#include "core/random.h"

namespace icp {
namespace {

// Set pixels are random nonzero values, not only 1, to check that any
// nonzero value counts.
cv::Mat RandomImage(RandomEngine& rng, int rows, int cols, double density) {
  cv::Mat image(rows, cols, CV_8UC1);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      image.at<std::uint8_t>(r, c) =
          UniformReal(rng, 0, 1) < density ? static_cast<std::uint8_t>(UniformInt(rng, 1, 255)) : 0;
  return image;
}

std::int64_t DirectCount(const cv::Mat& image, const PixelBlock& b) {
  std::int64_t n = 0;
  for (int r = std::max(b.row_begin, 0); r < std::min(b.row_end, image.rows); ++r)
    for (int c = std::max(b.col_begin, 0); c < std::min(b.col_end, image.cols); ++c)
      n += image.at<std::uint8_t>(r, c) != 0;
  return n;
}

// Pixel (r, c)'s closed square in world coordinates, rounded to nearest
// (exact for the dyadic frames below).
Box Square(const cv::Mat& image, const ImageFrame& f, int r, int c) {
  const double s = f.pixel_size;
  return Box{{f.origin_x + c * s, f.origin_x + (c + 1) * s},
             {f.origin_y + (image.rows - 1 - r) * s, f.origin_y + (image.rows - r) * s}};
}

// The minimal contraction by brute force: the hull of S_d ∩ xy, pixel by pixel.
Box BruteContract(const cv::Mat& image, const ImageFrame& f, const Box& xy) {
  Box hull(2);
  hull.SetEmpty();
  for (int r = 0; r < image.rows; ++r)
    for (int c = 0; c < image.cols; ++c)
      if (image.at<std::uint8_t>(r, c) != 0)
        hull = Hull(hull, Intersect(Square(image, f, r, c), xy));
  return hull;
}

// A bound in [lo, hi]: a random real, a pixel edge, or (rarely) infinite.
double RandomBound(RandomEngine& rng, double lo, double hi, double origin, double s, bool upper) {
  const std::int64_t kind = UniformInt(rng, 0, 9);
  if (kind == 0) return upper ? kInf : -kInf;
  const double v = UniformReal(rng, lo, hi);
  if (kind <= 4) return origin + std::round((v - origin) / s) * s;
  return v;
}

// A random box around (and sometimes beyond) the image.
Box RandomBox(RandomEngine& rng, const cv::Mat& image, const ImageFrame& f) {
  const double s = f.pixel_size, m = 3 * s;
  const double x0 = f.origin_x - m, x1 = f.origin_x + image.cols * s + m;
  const double y0 = f.origin_y - m, y1 = f.origin_y + image.rows * s + m;
  Box box(2);
  for (int d = 0; d < 2; ++d) {
    const double lo = d == 0 ? x0 : y0, hi = d == 0 ? x1 : y1;
    const double origin = d == 0 ? f.origin_x : f.origin_y;
    double a = RandomBound(rng, lo, hi, origin, s, false);
    double b = UniformInt(rng, 0, 9) == 0 ? a : RandomBound(rng, lo, hi, origin, s, true);
    box[d] = Interval(std::min(a, b), std::max(a, b));
    if (box[d].IsEmpty()) box[d] = Interval(-kInf, kInf);  // a = b = -inf
  }
  return box;
}

Box Apply(Contractor& c, Box box) {
  ContractContext context;
  c.Contract(box, context);
  return box;
}

// Frames whose pixel edges and every test computation are exact.
const ImageFrame kDyadicFrames[] = {{0, 0, 1}, {-3.5, 2.25, 0.25}, {1024, -64, 8}};
// A frame whose edges are not doubles: results are only enclosures.
const ImageFrame kDecimalFrame{0.3, -1.7, 0.1};

TEST(BinaryImageTest, CountMatchesDirectCountsOnRandomBlocks) {
  RandomEngine rng(20240601);
  for (int trial = 0; trial < 40; ++trial) {
    const int rows = static_cast<int>(UniformInt(rng, 1, 40));
    const int cols = static_cast<int>(UniformInt(rng, 1, 40));
    const cv::Mat image = RandomImage(rng, rows, cols, UniformReal(rng, 0, 1));
    const BinaryImage bi(image, {});
    ASSERT_EQ(bi.rows(), rows);
    ASSERT_EQ(bi.cols(), cols);
    for (int k = 0; k < 100; ++k) {
      // Blocks may stick out of the image (Count clips them) or be empty.
      PixelBlock b;
      b.row_begin = static_cast<int>(UniformInt(rng, -3, rows + 2));
      b.row_end = static_cast<int>(UniformInt(rng, -3, rows + 3));
      b.col_begin = static_cast<int>(UniformInt(rng, -3, cols + 2));
      b.col_end = static_cast<int>(UniformInt(rng, -3, cols + 3));
      EXPECT_EQ(bi.Count(b), DirectCount(image, b));
    }
    EXPECT_EQ(bi.Count({0, rows, 0, cols}), cv::countNonZero(image));
    for (int k = 0; k < 50; ++k) {
      const int r = static_cast<int>(UniformInt(rng, -2, rows + 1));
      const int c = static_cast<int>(UniformInt(rng, -2, cols + 1));
      const bool inside = r >= 0 && r < rows && c >= 0 && c < cols;
      EXPECT_EQ(bi.IsSet(r, c), inside && image.at<std::uint8_t>(r, c) != 0);
    }
  }
}

TEST(BinaryImageTest, KeepsItsOwnZeroOnePixels) {
  cv::Mat image = (cv::Mat_<std::uint8_t>(2, 2) << 0, 7, 255, 0);
  const BinaryImage bi(image, {});
  image.setTo(0);  // the BinaryImage copied the pixels
  EXPECT_TRUE(bi.IsSet(0, 1));
  EXPECT_TRUE(bi.IsSet(1, 0));
  EXPECT_EQ(bi.pixels().type(), CV_8UC1);
  EXPECT_EQ(bi.pixels().at<std::uint8_t>(0, 1), 1);
  EXPECT_EQ(bi.pixels().at<std::uint8_t>(1, 1), 0);
}

TEST(BinaryImageTest, ContractIsTheBruteForceHullOnExactFrames) {
  RandomEngine rng(7);
  for (const ImageFrame& frame : kDyadicFrames) {
    for (int trial = 0; trial < 15; ++trial) {
      const int rows = static_cast<int>(UniformInt(rng, 1, 30));
      const int cols = static_cast<int>(UniformInt(rng, 1, 30));
      const double density = trial % 3 == 0 ? 0.02 : UniformReal(rng, 0, 0.5);
      const cv::Mat image = RandomImage(rng, rows, cols, density);
      const BinaryImage bi(image, frame);
      for (int k = 0; k < 60; ++k) {
        const Box xy = RandomBox(rng, image, frame);
        EXPECT_EQ(bi.Contract(xy), BruteContract(image, frame, xy))
            << "box " << xy[0] << " x " << xy[1];
      }
    }
  }
}

TEST(BinaryImageTest, ContractEnclosesTheBruteForceHullTightlyOnDecimalFrames) {
  RandomEngine rng(11);
  const ImageFrame& frame = kDecimalFrame;
  for (int trial = 0; trial < 20; ++trial) {
    const int rows = static_cast<int>(UniformInt(rng, 1, 30));
    const int cols = static_cast<int>(UniformInt(rng, 1, 30));
    const cv::Mat image = RandomImage(rng, rows, cols, UniformReal(rng, 0, 0.3));
    const BinaryImage bi(image, frame);
    for (int k = 0; k < 60; ++k) {
      // Random real bounds: none within rounding error of a pixel edge, so
      // both sides see the same pixels.
      Box xy(2);
      for (int d = 0; d < 2; ++d) {
        const double lo = d == 0 ? frame.origin_x - 0.3 : frame.origin_y - 0.3;
        const double hi = lo + 0.6 + (d == 0 ? cols : rows) * frame.pixel_size;
        const double a = UniformReal(rng, lo, hi), b = UniformReal(rng, lo, hi);
        xy[d] = Interval(std::min(a, b), std::max(a, b));
      }
      const Box got = bi.Contract(xy);
      const Box brute = BruteContract(image, frame, xy);
      ASSERT_EQ(got.IsEmpty(), brute.IsEmpty()) << "box " << xy[0] << " x " << xy[1];
      if (brute.IsEmpty()) continue;
      for (int d = 0; d < 2; ++d) {
        // Brute force rounds edges to nearest; the contractor rounds outward,
        // so it holds the exact hull, within a few ulps of brute force.
        EXPECT_LE(got[d].lo(), brute[d].lo() + 1e-12);
        EXPECT_GE(got[d].hi(), brute[d].hi() - 1e-12);
        EXPECT_NEAR(got[d].lo(), brute[d].lo(), 1e-12);
        EXPECT_NEAR(got[d].hi(), brute[d].hi(), 1e-12);
        EXPECT_TRUE(got[d].IsSubsetOf(xy[d]));
      }
    }
  }
}

// A point of pixel (r, c)'s closed square: an interior point, or a point on
// an edge or corner (t = 0 or 1). On the decimal frame an edge is not a
// double; the nearest double inside the square stands for it.
double PointIn(double origin, int cell, double s, double t) {
  if (t == 0) return (Interval(origin) + Interval(cell) * Interval(s)).hi();
  if (t == 1) return (Interval(origin) + Interval(cell + 1) * Interval(s)).lo();
  return origin + (cell + t) * s;
}

TEST(BinaryImageTest, NeverRemovesAPointOfTheSet) {
  RandomEngine rng(3);
  std::vector<ImageFrame> frames(std::begin(kDyadicFrames), std::end(kDyadicFrames));
  frames.push_back(kDecimalFrame);
  for (const ImageFrame& frame : frames) {
    const cv::Mat image = RandomImage(rng, 25, 35, 0.1);
    const BinaryImage bi(image, frame);
    auto contractor =
        std::make_shared<ImageContractor>(std::make_shared<BinaryImage>(image, frame));
    std::vector<std::pair<int, int>> set_pixels;
    for (int r = 0; r < image.rows; ++r)
      for (int c = 0; c < image.cols; ++c)
        if (image.at<std::uint8_t>(r, c)) set_pixels.emplace_back(r, c);
    ASSERT_FALSE(set_pixels.empty());
    const double s = frame.pixel_size;
    for (int k = 0; k < 3000; ++k) {
      const auto [r, c] = set_pixels[UniformIndex(rng, set_pixels.size())];
      const double tx[] = {0, 1, UniformReal(rng, 0.01, 0.99)};
      const double x = PointIn(frame.origin_x, c, s, tx[UniformIndex(rng, 3)]);
      const double y = PointIn(frame.origin_y, image.rows - 1 - r, s, tx[UniformIndex(rng, 3)]);
      Box xy(2);
      const double p[] = {x, y};
      for (int d = 0; d < 2; ++d) {
        // Each bound: the point itself, a random distance, a pixel edge on
        // the right side of the point, or infinite.
        double lo = 0, hi = 0;  // both set below (clang cannot tell)
        const double origin = d == 0 ? frame.origin_x : frame.origin_y;
        for (int side = 0; side < 2; ++side) {
          const std::int64_t kind = UniformInt(rng, 0, 3);
          const double sign = side == 0 ? -1 : 1;
          double v = p[d];
          if (kind == 1) v = p[d] + sign * UniformReal(rng, 0, 5 * s);
          if (kind == 2) {
            const double e =
                origin + std::round((p[d] - origin) / s + sign * UniformInt(rng, 0, 3)) * s;
            v = side == 0 ? std::min(e, p[d]) : std::max(e, p[d]);
          }
          if (kind == 3) v = sign * kInf;
          (side == 0 ? lo : hi) = v;
        }
        xy[d] = Interval(lo, hi);
      }
      const Box got = bi.Contract(xy);
      ASSERT_TRUE(got.Contains({x, y})) << "point (" << x << ", " << y << ") of pixel (" << r
                                        << ", " << c << ") lost from " << xy[0] << " x " << xy[1];
      Box big{Interval(-1, 1), xy[0], Interval(5), xy[1]};
      ImageContractor on_big(std::make_shared<BinaryImage>(bi), 1, 3);
      ASSERT_TRUE(Apply(on_big, big).Contains({0, x, 5, y}));
    }
    // Degenerate boxes at each set pixel's corners are kept.
    for (const auto& [r, c] : set_pixels) {
      for (double tx : {0.0, 1.0})
        for (double ty : {0.0, 1.0}) {
          const double x = PointIn(frame.origin_x, c, s, tx);
          const double y = PointIn(frame.origin_y, image.rows - 1 - r, s, ty);
          EXPECT_FALSE(Apply(*contractor, Box{Interval(x), Interval(y)}).IsEmpty());
        }
    }
  }
}

TEST(BinaryImageTest, OutsideTheImageOrOverUnsetPixelsIsEmpty) {
  cv::Mat image = cv::Mat::zeros(10, 10, CV_8UC1);
  image.row(0).setTo(1);            // the top row
  image.col(9).setTo(1);            // the right column
  const BinaryImage bi(image, {});  // covers [0, 10] x [0, 10]
  EXPECT_TRUE(bi.Contract(Box{{11, 20}, {0, 10}}).IsEmpty());
  EXPECT_TRUE(bi.Contract(Box{{-5, -0.5}, {-5, 20}}).IsEmpty());
  EXPECT_TRUE(bi.Contract(Box{{0, 10}, {-3, -1e-9}}).IsEmpty());
  EXPECT_TRUE(bi.BlockMeeting(Box{{11, 20}, {0, 10}}).IsEmpty());
  // Inside the image, over unset pixels only (columns 0-8, rows 1-9).
  EXPECT_TRUE(bi.Contract(Box{{0.5, 8.5}, {0.5, 8.5}}).IsEmpty());
  EXPECT_TRUE(bi.Contract(Box{{-100, 8.99}, {-100, 8.99}}).IsEmpty());
  // An empty box stays empty.
  EXPECT_TRUE(bi.Contract(Box{Interval::Empty(), {0, 10}}).IsEmpty());
  // Closed squares: a box touching a set pixel's edge keeps that edge.
  EXPECT_EQ(bi.Contract(Box{{10, 20}, {2.5, 3.5}}), (Box{{10, 10}, {2.5, 3.5}}));
  EXPECT_EQ(bi.Contract(Box{{2.5, 3.5}, {0, 9}}), (Box{{2.5, 3.5}, {9, 9}}));
  // An all-zero image is the empty set.
  const BinaryImage none(cv::Mat::zeros(4, 4, CV_8UC1), {});
  EXPECT_TRUE(none.Contract(Box{{-kInf, kInf}, {-kInf, kInf}}).IsEmpty());
}

TEST(BinaryImageTest, FrameMapsRowZeroToTheTop) {
  cv::Mat image = cv::Mat::zeros(4, 6, CV_8UC1);
  image.at<std::uint8_t>(0, 2) = 1;  // top row, third column
  const ImageFrame frame{10, -5, 0.5};
  const BinaryImage bi(image, frame);
  EXPECT_EQ(bi.Bounds(), (Box{{10, 13}, {-5, -3}}));
  EXPECT_EQ(bi.WorldBox({0, 1, 2, 3}), (Box{{11, 11.5}, {-3.5, -3}}));
  EXPECT_EQ(bi.WorldBox({3, 4, 0, 1}), (Box{{10, 10.5}, {-5, -4.5}}));
  EXPECT_TRUE(bi.WorldBox({}).IsEmpty());
  const Box whole{{-kInf, kInf}, {-kInf, kInf}};
  EXPECT_EQ(bi.Contract(whole), (Box{{11, 11.5}, {-3.5, -3}}));
  EXPECT_EQ(bi.Contract(bi.Bounds()), (Box{{11, 11.5}, {-3.5, -3}}));
  // The bottom-left pixel is (3, 0).
  image.at<std::uint8_t>(0, 2) = 0;
  image.at<std::uint8_t>(3, 0) = 1;
  EXPECT_EQ(BinaryImage(image, frame).Contract(whole), (Box{{10, 10.5}, {-5, -4.5}}));

  // BlockMeeting: the pixels a closed box may touch, edges included.
  EXPECT_EQ(bi.BlockMeeting(Box{{11.2, 11.3}, {-3.2, -3.1}}).col_begin, 2);
  const PixelBlock inner = bi.BlockMeeting(Box{{11.2, 11.3}, {-3.2, -3.1}});
  EXPECT_EQ((std::vector<int>{inner.row_begin, inner.row_end, inner.col_begin, inner.col_end}),
            (std::vector<int>{0, 1, 2, 3}));
  const PixelBlock edge = bi.BlockMeeting(Box{Interval(11.5), Interval(-3.5)});
  EXPECT_EQ((std::vector<int>{edge.row_begin, edge.row_end, edge.col_begin, edge.col_end}),
            (std::vector<int>{0, 2, 2, 4}));
  const PixelBlock all = bi.BlockMeeting(whole);
  EXPECT_EQ((std::vector<int>{all.row_begin, all.row_end, all.col_begin, all.col_end}),
            (std::vector<int>{0, 4, 0, 6}));
}

TEST(ImageContractorTest, ComposesWithTheAlgebraOnWiderBoxes) {
  // Two maps over [0, 8] x [0, 8]: a vertical wall at x in [2, 3], and a
  // horizontal one at y in [5, 6] (rows from the top: row 2).
  cv::Mat vertical = cv::Mat::zeros(8, 8, CV_8UC1), horizontal = cv::Mat::zeros(8, 8, CV_8UC1);
  vertical.col(2).setTo(1);
  horizontal.row(2).setTo(1);
  // The box is (y, heading, x, speed): x is component 2, y component 0.
  auto wall_x = std::make_shared<ImageContractor>(
      std::make_shared<BinaryImage>(vertical, ImageFrame{}), 2, 0);
  auto wall_y = std::make_shared<ImageContractor>(
      std::make_shared<BinaryImage>(horizontal, ImageFrame{}), 2, 0);
  const Box box{{-1, 7}, {0.1, 0.2}, {-4, 4}, {3, 4}};

  ContractContext context;
  Box one = box;
  const ContractSummary s = wall_x->Contract(one, context);
  EXPECT_EQ(s.status, ContractStatus::kContracted);
  EXPECT_EQ(one, (Box{{0, 7}, {0.1, 0.2}, {2, 3}, {3, 4}}));
  EXPECT_EQ(wall_x->Contract(one, context).status, ContractStatus::kFixpoint);

  IntersectionContractor both({wall_x, wall_y});
  EXPECT_EQ(Apply(both, box), (Box{{5, 6}, {0.1, 0.2}, {2, 3}, {3, 4}}));
  UnionContractor either({wall_x, wall_y});
  EXPECT_EQ(Apply(either, box), (Box{{0, 7}, {0.1, 0.2}, {0, 4}, {3, 4}}));

  // A third map holding neither wall's crossing: q = 1 keeps the crossing.
  auto nowhere = std::make_shared<ImageContractor>(
      std::make_shared<BinaryImage>(cv::Mat::zeros(8, 8, CV_8UC1), ImageFrame{}), 2, 0);
  const SharedContractors three{wall_x, wall_y, nowhere};
  EXPECT_EQ(testing::KeptBy(three, {5.5, 0, 2.5, 0}), 2);
  QIntersectionContractor q1(three, 1);
  EXPECT_EQ(Apply(q1, box), (Box{{5, 6}, {0.1, 0.2}, {2, 3}, {3, 4}}));
  QIntersectionContractor q0(three, 0);
  Box empty = box;
  EXPECT_EQ(q0.Contract(empty, context).status, ContractStatus::kEmpty);
  for (const Interval& x : empty) EXPECT_TRUE(x.IsEmpty());

  // Off the walls: every component is emptied, status kEmpty.
  Box off{{-1, 7}, {0.1, 0.2}, {4, 5}, {3, 4}};
  EXPECT_EQ(wall_x->Contract(off, context).status, ContractStatus::kEmpty);
  for (const Interval& x : off) EXPECT_TRUE(x.IsEmpty());
}

TEST(ImageContractorTest, BadInputsThrow) {
  const ImageFrame unit;
  const cv::Mat ok = cv::Mat::ones(3, 3, CV_8UC1);
  EXPECT_THROW(BinaryImage(cv::Mat(), unit), std::invalid_argument);
  EXPECT_THROW(BinaryImage(cv::Mat::ones(3, 3, CV_32F), unit), std::invalid_argument);
  EXPECT_THROW(BinaryImage(cv::Mat::ones(3, 3, CV_8UC3), unit), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double s : {0.0, -1.0, nan, kInf})
    EXPECT_THROW(BinaryImage(ok, (ImageFrame{0, 0, s})), std::invalid_argument) << s;
  EXPECT_THROW(BinaryImage(ok, (ImageFrame{nan, 0, 1})), std::invalid_argument);
  EXPECT_THROW(BinaryImage(ok, (ImageFrame{0, -kInf, 1})), std::invalid_argument);
  EXPECT_NO_THROW(BinaryImage(ok, (ImageFrame{-1e6, 1e6, 1e-3})));

  auto image = std::make_shared<BinaryImage>(ok, unit);
  EXPECT_THROW(ImageContractor(nullptr), std::invalid_argument);
  EXPECT_THROW(ImageContractor(image, 1, 1), std::invalid_argument);
  EXPECT_THROW(ImageContractor(image, -1, 0), std::invalid_argument);
  ImageContractor far(image, 0, 4);
  Box small{{0, 1}, {0, 1}, {0, 1}};
  ContractContext context;
  EXPECT_THROW(far.Contract(small, context), std::invalid_argument);
  EXPECT_THROW(image->Contract(small), std::invalid_argument);
  EXPECT_THROW(image->BlockMeeting(Box{{0, 1}}), std::invalid_argument);
}

}  // namespace
}  // namespace icp
