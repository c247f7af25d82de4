// The generic figures fig_profile_time and fig_profile_area: performance
// profiles (report/performance_profile.h), rho against tau on a log axis,
// one step line per algorithm configuration.
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "plots/figures.h"
#include "plots/figures_internal.h"
#include "report/performance_profile.h"

namespace icp {

void PlotProfileFigure(const FigureText& text, const std::vector<RunRecord>& runs,
                       ProfileMetric metric, const std::string& out_dir, PlotOutput* out) {
  const PerformanceProfile profile = RunsProfile(runs, metric);
  std::map<std::string, std::string> algorithm;  // solver -> algorithm, for its colour
  for (const RunRecord& r : runs) algorithm[ProfileSolver(r)] = r.spec.algorithm;
  double tau_max = 2;
  for (const SolverProfile& s : profile.solvers)
    if (!s.ratios.empty()) tau_max = std::max(tau_max, s.ratios.back() * 1.5);
  Panel panel;
  // An algorithm's colour for all its configurations, the second, third ...
  // dashed, so they stay apart.
  std::map<std::string, int> configurations;
  for (const SolverProfile& s : profile.solvers) {
    if (s.ratios.empty()) continue;
    const std::string& a = algorithm[s.solver];
    const int nth = configurations[a]++;
    Series line{"using 1:2 with steps lw 2 dt " + std::to_string(1 + nth % 5) + " lc rgb " +
                    Quote(Colour(a)) + " title " + Quote(s.solver),
                {}, ""};
    // rho is right-continuous: it rises at each ratio, then stays to tau_max.
    line.rows.push_back({1, 0});
    for (std::size_t k = 0; k < s.ratios.size(); ++k)
      line.rows.push_back({s.ratios[k], Rho(profile, s, s.ratios[k])});
    line.rows.push_back({tau_max, Rho(profile, s, tau_max)});
    panel.series.push_back(std::move(line));
  }
  if (panel.series.empty()) return Skip(text, out);
  panel.setup = "set title " + Quote(text.title) + " noenhanced\nset xlabel " +
                Quote("τ (" + ProfileMetricName(metric) + " over the best on the instance)") +
                "\nset ylabel " + Quote("ρ(τ): share of the " +
                                        std::to_string(profile.instances) + " instances") +
                "\nset logscale x\nset xrange [1:" + std::to_string(tau_max) +
                "]\nset yrange [0:1.02]\n"
                // Long configuration labels: the key below the plot, one a line,
                // the figure as high as they need (at most a page's 7.5 in).
                "set key below left Left reverse maxcols 1 noenhanced spacing 0.9\n";
  const double height =
      std::min(kPrintMaxHeightIn, 3.2 + 0.17 * static_cast<double>(panel.series.size()));
  RenderPanel(text.name, kPrintWidthIn, height, panel, out_dir, out);
}

}  // namespace icp
