#include "report/report.h"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "harness/metrics.h"
#include "harness/results_store.h"
#include "harness/spec.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kDash = "—";
constexpr int kMaxProblemLines = 20;  // failure list below table 1
constexpr int kMaxSeedsListed = 8;

bool ParseNumber(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return false;
  *value = v;
  return true;
}

// Numbers compare as numbers ("5" < "20"), anything else as text; a number
// sorts before a text.
bool NaturalLess(const std::string& a, const std::string& b) {
  double x, y;
  const bool xa = ParseNumber(a, &x);
  const bool yb = ParseNumber(b, &y);
  if (xa && yb && x != y) return x < y;
  if (xa != yb) return xa;
  return a < b;
}

bool ParamsLess(const ParamMap& a, const ParamMap& b) {
  auto i = a.begin();
  auto j = b.begin();
  for (; i != a.end() && j != b.end(); ++i, ++j) {
    if (i->first != j->first) return i->first < j->first;
    if (i->second != j->second) return NaturalLess(i->second, j->second);
  }
  return i == a.end() && j != b.end();
}

std::string FormatCsvNumber(double v) {
  if (std::isnan(v)) return "";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Mean of values weighted by weights, skipping NaN values; NaN when no weight.
double WeightedMean(const std::vector<std::pair<double, double>>& value_weight) {
  double sum = 0, total = 0;
  for (const auto& [v, w] : value_weight) {
    if (std::isnan(v) || !(w > 0)) continue;
    sum += v * w;
    total += w;
  }
  return total > 0 ? sum / total : kNaN;
}

RunMetrics NaNMetrics() {
  RunMetrics m;
  m.mean_area = m.consistency_rate = m.centre_rmse = kNaN;
  m.time_mean_s = m.time_median_s = m.time_p90_s = kNaN;
  m.time_mean_ci_lo_s = m.time_mean_ci_hi_s = kNaN;
  return m;
}

// Combines stored run metrics when steps are not at hand (see report.h).
RunMetrics CombineRunMetrics(const std::vector<const RunRecord*>& runs) {
  if (runs.size() == 1) return runs[0]->metrics;
  RunMetrics m = NaNMetrics();
  std::vector<std::pair<double, double>> area, rate, square, time;
  for (const RunRecord* r : runs) {
    const double w = r->metrics.steps;
    m.steps += r->metrics.steps;
    area.emplace_back(r->metrics.mean_area, w);
    rate.emplace_back(r->metrics.consistency_rate, w);
    square.emplace_back(r->metrics.centre_rmse * r->metrics.centre_rmse, w);
    time.emplace_back(r->metrics.time_mean_s, w);
  }
  m.mean_area = WeightedMean(area);
  m.consistency_rate = WeightedMean(rate);
  m.centre_rmse = std::sqrt(WeightedMean(square));
  m.time_mean_s = WeightedMean(time);
  return m;
}

std::string SeedList(std::vector<std::uint64_t> seeds) {
  std::sort(seeds.begin(), seeds.end());
  std::string out = seeds.size() == 1 ? "seed " : "seeds ";
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (i == kMaxSeedsListed) {
      out += ", … (" + std::to_string(seeds.size()) + " runs)";
      break;
    }
    if (i > 0) out += ", ";
    out += std::to_string(seeds[i]);
  }
  return out;
}

std::string OneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return text;
}

std::string RunsCell(const GroupSummary& g) {
  if (g.failed == 0 && g.timeout == 0 && g.skipped == 0) return std::to_string(g.ok);
  std::string out = std::to_string(g.ok) + " ok";
  for (const auto& [count, name] : {std::pair<int, const char*>{g.failed, "failed"},
                                    {g.timeout, "timeout"},
                                    {g.skipped, "skipped"}}) {
    if (count > 0) out += ", " + std::to_string(count) + " " + name;
  }
  return out;
}

std::string Micro(double seconds) { return FormatNumber(seconds * 1e6); }

std::string MeanWithInterval(double mean, double lo, double hi, double scale) {
  std::string out = FormatNumber(mean * scale);
  if (!std::isnan(lo) && !std::isnan(hi)) {
    out += " [" + FormatNumber(lo * scale) + ", " + FormatNumber(hi * scale) + "]";
  }
  return out;
}

