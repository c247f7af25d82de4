#include "problems/marina_sonar/marina_map.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/params.h"
#include "problems/log_file.h"

namespace icp {

namespace {

// Fills the world rectangle [x0, x1] x [y0, y1] (metres, on the pixel grid
// of the shipped map) with wall pixels.
void Fill(cv::Mat& img, double x0, double x1, double y0, double y1) {
  const double s = kMarinaPixelSize;
  const int c0 = static_cast<int>(std::lround(x0 / s)), c1 = static_cast<int>(std::lround(x1 / s));
  const int b0 = static_cast<int>(std::lround(y0 / s)), b1 = static_cast<int>(std::lround(y1 / s));
  cv::rectangle(img, cv::Rect(c0, img.rows - b1, c1 - c0, b1 - b0), cv::Scalar(255), cv::FILLED);
}

// The pixel holding the world point (x, y) of the shipped map.
cv::Point PixelOf(const cv::Mat& img, double x, double y) {
  const double s = kMarinaPixelSize;
  return {static_cast<int>(std::floor(x / s)), img.rows - 1 - static_cast<int>(std::floor(y / s))};
}

}  // namespace

cv::Mat DrawMarinaMap() {
  const int cols = static_cast<int>(std::lround(kMarinaWidth / kMarinaPixelSize));
  const int rows = static_cast<int>(std::lround(kMarinaHeight / kMarinaPixelSize));
  cv::Mat img(rows, cols, CV_8UC1, cv::Scalar(0));
  // The main basin's quays, one pixel (0.5 m) thick, open on the east quay
  // between y = 130 and 150 m where the canal leaves.
  Fill(img, 19.5, 20, 70, 250.5);      // west quay
  Fill(img, 19.5, 230.5, 250, 250.5);  // north quay
  Fill(img, 230, 230.5, 150, 250.5);   // east quay, north of the canal
  Fill(img, 230, 230.5, 39.5, 130);    // east quay, south of the canal
  Fill(img, 50, 230.5, 39.5, 40);      // south quay
  // The chamfered south-west corner: a 4-connected line (no diagonal gaps
  // a ray could slip through).
  cv::line(img, PixelOf(img, 19.75, 70), PixelOf(img, 50, 39.75), cv::Scalar(255), 1, cv::LINE_4);
  // The canal: 20 m wide, 210 m long, closed at its east end.
  Fill(img, 230, 440.5, 150, 150.5);
  Fill(img, 230, 440.5, 129.5, 130);
  Fill(img, 440, 440.5, 129.5, 150.5);
  // Four 1 m pontoons from the north quay, 45 m long; finger piers on two.
  for (double x : {70.0, 110.0, 150.0, 190.0}) Fill(img, x, x + 1, 205, 250);
  for (double y : {215.0, 225.0, 235.0}) {
    Fill(img, 111, 119, y, y + 0.5);
    Fill(img, 142, 150, y, y + 0.5);
  }
  // A T-headed jetty from the south quay.
  Fill(img, 140, 141, 40, 75);
  Fill(img, 133, 148, 75, 76);
  // A walled island in the middle of the basin.
  Fill(img, 115, 160, 125, 125.5);
  Fill(img, 115, 160, 154.5, 155);
  Fill(img, 115, 115.5, 125, 155);
  Fill(img, 159.5, 160, 125, 155);
  return img;
}

ImageFrame MarinaMapFrame() { return ImageFrame{0, 0, kMarinaPixelSize}; }

std::string ShippedMarinaMapPath() { return std::string(ICPBENCH_MARINA_SONAR_DATA) + "/marina.png"; }

std::string MapFramePath(const std::string& image_path) {
  return std::filesystem::path(image_path).replace_extension(".yaml").string();
}

ImageFrame ReadMapFrame(const std::string& path) {
  std::ifstream in = OpenLogFile(path, "map frame (origin_x, origin_y, pixel_size)");
  return ReadMapFrame(in, path);
}

ImageFrame ReadMapFrame(std::istream& in, const std::string& source) {
  double values[3] = {0, 0, 0};
  bool seen[3] = {false, false, false};
  constexpr const char* kKeys[3] = {"origin_x", "origin_y", "pixel_size"};
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    if (++number == 1) StripByteOrderMark(line);
    const std::string where = source + ":" + std::to_string(number) + ": ";
    std::string_view text(line);
    const auto hash = text.find('#');
    if (hash != std::string_view::npos) text = text.substr(0, hash);
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) throw std::invalid_argument(where + "expected 'key: value'");
    auto trim = [](std::string_view s) {
      const auto b = s.find_first_not_of(" \t\r");
      if (b == std::string_view::npos) return std::string_view();
      const auto e = s.find_last_not_of(" \t\r");
      return s.substr(b, e - b + 1);
    };
    const std::string_view key = trim(text.substr(0, colon));
    const std::string_view value = trim(text.substr(colon + 1));
    const auto* it = std::find(std::begin(kKeys), std::end(kKeys), key);
    if (it == std::end(kKeys))
      throw std::invalid_argument(where + "unknown key '" + QuoteForMessage(key) +
                                  "' (known: origin_x, origin_y, pixel_size)");
    const int k = static_cast<int>(it - std::begin(kKeys));
    if (seen[k]) throw std::invalid_argument(where + "key '" + std::string(key) + "' repeated");
    double v = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (value.empty() || ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v) ||
        std::fabs(v) > 1e9)
      throw std::invalid_argument(where + std::string(key) + ": '" + QuoteForMessage(value) +
                                  "' is not a finite number within +-1e9");
    if (k == 2 && !(v > 0)) throw std::invalid_argument(where + "pixel_size must be > 0");
    values[k] = v;
    seen[k] = true;
  }
  for (int k = 0; k < 3; ++k)
    if (!seen[k]) throw std::invalid_argument(source + ": lacks the key '" + kKeys[k] + "'");
  return ImageFrame{values[0], values[1], values[2]};
}

