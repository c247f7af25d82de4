// The papers whose tables and figures icpbench reproduces: one explicit
// table (experiments/registry.cc), one line per paper, its code in
// experiments/NAME/. Each chooses its runs by spec experiment name (see its
// header) and adds tables to the report and figures to the plots; the
// report and the plots themselves know no paper.
#ifndef ICPBENCH_EXPERIMENTS_REGISTRY_H_
#define ICPBENCH_EXPERIMENTS_REGISTRY_H_

#include <string>
#include <vector>

#include "report/report.h"
#include "harness/run_record.h"
#include "plots/figures.h"

namespace icp {

struct PaperInfo {
  std::string name;         // "paper000"
  std::string description;  // one line
  std::vector<TextTable> (*tables)(const std::vector<RunRecord>& runs);
  void (*figures)(const std::vector<RunRecord>& runs, const std::string& out_dir,
                  PlotOutput* out);
};

const std::vector<PaperInfo>& Papers();

// Every paper's tables, in registry order: the report's TableMaker.
std::vector<TextTable> PaperTables(const std::vector<RunRecord>& runs);
// Every paper's figures, in registry order: the plots' FigureMaker.
void PaperFigures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                  PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_REGISTRY_H_