// The runs-per-configuration table and its failure list.
TextTable GroupTable(const std::vector<GroupSummary>& groups) {
  TextTable t;
  t.title = "Runs per configuration (aggregated over seeds)";
  t.headers = {"algorithm", "params",       "problem",          "params",
               "runs",      "CSPs",         "mean area (m²)",   "consistency",
               "centre RMSE (m)", "time median (µs)", "time p90 (µs)",
               "time mean (µs) [95% CI]"};
  t.numeric = {false, false, false, false, true, true, true, true, true, true, true, true};
  int listed = 0, unlisted = 0;
  for (const GroupSummary& g : groups) {
    const RunMetrics& m = g.metrics;
    t.rows.push_back({g.algorithm, ParamsCell(g.algorithm_params), g.problem,
                      ParamsCell(g.problem_params), RunsCell(g), std::to_string(m.steps),
                      FormatNumber(m.mean_area), FormatNumber(m.consistency_rate),
                      FormatNumber(m.centre_rmse), Micro(m.time_median_s), Micro(m.time_p90_s),
                      MeanWithInterval(m.time_mean_s, m.time_mean_ci_lo_s, m.time_mean_ci_hi_s,
                                       1e6)});
    for (const std::string& p : g.problems) {
      if (listed == kMaxProblemLines) {
        ++unlisted;
        continue;
      }
      ++listed;
      t.items.push_back(ProblemItem(g, p));
    }
  }
  if (unlisted > 0) t.items.push_back("… and " + std::to_string(unlisted) + " more");
  t.notes.push_back(
      "Metrics over the CSPs of the ok runs, pooled across seeds; consistency: share of CSPs "
      "whose box holds the truth (paper 004 eq. 31); times per CSP, 95% CI by bootstrap of "
      "the mean.");
  if (std::any_of(groups.begin(), groups.end(), [](const GroupSummary& g) { return !g.pooled; })) {
    t.notes.push_back(
        "Groups whose runs have no step records combine the stored run metrics; their median, "
        "p90 and CI are shown only for a single run.");
  }
  if (!t.items.empty()) t.notes.push_back("Runs that did not finish ok:");
  return t;
}

std::string MarkdownCell(const std::string& cell) {
  std::string out;
  for (char c : OneLine(cell)) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

void WriteMarkdown(const TextTable& t, std::ostream& out) {
  out << "## " << t.title << "\n\n";
  if (!t.rows.empty() || !t.omit_if_empty) {
    out << "|";
    for (const std::string& h : t.headers) out << " " << MarkdownCell(h) << " |";
    out << "\n|";
    for (bool n : t.numeric) out << (n ? " ---: |" : " :--- |");
    out << "\n";
    for (const auto& row : t.rows) {
      out << "|";
      for (const std::string& c : row) out << " " << MarkdownCell(c) << " |";
      out << "\n";
    }
    out << "\n";
  }
  for (const std::string& n : t.notes) out << n << "\n\n";
  for (const std::string& i : t.items) out << "- " << OneLine(i) << "\n";
  if (!t.items.empty()) out << "\n";
}

}  // namespace

std::string TexEscape(const std::string& text) {
  static const std::vector<std::pair<std::string, std::string>> kMap = {
      {"\\", "\\textbackslash{}"}, {"_", "\\_"}, {"&", "\\&"}, {"%", "\\%"}, {"#", "\\#"},
      {"{", "\\{"}, {"}", "\\}"}, {"$", "\\$"}, {"~", "\\textasciitilde{}"},
      {"^", "\\textasciicircum{}"}, {"—", "---"}, {"µ", "$\\mu$"}, {"²", "$^2$"},
      {"×", "$\\times$"}, {"∞", "$\\infty$"}, {"…", "\\ldots{}"}, {"≤", "$\\leq$"},
      {"≥", "$\\geq$"}, {"§", "\\S{}"}, {"−", "$-$"}, {"±", "$\\pm$"}, {"≈", "$\\approx$"},
      {"π", "$\\pi$"}, {"Ξ", "$\\Xi$"}, {"ψ", "$\\psi$"}, {"θ", "$\\theta$"},
      {"ε", "$\\varepsilon$"}, {"·", "$\\cdot$"}, {"–", "--"},
      {"<", "$<$"}, {">", "$>$"}, {"|", "\\textbar{}"}};
  std::string out;
  const std::string line = OneLine(text);
  for (std::size_t i = 0; i < line.size();) {
    bool matched = false;
    for (const auto& [from, to] : kMap) {
      if (line.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        matched = true;
        break;
      }
    }
    if (!matched) out += line[i++];
  }
  return out;
}