void WriteMapFrame(const ImageFrame& frame, const std::string& path, const std::string& comment) {
  std::ofstream out(path);
  if (!out) throw std::invalid_argument(path + ": cannot write the map frame");
  out << "# " << comment << "\n"
      << "origin_x: " << FormatDouble(frame.origin_x) << "\n"
      << "origin_y: " << FormatDouble(frame.origin_y) << "\n"
      << "pixel_size: " << FormatDouble(frame.pixel_size) << "\n";
}

MarinaMap MakeMarinaMap(const cv::Mat& walls, const ImageFrame& frame) {
  cv::Mat binary = walls != 0;  // 255 on walls
  if (cv::countNonZero(binary) == 0) throw std::invalid_argument("marina map: no wall pixel");
  MarinaMap map;
  map.image = std::make_shared<const BinaryImage>(binary, frame);
  cv::Mat water = binary == 0;
  cv::Mat distance;
  cv::distanceTransform(water, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  distance *= frame.pixel_size;
  map.distance = std::make_shared<const cv::Mat>(std::move(distance));
  map.bounds = map.image->Bounds();
  return map;
}

namespace {

// The PNG signature and the IHDR chunk that must follow it (PNG spec §5.2,
// §11.2.2): length 13, type, width and height (big-endian, 1 to 2^31 - 1),
// bit depth, colour type, compression, filter, interlace, CRC.
constexpr std::string_view kPngSignature("\x89PNG\r\n\x1a\n", 8);
constexpr std::size_t kPngHeadSize = 33;

std::uint32_t BigEndian32(std::string_view bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[i]);
  return v;
}

std::string NotAPng(const std::string& source, const std::string& why) {
  return source + ": not a PNG map image (" + why +
         "); a map is a PNG whose pixels are walls where the grey level is >= 128";
}

// The first kPngHeadSize bytes of the file at path (fewer if it is shorter).
std::string ReadHead(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open the map image");
  std::string head(kPngHeadSize, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

void CheckRegularFile(const std::string& image_path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(image_path, ec))
    throw std::invalid_argument(image_path + ": no such map image (a regular file)");
}

// The walls of a decoded grey image; OpenCV's own exceptions (a decoder
// failing on a corrupt file) become the reader's documented one.
template <typename Decode>
cv::Mat WallsOf(Decode decode, const std::string& source) {
  cv::Mat grey;
  try {
    grey = decode();
  } catch (const cv::Exception& e) {
    throw std::invalid_argument(source + ": cannot decode the map image (" + e.err + ")");
  }
  if (grey.empty()) throw std::invalid_argument(source + ": cannot decode the map image");
  cv::Mat walls = grey >= 128;
  if (cv::countNonZero(walls) == 0)
    throw std::invalid_argument(source + ": the map has no wall pixel (grey level >= 128)");
  return walls;
}

// The world box of a rows x cols image in frame, rounded outward: what
// BinaryImage::Bounds gives once the image is decoded.
Box MapBounds(int rows, int cols, const ImageFrame& frame) {
  const Interval s(frame.pixel_size);
  auto extent = [&](double origin, int n) {
    const Interval o(origin);
    return Interval(o.lo(), (o + Interval(static_cast<double>(n)) * s).hi());
  };
  return Box{extent(frame.origin_x, cols), extent(frame.origin_y, rows)};
}

}  // namespace

cv::Size MapImageSize(std::string_view head, const std::string& source) {
  if (head.substr(0, kPngSignature.size()) != kPngSignature)
    throw std::invalid_argument(NotAPng(source, "no PNG signature"));
  if (head.size() < kPngHeadSize) throw std::invalid_argument(NotAPng(source, "truncated header"));
  if (BigEndian32(head.substr(8)) != 13 || head.substr(12, 4) != "IHDR")
    throw std::invalid_argument(NotAPng(source, "no IHDR chunk first"));
  const std::uint32_t width = BigEndian32(head.substr(16)), height = BigEndian32(head.substr(20));
  constexpr std::uint32_t kPngMaxSide = 0x7fffffff;
  if (width == 0 || height == 0 || width > kPngMaxSide || height > kPngMaxSide)
    throw std::invalid_argument(NotAPng(source, "width " + std::to_string(width) + ", height " +
                                                    std::to_string(height)));
  const std::int64_t pixels = std::int64_t{width} * height;
  if (pixels > kMaxMarinaMapPixels)
    throw std::invalid_argument(source + ": the map image is " + std::to_string(width) + " x " +
                                std::to_string(height) + " = " + std::to_string(pixels) +
                                " pixels, beyond the limit of " +
                                std::to_string(kMaxMarinaMapPixels) +
                                " (5000 x 5000): crop the map or use larger pixels");
  return cv::Size(static_cast<int>(width), static_cast<int>(height));
}

cv::Mat DecodeMapWalls(std::string_view bytes, const std::string& source) {
  MapImageSize(bytes.substr(0, kPngHeadSize), source);
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::invalid_argument(source + ": the map image's file is over 2 GiB");
  return WallsOf(
      [bytes] {
        const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8UC1,
                             const_cast<char*>(bytes.data()));
        return cv::imdecode(buffer, cv::IMREAD_GRAYSCALE);
      },
      source);
}

