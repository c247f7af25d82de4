// Estimates on a binary map: the map's wall pixels, then boxes, tracks and
// points (plots/map_figure.h).
#include "plots/map_figure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "plots/figures_internal.h"

namespace icp {

namespace {

// Wall cells drawn per side at most: enough to read the quays, few enough
// that the inline data stays small.
constexpr int kMaxWallCells = 300;

// {x lo, x hi, y lo, y hi} as {x, y, half width, half height}, what
// gnuplot's boxxyerror reads.
std::vector<double> CentreAndHalves(const std::vector<double>& b) {
  return {Finite((b[0] + b[1]) / 2), Finite((b[2] + b[3]) / 2), Finite((b[1] - b[0]) / 2),
          Finite((b[3] - b[2]) / 2)};
}

std::string Title(const std::string& t) { return t.empty() ? "notitle" : "title " + Quote(t); }

// The panel, its title wrapped to width_in; its legend in the figure's
// footer, or none when key is false.
Panel ToPanel(const MapPanel& p, bool key, double width_in) {
  const MapFrame& f = p.frame;
  Panel panel;
  panel.setup = "set title " + MultiLine(Wrapped(p.title, width_in)) +
                " noenhanced\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset size ratio -1\n" +
                (key ? kFooterKey : "unset key\n") + TicsFor("x", f.x.lo(), f.x.hi(), 8) +
                TicsFor("y", f.y.lo(), f.y.hi(), 6) + "set xrange [" + std::to_string(f.x.lo()) +
                ":" + std::to_string(f.x.hi()) + "]\nset yrange [" + std::to_string(f.y.lo()) +
                ":" + std::to_string(f.y.hi()) + "]\n";
  Series walls{"using 1:2:3:4 with boxxyerror fs solid 1.0 noborder lc rgb '#c8c8c8' title 'map'",
               {}, ""};
  for (const std::vector<double>& c : WallCells(f, kMaxWallCells))
    walls.rows.push_back(CentreAndHalves(c));
  if (HasPoint(walls)) panel.series.push_back(std::move(walls));
  for (const MapLayer& l : p.layers) {
    const std::string colour = "lc rgb " + Quote(l.colour) + " " + Title(l.title);
    Series s;
    switch (l.kind) {
      case MapLayer::Kind::kBoxes:
        // Filled see-through, so that small boxes show and overlaps read.
        s.spec = "using 1:2:3:4 with boxxyerror fs transparent solid 0.25 border lw 1.2 " + colour;
        for (const std::vector<double>& b : l.rows) s.rows.push_back(CentreAndHalves(b));
        break;
      case MapLayer::Kind::kTrack:
        s.spec = "using 1:2 with lines lw 1.5 " + colour;
        s.rows = l.rows;
        break;
      case MapLayer::Kind::kPoints:
        s.spec = "using 1:2 with points pt 7 ps 0.3 " + colour;
        s.rows = l.rows;
        break;
    }
    if (HasPoint(s)) panel.series.push_back(std::move(s));
  }
  return panel;
}

// The legend entries of a panel, in order.
std::vector<std::string> LegendOf(const MapPanel& p) {
  std::vector<std::string> titles = {"map"};
  for (const MapLayer& l : p.layers)
    if (!l.title.empty()) titles.push_back(l.title + "\t" + l.colour);
  return titles;
}

// The height a panel of frame f takes at the given width: its plot at equal
// scales (at most max_plot_in high), its title lines and axis labels.
double PanelHeight(const MapPanel& p, double width_in, double max_plot_in) {
  const MapFrame& f = p.frame;
  const double plot_width = width_in - 0.8;
  const double plot = std::min(max_plot_in, plot_width * f.y.Width() / std::max(1e-9, f.x.Width()));
  const std::string title = Wrapped(p.title, width_in);
  return plot + 0.55 +
         0.17 * (1 + static_cast<double>(std::count(title.begin(), title.end(), '\n')));
}

bool HasLayerPoint(const MapPanel& p) {
  return std::any_of(p.layers.begin(), p.layers.end(), [](const MapLayer& l) {
    return std::any_of(l.rows.begin(), l.rows.end(), [](const std::vector<double>& r) {
      return std::all_of(r.begin(), r.end(), [](double v) { return std::isfinite(v); });
    });
  });
}

}  // namespace

Interval MapXBounds(const MapFrame& f) {
  return Interval(f.origin_x, f.origin_x + f.walls.cols * f.pixel_size);
}

Interval MapYBounds(const MapFrame& f) {
  return Interval(f.origin_y, f.origin_y + f.walls.rows * f.pixel_size);
}

void FrameToShow(const std::vector<MapLayer>& layers, double margin, const Interval& x_bounds,
                 const Interval& y_bounds, MapFrame* frame) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
  auto fit = [&](bool boxes) {
    for (const MapLayer& l : layers) {
      if ((l.kind == MapLayer::Kind::kBoxes) != boxes) continue;
      for (const std::vector<double>& r : l.rows) {
        if (!std::all_of(r.begin(), r.end(), [](double v) { return std::isfinite(v); })) continue;
        x0 = std::min(x0, r[0]), x1 = std::max(x1, boxes ? r[1] : r[0]);
        y0 = std::min(y0, boxes ? r[2] : r[1]), y1 = std::max(y1, boxes ? r[3] : r[1]);
      }
    }
  };
  fit(false);              // the tracks and points
  if (x0 > x1) fit(true);  // else the boxes
  if (x0 > x1) {
    frame->x = x_bounds, frame->y = y_bounds;
    return;
  }
  frame->x = Interval(std::max(x_bounds.lo(), x0 - margin), std::min(x_bounds.hi(), x1 + margin));
  frame->y = Interval(std::max(y_bounds.lo(), y0 - margin), std::min(y_bounds.hi(), y1 + margin));
}