std::string TexTable(const TextTable& t) {
  std::ostringstream out;
  out << "% " << OneLine(t.title) << "\n";
  if (!t.rows.empty() || !t.omit_if_empty) {
    out << "\\begin{table}[htbp]\n\\centering\n\\small\n\\caption{" << TexEscape(t.title)
        << "}\n"
        // Shrunk to the line width when wider, never enlarged.
        << "\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!}{%\n"
        << "\\begin{tabular}{";
    for (bool n : t.numeric) out << (n ? 'r' : 'l');
    out << "}\n\\toprule\n";
    for (std::size_t i = 0; i < t.headers.size(); ++i) {
      out << (i ? " & " : "") << TexEscape(t.headers[i]);
    }
    out << " \\\\\n\\midrule\n";
    for (const auto& row : t.rows) {
      for (std::size_t i = 0; i < row.size(); ++i) out << (i ? " & " : "") << TexEscape(row[i]);
      out << " \\\\\n";
    }
    out << "\\bottomrule\n\\end{tabular}}\n\\end{table}\n\n";
  }
  for (const std::string& n : t.notes) out << TexEscape(n) << "\n\n";
  if (!t.items.empty()) {
    out << "\\begin{itemize}\n";
    for (const std::string& i : t.items) out << "\\item " << TexEscape(i) << "\n";
    out << "\\end{itemize}\n\n";
  }
  return out.str();
}

namespace {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string GroupCsv(const std::vector<GroupSummary>& groups) {
  std::ostringstream out;
  out << "algorithm,algorithm_params,problem,problem_params,runs_ok,runs_failed,runs_timeout,"
         "runs_skipped,steps,mean_area_m2,consistency_rate,centre_rmse_m,time_median_us,"
         "time_p90_us,time_mean_us,time_mean_ci_lo_us,time_mean_ci_hi_us\n";
  for (const GroupSummary& g : groups) {
    const RunMetrics& m = g.metrics;
    const std::vector<std::string> fields = {
        g.algorithm, CompactParams(g.algorithm_params), g.problem, CompactParams(g.problem_params),
        std::to_string(g.ok), std::to_string(g.failed), std::to_string(g.timeout),
        std::to_string(g.skipped), std::to_string(m.steps), FormatCsvNumber(m.mean_area),
        FormatCsvNumber(m.consistency_rate), FormatCsvNumber(m.centre_rmse),
        FormatCsvNumber(m.time_median_s * 1e6), FormatCsvNumber(m.time_p90_s * 1e6),
        FormatCsvNumber(m.time_mean_s * 1e6), FormatCsvNumber(m.time_mean_ci_lo_s * 1e6),
        FormatCsvNumber(m.time_mean_ci_hi_s * 1e6)};
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << CsvField(fields[i]);
    out << "\n";
  }
  return out.str();
}

// Distinct values of one provenance field over the runs, for the header.
std::string Distinct(const std::vector<RunRecord>& runs, std::string Provenance::*field) {
  std::set<std::string> values;
  for (const RunRecord& r : runs) {
    if (!(r.provenance.*field).empty()) values.insert(r.provenance.*field);
  }
  std::string out;
  for (const std::string& v : values) out += (out.empty() ? "" : "; ") + v;
  return out.empty() ? "unknown" : out;
}

}  // namespace

bool RecordedRunsOnly(const RunRecord& run) {
  return run.status == RunStatus::kOk && run.steps.empty() && run.metrics.steps > 0;
}

namespace {

std::string Overview(const std::vector<RunRecord>& runs) {
  int counts[4] = {0, 0, 0, 0};
  for (const RunRecord& r : runs) ++counts[static_cast<int>(r.status)];
  std::ostringstream out;
  out << runs.size() << " runs: " << counts[0] << " ok, " << counts[1] << " failed, "
      << counts[2] << " timeout, " << counts[3] << " skipped. Machines: "
      << Distinct(runs, &Provenance::machine)
      << ". Revisions: " << Distinct(runs, &Provenance::git_revision) << ".";
  std::set<std::string> revisions;
  for (const RunRecord& r : runs)
    if (r.status == RunStatus::kOk) revisions.insert(r.provenance.git_revision);
  if (revisions.size() > 1)
    out << " Note: the tables mix runs of " << revisions.size()
        << " code revisions; rerun with --force to measure one.";
  const auto runs_only = std::count_if(runs.begin(), runs.end(), RecordedRunsOnly);
  if (runs_only > 0)
    out << " Note: " << runs_only << (runs_only == 1 ? " ok run was" : " ok runs were")
        << " recorded with `record: runs` (run metrics only, no step rows): the runs per "
           "configuration table combines their stored metrics (median, p90 and CI only for a "
           "single run); tables over steps leave them out (rerun with record: steps to include "
           "them).";
  return out.str();
}

}  // namespace

std::string OkRunsCell(const GroupSummary& group) {
  std::string cell = std::to_string(group.ok);
  if (group.runs.size() != static_cast<std::size_t>(group.ok))
    cell += " of " + std::to_string(group.runs.size());
  return cell;
}