MarinaMap LoadMarinaMap(const std::string& image_path) {
  CheckRegularFile(image_path);
  MapImageSize(ReadHead(image_path), image_path);
  const ImageFrame frame = ReadMapFrame(MapFramePath(image_path));
  return MakeMarinaMap(
      WallsOf([&] { return cv::imread(image_path, cv::IMREAD_GRAYSCALE); }, image_path), frame);
}

Box CheckMarinaMap(const std::string& image_path) {
  CheckRegularFile(image_path);
  MapImageSize(ReadHead(image_path), image_path);
  const ImageFrame frame = ReadMapFrame(MapFramePath(image_path));
  const cv::Mat walls =
      WallsOf([&] { return cv::imread(image_path, cv::IMREAD_GRAYSCALE); }, image_path);
  return MapBounds(walls.rows, walls.cols, frame);
}

double WallDistance(const MarinaMap& map, double x, double y) {
  const BinaryImage& image = *map.image;
  const ImageFrame& f = image.frame();
  const double u = (x - f.origin_x) / f.pixel_size, w = (y - f.origin_y) / f.pixel_size;
  const double cu = std::clamp(u, 0.0, image.cols() - 0.5), cw = std::clamp(w, 0.0, image.rows() - 0.5);
  const double outside = std::hypot(u - cu, w - cw) * f.pixel_size;
  const int c = static_cast<int>(cu), r = image.rows() - 1 - static_cast<int>(cw);
  return map.distance->at<float>(r, c) + outside;
}

bool InsideWallPixel(const BinaryImage& map, double x, double y, double margin) {
  const ImageFrame& f = map.frame();
  const double u = (x - f.origin_x) / f.pixel_size, w = (y - f.origin_y) / f.pixel_size;
  if (!(u >= 0 && w >= 0 && u < map.cols() && w < map.rows())) return false;
  const double c = std::floor(u), b = std::floor(w);
  const double fu = u - c, fw = w - b;
  if (fu < margin || fu > 1 - margin || fw < margin || fw > 1 - margin) return false;
  return map.IsSet(map.rows() - 1 - static_cast<int>(b), static_cast<int>(c));
}

std::optional<double> CastRay(const BinaryImage& map, double x, double y, double angle,
                              double max_distance) {
  constexpr double kPenetration = 1e-3;  // m
  constexpr double kMargin = 1e-6;       // pixel
  const ImageFrame& f = map.frame();
  const double s = f.pixel_size;
  const double u = (x - f.origin_x) / s, w = (y - f.origin_y) / s;
  if (!(u >= 0 && w >= 0 && u < map.cols() && w < map.rows())) return std::nullopt;
  const double dx = std::cos(angle), dy = std::sin(angle);
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(w));
  const int step_i = dx > 0 ? 1 : -1, step_j = dy > 0 ? 1 : -1;
  // Amanatides-Woo traversal: t (metres along the ray) of the next vertical
  // and horizontal pixel edges.
  double next_x = dx == 0 ? kInfinity : (dx > 0 ? i + 1 - u : u - i) * s / std::fabs(dx);
  double next_y = dy == 0 ? kInfinity : (dy > 0 ? j + 1 - w : w - j) * s / std::fabs(dy);
  const double delta_x = dx == 0 ? kInfinity : s / std::fabs(dx);
  const double delta_y = dy == 0 ? kInfinity : s / std::fabs(dy);
  double t_enter = 0;
  while (t_enter <= max_distance) {
    if (map.IsSet(map.rows() - 1 - j, i)) {
      const double t = t_enter + kPenetration;
      if (InsideWallPixel(map, x + t * dx, y + t * dy, kMargin)) return t;
    }
    if (next_x < next_y) {
      i += step_i;
      t_enter = next_x;
      next_x += delta_x;
    } else {
      j += step_j;
      t_enter = next_y;
      next_y += delta_y;
    }
    if (i < 0 || j < 0 || i >= map.cols() || j >= map.rows()) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace icp
