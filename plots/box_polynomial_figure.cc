#include "plots/box_polynomial_figure.h"

#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

#include "plots/figures_internal.h"

namespace icp {

namespace {

// Grey of degree k of n: light for 0, black for n; as gnuplot's rgb integer.
double Grey(int k, int n) {
  const int level = 225 - 225 * k / std::max(1, n);
  return static_cast<double>((level << 16) | (level << 8) | level);
}

std::string Range(const Interval& r) {
  std::ostringstream s;
  s.precision(17);
  s << "[" << r.lo() << ":" << r.hi() << "]";
  return s.str();
}

constexpr char kGreyBoxes[] =
    "using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc rgb variable notitle";
constexpr char kWhiteBox[] =
    "using 1:2:3:4 with boxxyerror fs solid 1.0 border lc rgb '#d62728' lw 1.5 lc rgb 'white' "
    "notitle";

// The coefficients drawn as boxes {x, y, half width, half height} of
// row_of(coefficient k, k): the grey ones, then the white one.
template <typename RowOf>
void AddCoefficients(const BoxPolynomialPanel& p, RowOf row_of, Panel* panel) {
  const int n = static_cast<int>(p.coefficients.size()) - 1;
  Series grey{kGreyBoxes, {}, ""}, white{kWhiteBox, {}, ""};
  for (int k = 0; k <= n; ++k) {
    const Box& b = p.coefficients[k];
    if (b.IsEmpty() || b.size() < 2) continue;
    std::vector<double> row = row_of(b, k);
    if (k == p.white) {
      white.rows.push_back(std::move(row));
    } else {
      row.push_back(Grey(k, n));
      grey.rows.push_back(std::move(row));
    }
  }
  panel->series.push_back(std::move(grey));
  panel->series.push_back(std::move(white));
}

// The x-y boxes, the lines and the truth.
Panel Boxes(const BoxPolynomialPanel& p, const Interval& x, const Interval& y,
            const std::vector<std::array<double, 4>>& segments, const std::vector<double>& truth) {
  Panel panel;
  // Two panels a row: the title wrapped to half the page.
  panel.setup = "set title " + MultiLine(Wrapped(p.title, 0.8 * kPrintWidthIn / 2)) +
                " noenhanced\nunset grid\nset size ratio -1\nset ylabel 'y (m)'\n"
                "set xrange " +
                Range(x) + "\nset yrange " + Range(y) + "\nunset key\n" +
                // A square panel, narrow: few x tics, or their labels touch.
                TicsFor("x", x.lo(), x.hi(), 3);
  AddCoefficients(
      p,
      [](const Box& b, int) {
        return std::vector<double>{Finite(b[0].Mid()), Finite(b[1].Mid()),
                                   Finite(b[0].Width() / 2), Finite(b[1].Width() / 2)};
      },
      &panel);
  Series lines{"using 1:2:($3-$1):($4-$2) with vectors nohead lw 0.8 lc rgb '#1f77b4' notitle",
               {}, ""};
  for (const auto& [x0, y0, x1, y1] : segments) lines.rows.push_back({x0, y0, x1, y1});
  panel.series.push_back(std::move(lines));
  if (truth.size() >= 2)
    panel.series.push_back({"using 1:2 with points pt 2 ps 1.5 lw 2 lc rgb '#d62728' notitle",
                            {{truth[0], truth[1]}},
                            ""});
  return panel;
}

// Coefficient k's x interval at height k.
Panel Projection(const BoxPolynomialPanel& p, const Interval& x) {
  Panel panel;
  const int n = static_cast<int>(p.coefficients.size()) - 1;
  panel.setup = TicsFor("y", 0, n, 3) +
                "unset grid\nset xlabel 'x (m)'\nset ylabel 'degree'\nset xrange " + Range(x) +
                "\nset yrange [-0.5:" + std::to_string(n) + ".5]\nunset key\n";
  AddCoefficients(
      p,
      [](const Box& b, int k) {
        return std::vector<double>{Finite(b[0].Mid()), static_cast<double>(k),
                                   Finite(b[0].Width() / 2), 0.5};
      },
      &panel);
  return panel;
}

}  // namespace

void PlotBoxPolynomialFigure(const FigureText& text, const std::vector<BoxPolynomialPanel>& panels,
                             const Interval& x, const Interval& y,
                             const std::vector<std::array<double, 4>>& segments,
                             const std::vector<double>& truth, const std::string& out_dir,
                             PlotOutput* out) {
  if (panels.empty()) return Skip(text, out);
  Figure f;
  f.name = text.name;
  f.title =
      Wrapped(text.title + "; framed red: the coefficient of degree n - q; red cross: the truth",
              kPrintWidthIn);
  // Two panels a row, each's boxes above its projection (a square plot,
  // then a flat one), so that the figure prints at the page's width.
  f.cols = 2;
  const int pairs = (static_cast<int>(panels.size()) + 1) / 2;
  f.rows = 2 * pairs;
  for (int r = 0; r < pairs; ++r) f.row_weights.insert(f.row_weights.end(), {2.3, 1.5});
  f.height_in = std::min(kPrintMaxHeightIn, 0.4 + 3.8 * pairs);
  const Panel none{"unset border\nunset tics\nunset key\nunset grid\nset xrange [0:1]\n", {}};
  for (int r = 0; r < pairs; ++r) {
    for (int c = 0; c < 2; ++c) {
      const std::size_t i = static_cast<std::size_t>(2 * r + c);
      f.panels.push_back(i < panels.size() ? Boxes(panels[i], x, y, segments, truth) : none);
    }
    for (int c = 0; c < 2; ++c) {
      const std::size_t i = static_cast<std::size_t>(2 * r + c);
      f.panels.push_back(i < panels.size() ? Projection(panels[i], x) : none);
    }
  }
  Render(f, out_dir, out);
}

}  // namespace icp
