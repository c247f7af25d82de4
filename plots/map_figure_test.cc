#include "plots/map_figure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace icp {
namespace {

// A 4 x 6 map of 0.5 m pixels from (10, 20): one wall pixel at row 0 (the
// top), column 5, and one at row 3 (the bottom), column 0.
MapFrame Small() {
  MapFrame f;
  f.walls = cv::Mat(4, 6, CV_8U, cv::Scalar(0));
  f.walls.at<unsigned char>(0, 5) = 1;
  f.walls.at<unsigned char>(3, 0) = 1;
  f.origin_x = 10, f.origin_y = 20, f.pixel_size = 0.5;
  f.x = MapXBounds(f);
  f.y = MapYBounds(f);
  return f;
}

TEST(MapFigureTest, WallCellsPlaceSetPixelsInTheWorld) {
  const MapFrame f = Small();
  EXPECT_EQ(f.x.lo(), 10);
  EXPECT_EQ(f.x.hi(), 13);
  EXPECT_EQ(f.y.hi(), 22);
  const auto cells = WallCells(f, 100);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_EQ(cells[0], (std::vector<double>{12.5, 13, 21.5, 22}));  // top right
  EXPECT_EQ(cells[1], (std::vector<double>{10, 10.5, 20, 20.5}));  // bottom left
  // At most 2 cells a side: blocks of 3 pixels, set when any pixel is.
  const auto blocks = WallCells(f, 2);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0], (std::vector<double>{11.5, 13, 20.5, 22}));
  EXPECT_EQ(blocks[1], (std::vector<double>{10, 11.5, 20, 20.5}));
  // A frame over the left half sees only the bottom-left pixel.
  MapFrame left = f;
  left.x = Interval(10, 11.4);
  EXPECT_EQ(WallCells(left, 100).size(), 1u);
}

TEST(MapFigureTest, FrameFitsTheTracksAndPointsCutToTheBounds) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<MapLayer> layers = {
      {MapLayer::Kind::kBoxes, "", "red", {{5, 60, 7, 80}, {nan, 1, 2, 3}}},
      {MapLayer::Kind::kTrack, "", "black", {{9, 4}, {nan, nan}}},
      {MapLayer::Kind::kPoints, "", "green", {{12, 6}}},
  };
  MapFrame f;
  FrameToShow(layers, 1, Interval(0, 100), Interval(0, 100), &f);  // the wide box is cut
  EXPECT_EQ(f.x.lo(), 8);
  EXPECT_EQ(f.x.hi(), 13);
  EXPECT_EQ(f.y.lo(), 3);
  EXPECT_EQ(f.y.hi(), 7);
  FrameToShow(layers, 10, Interval(0, 100), Interval(5, 100), &f);
  EXPECT_EQ(f.x.lo(), 0);
  EXPECT_EQ(f.y.lo(), 5);
  FrameToShow({layers[0]}, 1, Interval(0, 100), Interval(0, 100), &f);  // boxes alone: theirs
  EXPECT_EQ(f.x.lo(), 4);
  EXPECT_EQ(f.x.hi(), 61);
  EXPECT_EQ(f.y.lo(), 6);
  EXPECT_EQ(f.y.hi(), 81);
  FrameToShow({}, 1, Interval(0, 3), Interval(0, 4), &f);
  EXPECT_EQ(f.x.hi(), 3);
  EXPECT_EQ(f.y.hi(), 4);
}

TEST(MapFigureTest, NothingToDrawIsSkippedWithTheReason) {
  PlotOutput out;
  PlotMapFigure({"fig_map", "", "no run"}, Small(), {{MapLayer::Kind::kTrack, "", "red", {}}},
                "/nonexistent", &out);
  EXPECT_EQ(out.messages, (std::vector<std::string>{"fig_map: skipped: no run"}));
  EXPECT_TRUE(out.files.empty());
}

}  // namespace
}  // namespace icp
