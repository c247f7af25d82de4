// Box polynomials drawn as thesis 003 draws them in Fig. 5.2 (§5.1.4): per
// panel, the x-y boxes of the coefficients (the darker, the higher the
// degree) with the lines (or any segments) on top, and below it the
// projection on x: coefficient k's x interval at height k, where the point
// most measurements agree on shows as a peak. One coefficient, the one of
// degree n - q that encloses the guaranteed solution, is drawn white.
#ifndef ICPBENCH_PLOTS_BOX_POLYNOMIAL_FIGURE_H_
#define ICPBENCH_PLOTS_BOX_POLYNOMIAL_FIGURE_H_

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/box.h"
#include "plots/figures.h"

namespace icp {

struct BoxPolynomialPanel {
  std::string title;               // "(a) C*(3), p = 1"
  std::vector<Box> coefficients;   // by degree 0..N; x = component 0, y = 1
  int white = -1;                  // the degree drawn white; -1: none
};

// The figure: two panels a row, each one's boxes above its projection, over
// the search rectangle x by y; segments {x0, y0, x1, y1} (the lines) and
// the truth (when given) on top of the boxes. Empty coefficients are not
// drawn. Skipped (text.skip_reason) without panels.
void PlotBoxPolynomialFigure(const FigureText& text, const std::vector<BoxPolynomialPanel>& panels,
                             const Interval& x, const Interval& y,
                             const std::vector<std::array<double, 4>>& segments,
                             const std::vector<double>& truth, const std::string& out_dir,
                             PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_PLOTS_BOX_POLYNOMIAL_FIGURE_H_
