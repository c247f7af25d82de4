// The paper of a results store (`icpbench paper DIR`): a LaTeX document,
// paper/template/icpbench.tex, whose every number, table and figure is
// generated from the store by this library, compiled by latexmk into
// DIR/paper/icpbench.pdf. It holds, after the store's provenance (its code
// revisions and machines, on the first page):
//
//   the algorithms and problems (from the registries), with the papers cited;
//   for each seed paper (000, thesis 003, 004) its tables and figures as
//   `report` and `plot` make them (experiments/) and a published-vs-measured
//   table (paper/comparison.h) whose verdicts are decided by rules in code;
//   the performance comparison: time per step of every configuration.
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
