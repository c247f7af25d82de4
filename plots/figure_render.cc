// The gnuplot machinery the figures share: quoting, drawing a figure's
// panels to PNG and PDF in one session, and the skip messages.
#include <gnuplot-iostream.h>
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <set>
#include <sstream>
#include <utility>

#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp::detail::plots {

namespace {

// PNG size from the PDF size in inches; its fonts and lines scaled so that
// it looks as the PDF does (cairo's PNG takes a point for a pixel).
constexpr double kPixelsPerInch = 150;
constexpr double kPngScale = kPixelsPerInch / 72;
// Cairo takes a font point at 96 dpi (and pdfcairo scales fonts by 0.5
// unless told): fontscale 0.75 prints a font of kFontPt at kFontPt, in the
// PDF and in the PNG alike (measured with pdftotext -bbox).
constexpr double kCairoFontScale = 0.75;

enum class Terminal { kPng, kPdf };

bool GnuplotAvailable() {
  static const bool available = std::system("gnuplot --version >/dev/null 2>&1") == 0;
  return available;
}

// The shared terminal setup: cairo PNG or PDF of the figure's size, UTF-8,
// output to path.
void SetTerminal(Gnuplot& gp, Terminal terminal, const Figure& f, const std::string& path) {
  gp << "set encoding utf8\n";
  if (terminal == Terminal::kPng) {
    gp << "set terminal pngcairo enhanced size " << static_cast<int>(f.width_in * kPixelsPerInch)
       << "," << static_cast<int>(f.height_in * kPixelsPerInch) << " font 'Sans,"
       << std::lround(kFontPt * kPngScale) << "' fontscale " << kCairoFontScale << " linewidth "
       << kPngScale / 2 << "\n";
  } else {
    gp << "set terminal pdfcairo enhanced size " << f.width_in << "in," << f.height_in
       << "in font 'Sans," << kFontPt << "' fontscale " << kCairoFontScale << "\n";
  }
  gp << "set output " << Quote(path) << "\n";
}

// A figure's title is centred on the whole figure, wider than a panel's
// plot, which Wrapped assumes.
constexpr double kTitleWidth = 8.0 / 7.0;

// Where panel i of a figure placed by hand goes: "set origin ..., set
// size ..." in screen fractions, rows from the top below the title, the
// footer strip left free.
std::string Placement(const Figure& f, std::size_t i) {
  const std::string wrapped = Wrapped(f.title, kTitleWidth * f.width_in);
  const int lines =
      f.title.empty() ? 0 : 1 + static_cast<int>(std::count(wrapped.begin(), wrapped.end(), '\n'));
  const double title = lines * 0.2 / f.height_in, footer = f.footer_in / f.height_in;
  const double avail = std::max(0.1, 1 - title - footer);
  std::vector<double> w = f.row_weights;
  w.resize(static_cast<std::size_t>(f.rows), 1.0);
  double total = 0;
  for (double x : w) total += x;
  const std::size_t row = i / static_cast<std::size_t>(f.cols), col = i % f.cols;
  double above = 0;
  for (std::size_t r = 0; r < row; ++r) above += w[r];
  const double h = w[row] / total * avail;
  const double y = 1 - title - above / total * avail - h;
  std::ostringstream out;
  out << "set origin " << static_cast<double>(col) / f.cols << "," << y << "\nset size "
      << 1.0 / f.cols << "," << h << "\n";
  return out.str();
}

void DrawPanel(Gnuplot& gp, const Panel& panel, const std::string& placement) {
  gp << "reset\nset encoding utf8\nset grid\n" << placement << panel.setup << "\n";
  std::vector<const Series*> drawn;
  for (const Series& s : panel.series) {
    if (HasPoint(s)) drawn.push_back(&s);
  }
  if (drawn.empty()) {  // keep the multiplot's place
    gp << "unset key\nset xrange [0:1]\nset yrange [0:1]\n"
          "set label 99 'no data' at graph 0.5, graph 0.5 center\nplot 2 notitle\n";
    return;
  }
  gp << "plot ";
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    gp << (i ? ", " : "") << (drawn[i]->function.empty() ? "'-'" : drawn[i]->function) << " "
       << drawn[i]->spec;
  }
  gp << "\n";
  for (const Series* s : drawn) {
    if (s->function.empty()) gp.send1d(s->rows);
  }
}

}  // namespace

