// A figure of estimates drawn on a binary map (the marina's Figs. 6.7-6.9):
// each panel shows the map's set pixels as the background, then layers of
// boxes (see-through rectangles), tracks (lines) and points (dots), in a
// frame chosen to show them. Plots know no problem: the caller gives the map as an
// image with its frame and the layers as numbers.
#ifndef ICPBENCH_PLOTS_MAP_FIGURE_H_
#define ICPBENCH_PLOTS_MAP_FIGURE_H_

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/interval.h"
#include "plots/figures.h"

namespace icp {

// The map: walls (CV_8U, non-zero = set; row 0 the top, the y of its lower
// edge origin_y + rows * pixel_size) placed in the world by its lower-left
// corner and the side of a pixel; x, y: the rectangle a panel shows.
struct MapFrame {
  cv::Mat walls;
  double origin_x = 0, origin_y = 0, pixel_size = 1;
  Interval x, y;
};

// One layer of a panel, drawn in the order given, in colour (a gnuplot
// colour name or '#rrggbb'), with a legend entry unless title is empty.
struct MapLayer {
  enum class Kind { kBoxes, kTrack, kPoints };
  Kind kind = Kind::kTrack;
  std::string title;
  std::string colour = "black";
  // kBoxes: {x lo, x hi, y lo, y hi} per box; kTrack, kPoints: {x, y} per
  // point (a NaN row breaks a track).
  std::vector<std::vector<double>> rows;
};

struct MapPanel {
  std::string title;
  MapFrame frame;
  std::vector<MapLayer> layers;
};

// The frame that shows every track and point of layers with margin metres
// on each side, cut to bounds: the track fills the figure, and boxes wider
// than it (dead reckoning, an unknown start) are cut at its edges. The
// boxes' when the layers hold no track or point; bounds when they hold
// nothing finite.
void FrameToShow(const std::vector<MapLayer>& layers, double margin, const Interval& x_bounds,
                 const Interval& y_bounds, MapFrame* frame);

// The map's bounds in the world.
Interval MapXBounds(const MapFrame& frame);
Interval MapYBounds(const MapFrame& frame);

// The panels in rows of cols, equal scales, as wide as the paper prints
// them, each row as high as its frames need; one legend below them when
// the panels' layers have the same titles and colours; skipped with
// text.skip_reason when no panel has a layer with a point.
void PlotMapFigure(const FigureText& text, const std::vector<MapPanel>& panels, int cols,
                   const std::string& out_dir, PlotOutput* out);
// One panel titled text.title.
void PlotMapFigure(const FigureText& text, const MapFrame& frame,
                   const std::vector<MapLayer>& layers, const std::string& out_dir,
                   PlotOutput* out);

// The wall pixels inside frame's rectangle, at most max_cells a side
// (blocks of pixels, set when any pixel is): {x lo, x hi, y lo, y hi} each.
std::vector<std::vector<double>> WallCells(const MapFrame& frame, int max_cells);

}  // namespace icp

#endif  // ICPBENCH_PLOTS_MAP_FIGURE_H_
