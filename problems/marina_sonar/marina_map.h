// The marina map of the marina-sonar problem (paper 003 §6.5.2): the walls a
// sector-scan sonar sees, as a binary image in a world frame (x east, y
// north, metres), plus what the problem derives from it once: the image
// contractor's ψ transform (core/image_contractor.h) and a distance field for
// the particle filter's likelihood.
//
// The shipped map (data/marina.png, frame in data/marina.yaml) is drawn by
// DrawMarinaMap: 460 m x 280 m at 0.5 m per pixel, origin (0, 0) at the
// lower-left corner. A main basin (x 20-230 m, y 40-250 m) with 0.5 m quay
// walls and a chamfered south-west corner, four pontoons from the north quay
// (two with finger piers), a T-headed jetty from the south quay, a walled
// island in the middle, and a 20 m wide canal (y 130-150 m) leaving the east
// quay and running 210 m east to a closed end at x = 440 m. marina_map_test
// (in marina_sonar_test.cc) checks that the shipped PNG is exactly the drawn
// image; the `marina_map` tool writes both files.
#ifndef ICPBENCH_PROBLEMS_MARINA_SONAR_MARINA_MAP_H_
#define ICPBENCH_PROBLEMS_MARINA_SONAR_MARINA_MAP_H_

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

#include "core/image_contractor.h"

namespace icp {

// The frame of the shipped map.
inline constexpr double kMarinaPixelSize = 0.5;  // m
inline constexpr double kMarinaWidth = 460;      // m, along x
inline constexpr double kMarinaHeight = 280;     // m, along y

// The shipped map, drawn with OpenCV: CV_8UC1, 255 on walls, 0 elsewhere;
// row 0 is the northern edge (y = kMarinaHeight).
cv::Mat DrawMarinaMap();
// Its frame: origin (0, 0), kMarinaPixelSize.
ImageFrame MarinaMapFrame();

// Paths of the shipped map and its frame sidecar.
std::string ShippedMarinaMapPath();
// The sidecar of a map image: the same path with the extension replaced by
// ".yaml" (data/marina.png -> data/marina.yaml).
std::string MapFramePath(const std::string& image_path);

// Reads a frame sidecar: lines "key: value" for origin_x, origin_y (m) and
// pixel_size (m per pixel, > 0), each exactly once; '#' comments, blank
// lines and a leading UTF-8 byte-order mark ignored. Throws
// std::invalid_argument naming the file (source) and line.
ImageFrame ReadMapFrame(const std::string& path);
ImageFrame ReadMapFrame(std::istream& in, const std::string& source);
// Writes one, with a comment line.
void WriteMapFrame(const ImageFrame& frame, const std::string& path, const std::string& comment);

// A map with what is derived from it.
struct MarinaMap {
  std::shared_ptr<const BinaryImage> image;
  // Distance from each pixel's centre to the nearest wall pixel's centre in
  // metres (cv::distanceTransform, L2, precise), CV_32FC1, image-sized.
  std::shared_ptr<const cv::Mat> distance;
  // The world box the image covers (image->Bounds()), kept for the
  // likelihood's per-particle check.
  Box bounds;
};
// From an image (nonzero = wall) and its frame.
MarinaMap MakeMarinaMap(const cv::Mat& walls, const ImageFrame& frame);

// The largest map image, width x height in pixels (5000 x 5000, a 2.5 km
// square at 0.5 m per pixel). A map costs about 20 bytes a pixel once loaded
// (the image, its ψ transform, the distance field and their temporaries),
// 500 MB at the limit; a small PNG can declare far more pixels (15000 x
// 15000 in 44 KB), so the size is checked from the header, before a pixel is
// decoded.
inline constexpr std::int64_t kMaxMarinaMapPixels = 25'000'000;

// The size of a map image from its first bytes: the PNG signature and the
// IHDR chunk (33 bytes; a map is a PNG). Throws std::invalid_argument naming
// source when head is not the start of a PNG image or when the image has
// more than kMaxMarinaMapPixels pixels.
cv::Size MapImageSize(std::string_view head, const std::string& source);
// The walls of a PNG map image given as its bytes (a pixel is a wall when
// its grey level is >= 128): CV_8UC1, 255 on walls. Checks the size first
// (MapImageSize). Throws std::invalid_argument naming source on a bad
// header, an undecodable image, or an image without walls.
cv::Mat DecodeMapWalls(std::string_view bytes, const std::string& source);
// Reads a map: a PNG image, read as DecodeMapWalls reads its bytes, and its
// sidecar. Throws std::invalid_argument as DecodeMapWalls and ReadMapFrame
// do, or when image_path is not a regular file.
MarinaMap LoadMarinaMap(const std::string& image_path);
// Checks a map as LoadMarinaMap does, without deriving the ψ transform and
// the distance field (about 2 bytes a pixel, not 20: validation runs in the
// parent process, without a worker's memory limit). Returns the world box it
// covers, MarinaMap::bounds.
Box CheckMarinaMap(const std::string& image_path);

// The distance in metres from (x, y) to the nearest wall, by the distance
// field (the nearest pixel's value; outside the image, that of the nearest
// border pixel plus the distance to the image).
double WallDistance(const MarinaMap& map, double x, double y);

// Ray casting on the exact map, the union of the closed squares of the wall
// pixels: the distance t >= 0 along the ray from (x, y) in direction angle
// (rad, counterclockwise from the x axis) at which the ray has entered the
// first wall pixel by 1 mm (so that the point lies inside a wall pixel, at
// least 1e-6 pixel from its edges; a ray that only grazes a pixel's corner
// goes on), or nothing when no wall lies within max_distance.
std::optional<double> CastRay(const BinaryImage& map, double x, double y, double angle,
                              double max_distance);

// Whether (x, y) lies in a wall pixel, at least margin pixels (a fraction of
// a pixel) inside it.
bool InsideWallPixel(const BinaryImage& map, double x, double y, double margin);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_MARINA_SONAR_MARINA_MAP_H_
