#include "paper/paper.h"

#include <filesystem>
#include <fstream>

#include "experiments/registry.h"
#include "harness/environment_error.h"
#include "harness/output_directory.h"
#include "harness/results_store.h"
#include "paper/latex.h"
#include "paper/sections.h"
#include "paper/template.h"
#include "plots/figures.h"
#include "report/report.h"

namespace icp {

namespace {

constexpr char kName[] = "icpbench";

void WriteText(const std::string& path, const std::string& text, const std::string& elsewhere) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) ThrowErrno("cannot write " + path, errno, elsewhere);
}

}  // namespace

PaperSources GeneratePaper(const std::vector<RunRecord>& runs, const std::string& store_path,
                           const std::string& figures_dir,
                           const std::vector<std::string>& skipped) {
  const FigureSet figures{figures_dir, skipped};
  const PaperComparisons rows = ComparePapers(runs);
  PaperSources s;
  s.files = {
      {std::string(kName) + ".tex", PaperTemplate()},
      {"generated/meta.tex", MetaTex(runs)},
      {"generated/tally.tex", TallyTex(rows)},
      {"claims.json", ClaimsJson(rows)},
      {"generated/provenance.tex", ProvenanceTex(runs, store_path)},
      {"generated/paper000.tex", Paper000Tex(runs, rows.paper000, figures)},
      {"generated/paper002.tex", Paper002Tex(runs, rows.paper002, figures)},
      {"generated/thesis003.tex", Thesis003Tex(runs, rows.thesis003, figures)},
      {"generated/paper004.tex", Paper004Tex(runs, rows.paper004, figures)},
      {"generated/profiles.tex", ProfilesTex(runs, figures)},
      {"generated/limitations.tex", LimitationsTex(runs, rows)},
      {"generated/conclusion.tex", ConclusionTex(runs, rows)},
      {"generated/registry.tex", RegistryTex()},
      {"generated/performance.tex", PerformanceTex(runs, figures)},
  };
  return s;
}

PaperOutput BuildPaper(const std::string& dir) {
  const std::vector<RunRecord> runs = LoadRunsFromDirectory(dir);  // no store: exit 2
  RequireLatex();                                                  // before drawing anything
  const std::string paper_dir = dir + "/paper";
  const std::string elsewhere = PaperElsewhere(dir);
  CreateOutputDirectory(paper_dir + "/generated", elsewhere);  // checks it, if it was there
  CheckWritableDirectory(paper_dir, elsewhere);                 // one left by another user
  // The figures as `plot` draws them (every paper's, then the generic ones).
  const PlotOutput plots = PlotRuns(runs, paper_dir + "/figures", PaperFigures);
  for (const auto& [path, text] :
       GeneratePaper(runs, StorePath(dir), paper_dir + "/figures", plots.messages).files)
    WriteText(paper_dir + "/" + path, text, elsewhere);
  RunLatexmk(paper_dir, kName);
  return {paper_dir + "/" + kName + ".pdf", plots.messages};
}

std::string PaperElsewhere(const std::string& dir) {
  return "copy " + StorePath(dir) + " into a directory you may write and run paper there";
}

}  // namespace icp
