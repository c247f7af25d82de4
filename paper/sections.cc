#include "paper/sections.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "algorithms/registry.h"
#include "experiments/paper000/own_experiments.h"
#include "experiments/paper000/paper000.h"
#include "experiments/paper002/paper002.h"
#include "experiments/paper004/paper004.h"
#include "experiments/thesis003/city_roads.h"
#include "experiments/thesis003/fig5_2.h"
#include "experiments/thesis003/marina.h"
#include "experiments/thesis003/thesis003.h"
#include "paper/comparison.h"
#include "problems/registry.h"
#include "report/performance_profile.h"
#include "report/report.h"

namespace icp {

namespace {

std::string Tt(const std::string& text) { return "\\texttt{" + TexEscape(text) + "}"; }

bool HasRunOf(const std::vector<RunRecord>& runs, bool (*of)(const std::string& experiment)) {
  return std::any_of(runs.begin(), runs.end(),
                     [&](const RunRecord& r) { return of(ExperimentOf(r)); });
}

// A figure drawn from the store, or why it is not. The figures are drawn at
// the size the page prints them (plots/figures_internal.h, kPrintWidthIn and
// kPrintMaxHeightIn), so that their 8-pt text prints at 8 pt; the caption
// adds what the drawing noted ("NAME: note: hc4 = bc4 draw the same values
// ... and are drawn once").
std::string FigureTex(const FigureSet& figures, const std::string& name,
                      const std::string& caption) {
  if (std::filesystem::is_regular_file(figures.dir + "/" + name + ".pdf")) {
    std::string notes;
    for (const std::string& m : figures.skipped)
      if (m.rfind(name + ": note: ", 0) == 0) notes += "; " + m.substr(name.size() + 8);
    return "\\begin{figure}[htbp]\n\\centering\n\\includegraphics[width=\\linewidth,height=0.75"
           "\\textheight,keepaspectratio]{figures/" +
           name + ".pdf}\n\\caption{" + TexEscape(caption + notes + " (" + name + ")") +
           "}\n\\end{figure}\n\n";
  }
  std::string why = "no figure was written";
  for (const std::string& m : figures.skipped)
    if (m.rfind(name + ": skipped: ", 0) == 0) why = m.substr(name.size() + 11);
  return "\\emph{" + TexEscape(caption) + "} (" + Tt(name) + ") is not drawn: " + TexEscape(why) +
         ".\n\n";
}

// A table as LaTeX, in parts of at most kPartRows rows: the template keeps
// a table on one page, so a long one is cut (titles "..., continued"; the
// notes and items after the last part).
constexpr std::size_t kPartRows = 45;
std::string PagedTable(const TextTable& table) {
  if (table.rows.size() <= kPartRows) return TexTable(table);
  std::string out;
  for (std::size_t first = 0; first < table.rows.size(); first += kPartRows) {
    TextTable part = table;
    const std::size_t last = std::min(table.rows.size(), first + kPartRows);
    part.rows.assign(table.rows.begin() + first, table.rows.begin() + last);
    if (first > 0) part.title += ", continued";
    if (last < table.rows.size()) part.notes.clear(), part.items.clear();
    out += TexTable(part);
  }
  return out;
}

std::string Paragraph(const std::string& text) { return TexEscape(text) + "\n\n"; }

// A paper's claims: its published-vs-measured table.
std::string ClaimsTex(const std::string& title, const std::vector<ComparisonRow>& rows) {
  return "\\subsection{Claims}\n" + PagedTable(ComparisonTable(title, rows));
}

// The run counts by status, "87 ok, 1 failed".
std::string StatusCounts(const std::vector<RunRecord>& runs) {
  std::map<std::string, int> counts;
  for (const RunRecord& r : runs) ++counts[std::string(ToString(r.status))];
  std::string out;
  for (const auto& [status, n] : counts)
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + status;
  return out.empty() ? "none" : out;
}

// The distinct values of one provenance field with their run counts.
std::string Distinct(const std::vector<RunRecord>& runs, std::string Provenance::*field) {
  std::map<std::string, int> values;
  for (const RunRecord& r : runs)
    ++values[(r.provenance.*field).empty() ? "unknown" : r.provenance.*field];
  std::string out;
  for (const auto& [value, n] : values)
    out += (out.empty() ? "" : "; ") + value +
           (values.size() > 1 ? " (" + std::to_string(n) + " runs)" : "");
  return out.empty() ? "none" : out;
}

bool IsPaper000Experiment(const std::string& e) {
  return e == kPaper000Table1 || e == kPaper000Window;
}
bool IsRelaxedExperiment(const std::string& e) {
  return e == kThesis003Fig52 || e == kThesis003LinesAccumulator || e == kThesis003Fig55 ||
         e == kThesis003RelaxedLines || e == kThesis003RelaxedBeacons;
}
bool IsMarina(const std::string& e) { return IsMarinaExperiment(e); }
bool IsCityRoads(const std::string& e) { return e == kThesis003CityRoads; }

}  // namespace

std::string MetaTex(const std::vector<RunRecord>& runs) {
  std::string newest;
  for (const RunRecord& r : runs) newest = std::max(newest, r.provenance.date);
  return "\\newcommand{\\icpbenchdate}{" +
         TexEscape(newest.empty() ? "a store without runs" : "runs up to " + newest) + "}\n";
}

std::string ProvenanceTex(const std::vector<RunRecord>& runs, const std::string& store_path) {
  std::string first, last;
  for (const RunRecord& r : runs) {
    if (r.provenance.date.empty()) continue;
    if (first.empty() || r.provenance.date < first) first = r.provenance.date;
    last = std::max(last, r.provenance.date);
  }
  std::ostringstream out;
  out << "\\begin{center}\\small\n\\begin{tabular}{@{}lp{0.78\\linewidth}@{}}\n\\toprule\n"
      << "results store & " << Tt(store_path) << " \\\\\n"
      << "runs & " << TexEscape(std::to_string(runs.size()) + " (" + StatusCounts(runs) + ")")
      << " \\\\\n"
      << "code revision & " << TexEscape(Distinct(runs, &Provenance::git_revision)) << " \\\\\n"
      << "machine & " << TexEscape(Distinct(runs, &Provenance::machine)) << " \\\\\n"
      << "compiler & " << TexEscape(Distinct(runs, &Provenance::compiler)) << " \\\\\n"
      << "flags & " << TexEscape(Distinct(runs, &Provenance::flags)) << " \\\\\n"
      << "run dates & " << TexEscape(first.empty() ? "unknown" : first + " to " + last) << " \\\\\n"
      << "\\bottomrule\n\\end{tabular}\n\\end{center}\n\n";
  std::set<std::string> revisions;
  for (const RunRecord& r : runs)
    if (r.status == RunStatus::kOk) revisions.insert(r.provenance.git_revision);
  if (revisions.size() > 1)
    out << Paragraph("Note: the runs come from " + std::to_string(revisions.size()) +
                     " code revisions; rerun the spec with --force to measure one.");
  return out.str();
}

std::string RegistryTex() {
  std::ostringstream out;
  out << "\\begin{description}\\small\n";
  for (const AlgorithmInfo& a : Algorithms()) {
    if (a.test_only) continue;
    out << "\\item[" << Tt(a.name) << "] (needs the " << TexEscape(std::string(ToString(a.needs)))
        << " view) " << TexEscape(a.description) << "\n";
  }
  out << "\\end{description}\n\\begin{description}\\small\n";
  for (const ProblemInfo& p : Problems()) {
    std::string views;
    for (View v : p.offers) views += (views.empty() ? "" : ", ") + std::string(ToString(v));
    out << "\\item[" << Tt(p.name) << "] (offers " << TexEscape(views) << ") "
        << TexEscape(p.description) << "\n";
  }
  out << "\\end{description}\n";
  return out.str();
}

std::string Paper000Tex(const std::vector<RunRecord>& runs, const std::vector<ComparisonRow>& rows,
                        const FigureSet& figures) {
  std::ostringstream out;
  const bool has_runs = HasRunOf(runs, IsPaper000Experiment);
  out << "\\subsection{Setup}\n";
  if (!has_runs) {
    out << Paragraph(
        "This store holds no run of paper 000's experiments (table1, window): "
        "icpbench run specs/default.yaml produces them. Its published values "
        "are compared below as far as the store allows.");
  } else {
    out << Paragraph(
        "Table 1 and Figs. 2 to 4 of paper 000 on the simulated car track; the "
        "runs are those of the spec experiments table1 and window "
        "(specs/default.yaml).");
    for (const TextTable& t : Paper000Tables(runs)) out << PagedTable(t);
  }
  out << ClaimsTex("Paper 000: published vs measured", rows);
  if (has_runs) {
    out << "\\subsection{Figures}\n";
    out << FigureTex(figures, "fig2_window",
                     "Fig. 2: mean area (of the newest state, of the window states) and mean "
                     "time per CSP against w, a panel each, on log axes where the values span "
                     "a decade; each point the median over the seeds of each run's mean, its "
                     "error bar the 95 % interval of that median (from six seeds on)");
    out << FigureTex(figures, "fig3_corridors",
                     "Fig. 3: interval error corridors over the lap, a band per algorithm over "
                     "the GPS box (grey)");
    out << FigureTex(figures, "fig4_area",
                     "Fig. 4: x-y area over the lap, log scale; over more than 400 steps the "
                     "running median of a 40th of them");
    out << "\\subsection{Beyond the paper}\n"
        << Paragraph(
               "Two experiments of the default suite ask what the paper does not: a drive "
               "that starts with the heading unknown, and a GPS outage. No published value "
               "compares with them; they show where the propagators differ when the data "
               "stop constraining a variable.");
    for (const TextTable& t : Paper000OwnExperimentTables(runs)) out << PagedTable(t);
  }
  out << "\\subsection{Discussion}\n" << DiscussionTex(rows);
  return out.str();
}

std::string Thesis003Tex(const std::vector<RunRecord>& runs,
                         const std::vector<ComparisonRow>& rows, const FigureSet& figures) {
  std::ostringstream out;
  const bool relaxed = HasRunOf(runs, IsRelaxedExperiment);
  const bool city = HasRunOf(runs, IsCityRoads);
  const bool marina = HasRunOf(runs, IsMarina);
  const std::vector<TextTable> tables = Thesis003Tables(runs);  // relaxed, then marina
  out << "\\subsection{Setup}\n";
  out << "\\subsubsection*{Relaxed solvers: Figs. 5.2 and 5.5 to 5.7}\n";
  if (!relaxed) {
    out << Paragraph(
        "This store holds no run of experiments fig5_2, lines-accumulator, fig5_5, "
        "relaxed-lines or relaxed-beacons: icpbench run specs/default.yaml (a short sweep) or "
        "specs/relaxed.yaml (the whole one) produces them.");
  } else {
    out << PagedTable(tables.at(0));
  }
  out << "\\subsubsection*{The city without GPS: Fig. 4.17}\n";
  if (!city) {
    out << Paragraph(
        "This store holds no run of experiment city-roads: icpbench run specs/default.yaml "
        "produces them.");
  } else {
    out << Paragraph(
        "A car localized from its speed and compass alone (dead reckoning), then with the road "
        "map through the image contractor, by every ICP algorithm (the map as an extra "
        "contractor beside the CSP), the relaxed solver and the particle filter; the runs of "
        "experiment city-roads, whose areas and consistency are in the report's tables.");
  }
  out << "\\subsubsection*{Chapter 6: set membership against the particle filter}\n";
  if (!marina) {
    out << Paragraph(
        "This store holds no run of experiment marina or marina-*: "
        "icpbench run specs/marina.yaml (or specs/default.yaml, experiment "
        "marina-drive) produces them.");
  } else {
    out << PagedTable(tables.at(1));
  }
  out << ClaimsTex("Thesis 003: published vs measured", rows);
  if (relaxed || city || marina) out << "\\subsection{Figures}\n";
  if (relaxed) {
    out << FigureTex(figures, "fig5_2_box_polynomials",
                     "Fig. 5.2: box polynomials of 20 lines, 7 of them outliers, and their "
                     "projections on x");
    out << FigureTex(figures, "fig_lines_accumulator",
                     "The accumulator of the same lines (not a figure of the thesis)");
    out << FigureTex(figures, "fig5_5_robot_a", "Fig. 5.5: robot A alone");
    out << FigureTex(figures, "fig5_6_robot_b", "Fig. 5.6: robot B alone");
    out << FigureTex(figures, "fig5_7_sum", "Fig. 5.7: the sum of both robots");
  }
  if (city)
    out << FigureTex(figures, "fig4_17_city_roads",
                     "Fig. 4.17: dead-reckoning boxes (a) against the boxes on the roads (b)");
  if (marina) {
    out << FigureTex(figures, "fig6_7_dead_reckoning",
                     "Fig. 6.7: dead-reckoning boxes (every 50th step) and their centre against "
                     "the truth, the frame fitted to the track (wider boxes cut at its edges)");
    out << FigureTex(figures, "fig6_8_marina_tracks",
                     "Fig. 6.8: set-membership boxes (every 20th step) and centres against the "
                     "truth, one panel per start (known, the 10,368 m² area, unknown), each "
                     "frame fitted to the track; the guaranteed configuration (auto_q=false), "
                     "which the claims judge");
    out << FigureTex(figures, "fig6_9_particles",
                     "Fig. 6.9: 600 particles over the 10,368 m² prior and the filter's mean "
                     "track");
    out << FigureTex(figures, "fig6_errors",
                     "Centre error over time, both methods in the configurations the claims "
                     "judge (log scale; over more than 400 steps the running median of a 40th "
                     "of them)");
  }
  out << "\\subsection{Discussion}\n" << DiscussionTex(rows);
  return out.str();
}

std::string Paper002Tex(const std::vector<RunRecord>& runs, const std::vector<ComparisonRow>& rows,
                        const FigureSet& figures) {
  std::ostringstream out;
  out << "\\subsection{Setup}\n";
  out << Paragraph(
      "Paper 002's robot drives two paths of 46 acquisitions, one every 30 cm, at the end of a "
      "corridor (indoor-landmarks, paths a and b): wheel odometry with interval wheel radii, "
      "track width and rotations (eq. 5-7), and an omnidirectional sensor returning typed "
      "landmarks (corner, edge, other) as a range and a bearing, some dropped, with spurious "
      "returns near real landmarks. landmark-tracking follows the paper: each track picks its "
      "return by belief functions (Fig. 6 masses, Royère's fusion, the largest pignistic "
      "probability), each match adds eq. 10-11 and is propagated by HC3, and is cancelled when "
      "that empties the box; the returns left start tracks by box inclusion (§3.4). Beside it: "
      "the same with the first consistent return instead of the belief rule, with HC4, "
      "odometry alone (Fig. 9), the q-relaxed intersection (a wrong association is an outlier "
      "to it: each return is the union of the landmarks of its type) and the particle filter.");
  for (const TextTable& t : Paper002Tables(runs)) out << PagedTable(t);
  out << ClaimsTex("Paper 002: published vs measured", rows);
  out << "\\subsection{Figures}\n";
  out << FigureTex(figures, "fig9_odometry",
                   "Fig. 9: the pose boxes of odometry alone on paths a and b, with the truth")
      << FigureTex(figures, "fig11_landmarks",
                   "Fig. 11: the pose boxes of landmark tracking on paths a and b around the truth "
                   "(interval errors in x and y)");
  out << "\\subsection{Discussion}\n" << DiscussionTex(rows);
  return out.str();
}

std::string Paper004Tex(const std::vector<RunRecord>& runs, const std::vector<ComparisonRow>& rows,
                        const FigureSet& figures) {
  std::ostringstream out;
  out << "\\subsection{Setup}\n";
  out << Paragraph(
      "Paper 004 calls a localization consistent at a step when its box holds the reference "
      "(eq. 31: 0 lies in the interval error of eq. 30), and its method consistent when every "
      "step is; the runs' consistency above is that share. Its post-localization (§4.2, Fig. "
      "13) propagates each new observation back through a window of Xi = " +
      std::to_string(kPaper004.post_localization_window) +
      " steps: a state's box once the window has moved past it. icpbench's window estimators "
      "report each window's oldest state, whose last report is that box; the table sets it "
      "beside the real-time box (the newest state's) for every configuration and w of the "
      "window sweep.");
  const std::vector<TextTable> tables = Paper004Tables(runs);
  const TextTable& table = tables.at(0);
  out << PagedTable(table);
  out << "\\subsection{The visual teach and repeat system}\n";
  out << Paragraph(
      "Paper 004's own system on the visual-landmarks problem: a car maps landmarks seen by a "
      "monocular camera as interval cones (eq. 12) from GPS-boxed poses (teach, the straight "
      "route of §5.1), then drives a 183 m loop without GPS on that map (repeat). DIGO solves "
      "the window's graph of ICSPs (eq. 26) by HC4 and keeps every landmark's domain across "
      "windows; LIC, the authors' earlier method, solves each observation's ICSP alone. Every "
      "landmark box and every pose box is checked against the truth on every step.");
  for (std::size_t i = 1; i < tables.size(); ++i) out << PagedTable(tables[i]);
  out << ClaimsTex("Paper 004: published vs measured", rows);
  out << "\\subsection{Figures}\n";
  if (!table.rows.empty())
    out << FigureTex(figures, "fig13_post_localization",
                     "Figs. 12 and 13 on the car track: interval error of the real-time boxes "
                     "(top) and of the post-localized states (bottom)");
  out << FigureTex(figures, "fig8_landmark_boxes",
                   "Fig. 8: the landmarks' x-y boxes shrinking as the car drives (DIGO, Ξ = 10)")
      << FigureTex(figures, "fig9_window",
                   "Fig. 9: DIGO's mean position-box volume and time per step against Ξ")
      << FigureTex(figures, "fig12_13_repeat",
                   "Figs. 12 and 13 in repeat: interval error of the real-time boxes (top) and "
                   "of the post-localized poses (bottom)");
  out << "\\subsection{Discussion}\n" << DiscussionTex(rows);
  return out.str();
}

std::string ProfilesTex(const std::vector<RunRecord>& runs, const FigureSet& figures) {
  std::ostringstream out;
  out << Paragraph(
      "How the algorithm configurations compare across every problem of this store, as "
      "Dolan and Moré's performance profiles show it: for each configuration, the share ρ(τ) of "
      "the problem instances (a problem with its parameters and seed) on which its time per "
      "CSP, or its mean x-y area, is within a factor τ of the best configuration's there. ρ(1) "
      "is how often it is the best; its limit, how many instances it solves.");
  for (const ProfileMetric metric : {ProfileMetric::kTime, ProfileMetric::kArea})
    out << PagedTable(ProfileTable(runs, metric));
  out << FigureTex(figures, "fig_profile_time", "Performance profile of the time per CSP");
  out << FigureTex(figures, "fig_profile_area", "Performance profile of the mean x-y area");
  return out.str();
}

std::string PerformanceTex(const std::vector<RunRecord>& runs, const FigureSet& figures) {
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  std::vector<double> times;
  for (const GroupSummary& g : groups)
    if (g.ok > 0 && g.metrics.steps > 0) times.push_back(g.metrics.time_median_s);
  const Unit unit = TimeUnit(times);
  TextTable t;
  t.title = "Time per step of every configuration";
  t.headers = {"algorithm", "problem", "runs", "steps", "median (" + unit.name + ")",
               "mean (" + unit.name + ") [95% CI]", "mean / HC4 [95% CI]"};
  t.numeric = {false, false, true, true, true, true, true};
  t.omit_if_empty = true;
  for (const GroupSummary& g : groups) {
    if (g.ok == 0 || g.metrics.steps == 0) continue;
    MedianInterval to_hc4;
    for (const GroupSummary& h : groups) {
      if (h.algorithm == "hc4" && h.algorithm_params.empty() && h.ok > 0 &&
          h.problem == g.problem && h.problem_params == g.problem_params)
        to_hc4 = PairedRatio(g, h, RunMeanTime);
    }
    t.rows.push_back({WithParams(DisplayOf(g.algorithm).label, g.algorithm_params),
                      WithParams(g.problem, g.problem_params), OkRunsCell(g),
                      std::to_string(g.metrics.steps),
                      FormatNumber(g.metrics.time_median_s * unit.scale),
                      FormatWithInterval(RunMedian(g, RunMeanTime), unit.scale),
                      FormatWithInterval(to_hc4)});
  }
  t.notes.push_back(
      "Solve time per step (for ICP the contraction of one window alone, building it "
      "excluded), on the machines of the first page. Median: over the steps of each "
      "configuration's ok runs. Mean: each run's mean, then the median over the runs (seeds) "
      "with its 95% confidence interval (order statistics, from 6 runs on), rounded to the "
      "interval's leading digit. Mean / HC4: per seed, the run's mean over HC4's on the same "
      "instance (HC4 at default parameters on the same problem configuration), then their "
      "median and interval (— where there is none).");
  if (t.rows.empty())
    t.notes.push_back("No ok run in the store: icpbench run specs/default.yaml produces them.");
  std::ostringstream out;
  out << PagedTable(t);
  out << FigureTex(figures, "fig_timing", "Solve time per step, per algorithm");
  return out.str();
}

}  // namespace icp