std::string Colour(const std::string& algorithm) { return DisplayOf(algorithm).colour; }

std::string Wrapped(const std::string& text, double width_in) {
  // A character of the sans font is at most about 0.7 of its size wide
  // (measured on the rendered titles); a panel's title is centred on its
  // plot, narrower than the panel: 0.8.
  const std::size_t per_line = static_cast<std::size_t>(width_in * 72 / (0.8 * kFontPt));
  std::string out;
  std::istringstream paragraphs(text);
  for (std::string paragraph; std::getline(paragraphs, paragraph);) {
    std::string line;
    std::istringstream words(paragraph);
    for (std::string word; words >> word;) {
      if (!line.empty() && line.size() + 1 + word.size() > per_line) {
        out += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    out += line + "\n";
  }
  if (!out.empty()) out.pop_back();
  return out;
}

double FooterHeight(const std::vector<std::string>& titles) {
  std::size_t longest = 0;
  for (const std::string& t : titles) longest = std::max(longest, t.size());
  const std::size_t rows = longest > 28 ? titles.size() : (titles.size() + 1) / 2;
  return 0.1 + 0.16 * static_cast<double>(rows);
}

std::string TicsFor(const std::string& axis, double lo, double hi, int max_tics) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo) || max_tics < 2) return "";
  const double raw = (hi - lo) / (max_tics - 1);
  const double decade = std::pow(10, std::floor(std::log10(raw)));
  double step = decade;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    step = m * decade;
    if (step >= raw) break;
  }
  std::ostringstream out;
  out << "set " << axis << "tics " << step << "\n";
  return out.str();
}

std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') out += '\'';
    if (c != '\n') out += c;
  }
  return out + "'";
}

std::string MultiLine(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

double Finite(double v) { return std::isfinite(v) ? v : kNaN; }
double Positive(double v) { return std::isfinite(v) && v > 0 ? v : kNaN; }

bool HasPoint(const Series& s) {
  if (!s.function.empty()) return true;
  for (const auto& row : s.rows) {
    if (!row.empty() &&
        std::all_of(row.begin(), row.end(), [](double v) { return !std::isnan(v); }))
      return true;
  }
  return false;
}

void Render(const Figure& f, const std::string& out_dir, PlotOutput* out) {
  if (!GnuplotAvailable()) {
    out->messages.push_back(f.name + ": skipped: gnuplot not found");
    return;
  }
  const std::vector<std::pair<Terminal, std::string>> outputs = {
      {Terminal::kPng, (std::filesystem::path(out_dir) / (f.name + ".png")).string()},
      {Terminal::kPdf, (std::filesystem::path(out_dir) / (f.name + ".pdf")).string()}};
  for (const auto& [terminal, path] : outputs) std::filesystem::remove(path);
  // gnuplot reads on after an error, but should it die, a write must fail
  // rather than kill the process.
  struct sigaction ignore = {}, previous = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &previous);
  {
    // gnuplot writes to its stdout what it cannot write to a file: not ours.
    Gnuplot gp("gnuplot > /dev/null");
    for (const auto& [terminal, path] : outputs) {
      SetTerminal(gp, terminal, f, path);
      const bool by_hand = !f.row_weights.empty() || f.footer_in > 0;
      const bool multiplot = f.panels.size() > 1 || by_hand;
      if (multiplot) {
        gp << "set multiplot";
        if (!by_hand) gp << " layout " << f.rows << "," << f.cols;
        if (!f.title.empty())
          gp << " title " << MultiLine(Wrapped(f.title, kTitleWidth * f.width_in)) << " noenhanced";
        gp << "\n";
      }
      for (std::size_t i = 0; i < f.panels.size(); ++i)
        DrawPanel(gp, f.panels[i], by_hand ? Placement(f, i) : "");
      if (multiplot) gp << "unset multiplot\n";
      gp << "unset output\n";
    }
  }  // closing the pipe waits for gnuplot to finish
  sigaction(SIGPIPE, &previous, nullptr);
  for (const auto& [terminal, path] : outputs) {
    std::error_code ec;
    if (std::filesystem::file_size(path, ec) > 0 && !ec) {
      out->files.push_back(path);
    } else {
      out->messages.push_back(path + ": gnuplot wrote nothing (see its messages above)");
    }
  }
}

