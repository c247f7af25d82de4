// The generated fragments of the paper (generated/*.tex), each from the
// runs of the store; the template (paper/template/icpbench.tex) inputs them.
#ifndef ICPBENCH_PAPER_SECTIONS_H_
#define ICPBENCH_PAPER_SECTIONS_H_

#include <string>
#include <vector>

#include "harness/run_record.h"

namespace icp {

// Where the figures are and why the missing ones are ("NAME: skipped: ...").
struct FigureSet {
  std::string dir;  // holds NAME.pdf for each figure drawn
  std::vector<std::string> skipped;
};

// \icpbenchdate: the date of the store's newest run.
std::string MetaTex(const std::vector<RunRecord>& runs);
// The store, its runs by status, its code revisions, machines, compilers,
// flags and dates: the provenance on the first page.
std::string ProvenanceTex(const std::vector<RunRecord>& runs, const std::string& store_path);
// The registered algorithms and problems (test plugins left out).
std::string RegistryTex();
std::string Paper000Tex(const std::vector<RunRecord>& runs, const FigureSet& figures);
std::string Thesis003Tex(const std::vector<RunRecord>& runs, const FigureSet& figures);
std::string Paper004Tex(const std::vector<RunRecord>& runs, const FigureSet& figures);
// Time per step of every configuration, and fig_timing.
std::string PerformanceTex(const std::vector<RunRecord>& runs, const FigureSet& figures);

}  // namespace icp

#endif  // ICPBENCH_PAPER_SECTIONS_H_
