// The paper of a results store (`icpbench paper DIR`): a LaTeX document,
// paper/template/icpbench.tex, whose every number, table and figure is
// generated from the store by this library, compiled by latexmk into
// DIR/paper/icpbench.pdf. It holds, after the store's provenance (its code
// revisions and machines, on the first page):
//
//   an abstract stating the tally of verdicts ("Verdicts: N match, N
//   differ, N no data", counted from the comparison rows);
//   the algorithms and problems, with the papers cited;
//   for each seed paper (000, thesis 003, 004): its setup with the tables
//   `report` makes for it (experiments/), its claims (a published-vs-measured
//   table, paper/comparison.h, whose verdicts rules in code decide), its
//   figures as `plot` draws them, and a discussion of each difference;
//   the performance profiles of every algorithm configuration over every
//   problem instance (report/performance_profile.h), time and area;
//   limitations (simulated data, the machine, what is not reproduced);
//   a conclusion with the tally, overall and per paper;
//   an appendix: the registries' algorithms and problems, and the time per
//   step of every configuration.
//
// A section whose runs the store lacks says which spec produces them; a
// figure that cannot be drawn says why (gnuplot missing, no runs).
#ifndef ICPBENCH_PAPER_PAPER_H_
#define ICPBENCH_PAPER_PAPER_H_

#include <string>
#include <utility>
#include <vector>

#include "harness/run_record.h"

namespace icp {

// The generated LaTeX: the main file and the fragments it \input{}s, as
// (path relative to the paper's directory, text).
struct PaperSources {
  std::vector<std::pair<std::string, std::string>> files;
};
// figures_dir holds the figures drawn (NAME.pdf); skipped lists the plots'
// messages ("fig2_window: skipped: ..."), quoted where a figure is missing.
PaperSources GeneratePaper(const std::vector<RunRecord>& runs, const std::string& store_path,
                           const std::string& figures_dir, const std::vector<std::string>& skipped);

struct PaperOutput {
  std::string pdf;                    // DIR/paper/icpbench.pdf
  std::vector<std::string> messages;  // figures skipped
};
// Loads the store in dir, draws the figures into DIR/paper/figures, writes
// the sources into DIR/paper and compiles them. Throws std::runtime_error
// when dir holds no store (LoadRunsFromDirectory), EnvironmentError when
// latexmk, pdflatex or a LaTeX package is missing or DIR/paper cannot be
// written (its advice ends with PaperElsewhere), std::logic_error when
// LaTeX fails on the generated text (a bug; the message names the log).
PaperOutput BuildPaper(const std::string& dir);

// How to get the paper of the store in dir when dir cannot be written
// (paper has no --out: it writes DIR/paper).
std::string PaperElsewhere(const std::string& dir);

}  // namespace icp

#endif  // ICPBENCH_PAPER_PAPER_H_