void RenderPanel(const std::string& name, double width_in, double height_in, const Panel& panel,
                 const std::string& out_dir, PlotOutput* out) {
  Figure f;
  f.name = name;
  f.width_in = width_in;
  f.height_in = height_in;
  f.panels = {panel};
  Render(f, out_dir, out);
}

int CountRunsOnly(const std::vector<const RunRecord*>& runs) {
  return static_cast<int>(RunsOnlyOf(runs).size());
}

std::vector<const RunRecord*> RunsOnlyOf(const std::vector<const RunRecord*>& runs) {
  std::vector<const RunRecord*> out;
  std::copy_if(runs.begin(), runs.end(), std::back_inserter(out),
               [](const RunRecord* r) { return RecordedRunsOnly(*r); });
  return out;
}

std::string RunCount(std::size_t n) { return std::to_string(n) + (n == 1 ? " run" : " runs"); }

std::string RecordedWithRunsOnly(const std::vector<const RunRecord*>& runs) {
  std::set<std::string> experiments;
  for (const RunRecord* r : runs)
    if (!ExperimentOf(*r).empty()) experiments.insert(ExperimentOf(*r));
  std::string which;
  for (const std::string& e : experiments) which += (which.empty() ? "" : ", ") + e;
  if (!which.empty())
    which = (experiments.size() == 1 ? "experiment " : "experiments ") + which + "; ";
  return "recorded with `record: runs` (" + which +
         "run metrics only, no step rows; rerun with record: steps to draw them)";
}

std::string RunsOnlyText(int n) {
  return RunCount(n) + (n == 1 ? " was " : " were ") + RecordedWithRunsOnly({});
}

bool SkippedForOneStep(const FigureText& text, const std::vector<std::vector<std::vector<double>>>& rows,
                       PlotOutput* out) {
  const auto two_points = [](const std::vector<std::vector<double>>& r) {
    return std::count_if(r.begin(), r.end(), [](const std::vector<double>& row) {
             return HasPoint({"", {row}, ""});
           }) >= 2;
  };
  if (std::any_of(rows.begin(), rows.end(), two_points)) return false;
  out->messages.push_back(text.name +
                          ": skipped: no run it draws has two steps with values (a line over "
                          "the steps cannot show one)");
  return true;
}

void Skip(const FigureText& text, PlotOutput* out, const std::vector<const RunRecord*>& runs) {
  const std::vector<const RunRecord*> runs_only = RunsOnlyOf(runs);
  if (runs_only.empty()) {
    out->messages.push_back(text.name + ": skipped: " + text.skip_reason);
    return;
  }
  const std::size_t n = runs_only.size();
  out->messages.push_back(text.name + ": skipped: it needs step rows, and " + RunCount(n) +
                          (n == 1 ? " was " : " were ") + RecordedWithRunsOnly(runs_only));
}

void NoteRunsOnly(const FigureText& text, const std::vector<const RunRecord*>& runs,
                  PlotOutput* out) {
  const std::vector<const RunRecord*> runs_only = RunsOnlyOf(runs);
  if (!runs_only.empty())
    out->messages.push_back(text.name + ": drawn without " + RunCount(runs_only.size()) + " " +
                            RecordedWithRunsOnly(runs_only));
}

}  // namespace icp::detail::plots

namespace icp {

void SkipFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                PlotOutput* out) {
  detail::plots::Skip(text, out, runs);
}

}  // namespace icp