std::string ProblemItem(const GroupSummary& group, const std::string& problem) {
  return WithParams(group.algorithm, group.algorithm_params) + " on " +
         WithParams(group.problem, group.problem_params) + ": " + problem;
}

std::string FormatNumber(double v) {
  if (std::isnan(v)) return kDash;
  if (std::isinf(v)) return v > 0 ? "∞" : "-∞";
  if (v == 0) return "0";
  const double a = std::fabs(v);
  char buf[64];
  if (a >= 1e9 || a < 1e-3) {
    std::snprintf(buf, sizeof buf, "%.3e", v);
    return buf;
  }
  if (a >= 1e4) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  const int magnitude = static_cast<int>(std::floor(std::log10(a)));
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, 3 - magnitude), v);
  std::string out = buf;
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  return out;
}

std::string WithParams(const std::string& name, const ParamMap& params) {
  return params.empty() ? name : name + " {" + CompactParams(params) + "}";
}

std::string ParamsCell(const ParamMap& params) {
  return params.empty() ? "default" : CompactParams(params);
}

std::string FormatRatio(double a, double b) {
  if (std::isnan(a) || std::isnan(b) || b == 0) return kDash;
  return FormatNumber(a / b);
}

std::string ExperimentOf(const RunRecord& run) {
  const std::size_t hash = run.spec_file.rfind('#');
  return hash == std::string::npos ? "" : run.spec_file.substr(hash + 1);
}

bool HasExperiment(const GroupSummary& group, const std::string& experiment) {
  return std::any_of(group.runs.begin(), group.runs.end(),
                     [&](const RunRecord* r) { return ExperimentOf(*r) == experiment; });
}

std::string CompactParams(const ParamMap& params) {
  std::string out;
  for (const auto& [k, v] : params) out += (out.empty() ? "" : ",") + k + "=" + v;
  return out;
}

Display DisplayOf(const std::string& algorithm) {
  for (const AlgorithmInfo& a : Algorithms())
    if (a.name == algorithm) return a.display;
  return {algorithm, 1000, "#7f7f7f"};
}

bool AlgorithmLess(const std::string& a, const std::string& b) {
  const int oa = DisplayOf(a).order, ob = DisplayOf(b).order;
  return oa != ob ? oa < ob : a < b;
}

GroupSummary Summarise(const std::vector<const RunRecord*>& runs) {
  GroupSummary g;
  if (!runs.empty()) {
    g.algorithm = runs[0]->spec.algorithm;
    g.algorithm_params = runs[0]->spec.algorithm_params;
    g.problem = runs[0]->spec.problem;
    g.problem_params = runs[0]->spec.problem_params;
  }
  std::map<std::pair<RunStatus, std::string>, std::vector<std::uint64_t>> problems;
  bool all_have_steps = true;
  g.runs = runs;
  for (const RunRecord* r : runs) {
    switch (r->status) {
      case RunStatus::kOk:
        ++g.ok;
        g.ok_runs.push_back(r);
        if (r->steps.empty() && r->metrics.steps > 0) all_have_steps = false;
        continue;
      case RunStatus::kFailed:
        ++g.failed;
        break;
      case RunStatus::kTimeout:
        ++g.timeout;
        break;
      case RunStatus::kSkipped:
        ++g.skipped;
        break;
    }
    problems[{r->status, OneLine(r->reason)}].push_back(r->spec.seed);
  }
  for (const auto& [what, seeds] : problems) {
    std::string line = std::string(ToString(what.first)) + " (" + SeedList(seeds) + ")";
    if (!what.second.empty()) line += ": " + what.second;
    g.problems.push_back(line);
  }
  if (g.ok_runs.empty()) {
    g.metrics = NaNMetrics();
  } else if (all_have_steps) {
    std::vector<StepRecord> pooled;
    for (const RunRecord* r : g.ok_runs) pooled.insert(pooled.end(), r->steps.begin(), r->steps.end());
    g.metrics = ComputeMetrics(pooled);
  } else {
    g.pooled = false;
    g.metrics = CombineRunMetrics(g.ok_runs);
  }
  return g;
}