std::vector<std::vector<double>> WallCells(const MapFrame& f, int max_cells) {
  std::vector<std::vector<double>> cells;
  if (f.walls.empty() || f.pixel_size <= 0) return cells;
  // The pixel columns and rows (row 0 at the top) that meet the frame.
  const int rows = f.walls.rows, cols = f.walls.cols;
  auto col_of = [&](double x) { return static_cast<int>(std::floor((x - f.origin_x) / f.pixel_size)); };
  auto row_of = [&](double y) {
    return rows - 1 - static_cast<int>(std::floor((y - f.origin_y) / f.pixel_size));
  };
  const int c0 = std::max(0, col_of(f.x.lo())), c1 = std::min(cols - 1, col_of(f.x.hi()));
  const int r0 = std::max(0, row_of(f.y.hi())), r1 = std::min(rows - 1, row_of(f.y.lo()));
  if (c0 > c1 || r0 > r1) return cells;
  const int side = std::max(c1 - c0 + 1, r1 - r0 + 1);
  const int block = std::max(1, (side + max_cells - 1) / max_cells);
  for (int r = r0; r <= r1; r += block) {
    for (int c = c0; c <= c1; c += block) {
      const int re = std::min(r1 + 1, r + block), ce = std::min(c1 + 1, c + block);
      if (cv::countNonZero(f.walls(cv::Range(r, re), cv::Range(c, ce))) == 0) continue;
      cells.push_back({f.origin_x + c * f.pixel_size, f.origin_x + ce * f.pixel_size,
                       f.origin_y + (rows - re) * f.pixel_size,
                       f.origin_y + (rows - r) * f.pixel_size});
    }
  }
  return cells;
}

void PlotMapFigure(const FigureText& text, const std::vector<MapPanel>& panels, int cols,
                   const std::string& out_dir, PlotOutput* out) {
  if (std::none_of(panels.begin(), panels.end(), HasLayerPoint)) return Skip(text, out);
  Figure f;
  f.name = text.name;
  f.title = panels.size() > 1 ? Wrapped(text.title, kPrintWidthIn) : "";
  f.cols = std::max(1, std::min(cols, static_cast<int>(panels.size())));
  f.rows = (static_cast<int>(panels.size()) + f.cols - 1) / f.cols;
  // One legend, in the footer, when the panels' entries are the same; else
  // none (the caption names the layers).
  bool same = true;
  for (const MapPanel& p : panels) same = same && LegendOf(p) == LegendOf(panels.front());
  std::vector<std::string> entries = {"map"};
  for (const MapLayer& l : panels.back().layers)
    if (!l.title.empty()) entries.push_back(l.title);
  f.footer_in = same ? FooterHeight(entries) : 0;
  const double width = kPrintWidthIn / f.cols;
  const double title = f.title.empty() ? 0 : 0.25;
  const double max_plot = (kPrintMaxHeightIn - title - f.footer_in) / f.rows - 0.9;
  double height = title + f.footer_in;
  for (int row = 0; row < f.rows; ++row) {
    double tallest = 0;
    for (int c = 0; c < f.cols && row * f.cols + c < static_cast<int>(panels.size()); ++c)
      tallest = std::max(tallest, PanelHeight(panels[static_cast<std::size_t>(row * f.cols + c)],
                                              width, max_plot));
    f.row_weights.push_back(tallest);
    height += tallest;
  }
  f.height_in = std::min(kPrintMaxHeightIn, height);
  for (std::size_t i = 0; i < panels.size(); ++i)
    f.panels.push_back(ToPanel(panels[i], same && i + 1 == panels.size(), width));
  Render(f, out_dir, out);
}

void PlotMapFigure(const FigureText& text, const MapFrame& frame,
                   const std::vector<MapLayer>& layers, const std::string& out_dir,
                   PlotOutput* out) {
  PlotMapFigure(text, {{text.title, frame, layers}}, 1, out_dir, out);
}

}  // namespace icp
