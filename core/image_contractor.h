// The image contractor of paper 003 §4.8: a set of the plane given as a
// binary image (a map's walls), and the minimal contractor whose insensitive
// points are that set (Definition 20), in its discrete form (§4.8.5) used on
// real boxes (§4.8.6, eq. 4.94).
//
// The set S_d is the union of the closed squares of the set pixels. The ψ
// transform (eq. 4.92) is the image's integral image (cv::integral), so the
// number of set pixels in any block of pixels, ϕ_d (eq. 4.93), takes four
// look-ups. A box is contracted bound by bound (eq. 4.90): the first and last
// pixel column, then row, holding a set pixel of the block the box meets,
// each found by dichotomy on ϕ_d.
//
// Pixel (row r, column c) covers, in world coordinates (x right, y up; image
// row 0 is the top, so rows are flipped, the v of eq. 4.94),
//   x in [origin_x + c s, origin_x + (c + 1) s]
//   y in [origin_y + (rows - 1 - r) s, origin_y + (rows - r) s]
// with s = pixel_size. Every mapping between world and pixel coordinates is
// rounded outward: a box is mapped to every pixel its closure may touch, a
// block of pixels to a world box that holds it. So the contractor never
// removes a point of S_d; points outside the image are outside the set.
#ifndef ICPBENCH_CORE_IMAGE_CONTRACTOR_H_
#define ICPBENCH_CORE_IMAGE_CONTRACTOR_H_

#include <cstdint>
#include <memory>
#include <string_view>

#include <opencv2/core.hpp>

#include "core/box.h"
#include "core/contractor.h"

namespace icp {

// Where an image lies in the plane: the world coordinates of its lower-left
// corner and the side of a pixel, in world units (metres).
struct ImageFrame {
  double origin_x = 0;
  double origin_y = 0;
  double pixel_size = 1;
};

// A block of pixels: rows [row_begin, row_end) x columns [col_begin,
// col_end); empty when either range is.
struct PixelBlock {
  int row_begin = 0, row_end = 0;
  int col_begin = 0, col_end = 0;
  bool IsEmpty() const { return row_begin >= row_end || col_begin >= col_end; }
};

// A binary image with its ψ transform. Immutable once built, so one image is
// shared by every contractor and thread that uses it.
class BinaryImage {
 public:
  // image: CV_8UC1, a pixel is in the set when nonzero. Throws
  // std::invalid_argument on an empty image, another type, more than 2^31 - 1
  // pixels (ψ is CV_32S), or a frame with a non-finite origin or a pixel size
  // that is not finite and positive.
  BinaryImage(const cv::Mat& image, ImageFrame frame);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  const ImageFrame& frame() const { return frame_; }
  // The image itself (CV_8UC1, 0 or 1), for drawing and likelihood fields.
  const cv::Mat& pixels() const { return pixels_; }

  // ϕ_d: the number of set pixels in block (clipped to the image).
  std::int64_t Count(const PixelBlock& block) const;
  // Whether the set pixel (row, col) is set; false outside the image.
  bool IsSet(int row, int col) const;

  // The world box covered by the whole image, rounded outward.
  Box Bounds() const;
  // The world box covered by block (non-empty), rounded outward; the empty
  // (2-component) box for an empty block.
  Box WorldBox(const PixelBlock& block) const;
  // The pixels (clipped to the image) that the closed box xy = (x, y) may
  // touch, rounded outward; empty when xy misses the image or is empty.
  // Bounds may be infinite. Throws std::invalid_argument unless xy has 2
  // components.
  PixelBlock BlockMeeting(const Box& xy) const;

  // The minimal contraction of eq. 4.90-4.94: xy intersected with the world
  // box of the smallest block holding every set pixel of BlockMeeting(xy);
  // empty (both components) when that block holds none. Throws
  // std::invalid_argument unless xy has 2 components.
  Box Contract(const Box& xy) const;

 private:
  int rows_ = 0, cols_ = 0;
  ImageFrame frame_;
  cv::Mat pixels_;  // CV_8UC1, 0 or 1
  cv::Mat psi_;     // CV_32SC1, (rows + 1) x (cols + 1): the ψ transform
};

// The image contractor as a Contractor: contracts the components x_index and
// y_index of a box to the set (the other components are left alone). Usable
// with the contractor algebra and the relaxed solvers like any other. An
// empty result empties every component (status kEmpty). Contract throws
// std::invalid_argument on a box without components x_index and y_index.
class ImageContractor : public Contractor {
 public:
  // Throws std::invalid_argument on a null image, or indices that are
  // negative or equal.
  ImageContractor(std::shared_ptr<const BinaryImage> image, int x_index = 0, int y_index = 1);
  std::string_view Name() const override { return "image"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;
  const BinaryImage& image() const { return *image_; }

 private:
  std::shared_ptr<const BinaryImage> image_;
  int x_index_, y_index_;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_IMAGE_CONTRACTOR_H_