std::vector<GroupSummary> SummariseGroups(const std::vector<RunRecord>& runs) {
  using Key = std::tuple<std::string, ParamMap, std::string, ParamMap>;
  std::map<Key, std::vector<const RunRecord*>> by_key;
  for (const RunRecord& r : runs) {
    by_key[{r.spec.algorithm, r.spec.algorithm_params, r.spec.problem, r.spec.problem_params}]
        .push_back(&r);
  }
  std::vector<GroupSummary> groups;
  for (const auto& [key, members] : by_key) groups.push_back(Summarise(members));
  std::sort(groups.begin(), groups.end(), [](const GroupSummary& a, const GroupSummary& b) {
    if (a.problem != b.problem) return a.problem < b.problem;
    if (a.problem_params != b.problem_params) return ParamsLess(a.problem_params, b.problem_params);
    if (a.algorithm != b.algorithm) return AlgorithmLess(a.algorithm, b.algorithm);
    return ParamsLess(a.algorithm_params, b.algorithm_params);
  });
  return groups;
}

std::vector<SweepPoint> ParamSweep(const std::vector<RunRecord>& runs, const std::string& problem,
                                   const std::string& param) {
  const ParamMap defaults = ProblemDefaults(problem);
  const auto default_value = defaults.find(param);
  // configuration (algorithm, its params, problem params but param) -> value -> runs
  using Config = std::tuple<std::string, ParamMap, ParamMap>;
  std::map<Config, std::map<double, std::vector<const RunRecord*>>> configs;
  for (const RunRecord& r : runs) {
    if (r.spec.problem != problem || r.status != RunStatus::kOk) continue;
    const auto given = r.spec.problem_params.find(param);
    const std::string* text = given != r.spec.problem_params.end() ? &given->second
                              : default_value != defaults.end()    ? &default_value->second
                                                                   : nullptr;
    double value;
    if (!text || !ParseNumber(*text, &value)) continue;
    ParamMap others = r.spec.problem_params;
    others.erase(param);
    configs[{r.spec.algorithm, r.spec.algorithm_params, others}][value].push_back(&r);
  }
  std::vector<SweepPoint> points;
  for (const auto& [config, by_value] : configs) {
    if (by_value.size() < 2) continue;
    const auto& [algorithm, algorithm_params, others] = config;
    std::string label = WithParams(algorithm, algorithm_params);
    if (!others.empty()) label += " [" + CompactParams(others) + "]";
    for (const auto& [value, members] : by_value) {
      const GroupSummary g = Summarise(members);
      std::vector<double> window_areas;
      for (const RunRecord* r : members) {
        for (const StepRecord& s : r->steps) {
          if (auto a = NumberProperty(s.properties, "window_mean_area")) window_areas.push_back(*a);
        }
      }
      points.push_back({label, algorithm, value, g.ok, g.metrics.steps, g.metrics.mean_area,
                        g.metrics.time_mean_s, Mean(window_areas), members});
    }
  }
  std::stable_sort(points.begin(), points.end(), [](const SweepPoint& a, const SweepPoint& b) {
    if (a.algorithm != b.algorithm) return AlgorithmLess(a.algorithm, b.algorithm);
    if (a.label != b.label) return a.label < b.label;
    return a.value < b.value;
  });
  return points;
}

std::string Report(const std::vector<RunRecord>& runs, const std::string& format,
                   const TableMaker& more) {
  if (format != "md" && format != "tex" && format != "csv") {
    throw std::invalid_argument("report format '" + format + "': must be one of md|tex|csv");
  }
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  if (format == "csv") return GroupCsv(groups);

  std::vector<TextTable> tables = {GroupTable(groups)};
  if (more) {
    for (TextTable& t : more(runs)) tables.push_back(std::move(t));
  }
  std::ostringstream out;
  if (format == "md") {
    out << "# icpbench report\n\n" << Overview(runs) << "\n\n";
    for (const TextTable& t : tables) WriteMarkdown(t, out);
  } else {
    out << "% icpbench report; needs \\usepackage{booktabs,graphicx}\n% " << OneLine(Overview(runs))
        << "\n\n";
    for (const TextTable& t : tables) out << TexTable(t);
  }
  return out.str();
}

std::vector<RunRecord> LoadRunsFromDirectory(const std::string& dir) {
  const std::string path = StorePath(dir);
  if (!std::filesystem::is_regular_file(path)) {
    throw std::runtime_error("no results store in '" + dir + "' (expected " + path + ")");
  }
  // Read-only: archived or another user's stores must be reportable.
  std::vector<RunRecord> runs = ResultsStore::OpenReadOnly(path)->LoadRuns(/*with_steps=*/true);
  for (RunRecord& r : runs) r.spec = WithoutDefaults(r.spec);
  return runs;
}

std::string ReportDirectory(const std::string& dir, const std::string& format,
                            const TableMaker& more) {
  if (format != "md" && format != "tex" && format != "csv") {
    throw std::invalid_argument("report format '" + format + "': must be one of md|tex|csv");
  }
  return Report(LoadRunsFromDirectory(dir), format, more);
}

}  // namespace icp
