// The generated fragments of the paper (generated/*.tex), each from the
// runs of the store; the template (paper/template/icpbench.tex) inputs them.
#ifndef ICPBENCH_PAPER_SECTIONS_H_
#define ICPBENCH_PAPER_SECTIONS_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "paper/comparison.h"

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

// The published-vs-measured rows of each seed paper, made once: its section
// lays them out and discusses them, the abstract and the conclusion count
// them.
struct PaperComparisons {
  std::vector<ComparisonRow> paper000;
  std::vector<ComparisonRow> paper002;
  std::vector<ComparisonRow> thesis003;
  std::vector<ComparisonRow> paper004;
  std::vector<ComparisonRow> All() const;  // in that order
};
PaperComparisons ComparePapers(const std::vector<RunRecord>& runs);

// A seed paper's section: subsections Setup (the runs and the tables made
// from them), Claims (its rows), Figures and Discussion (DiscussionTex).
std::string Paper000Tex(const std::vector<RunRecord>& runs, const std::vector<ComparisonRow>& rows,
                        const FigureSet& figures);
std::string Paper002Tex(const std::vector<RunRecord>& runs, const std::vector<ComparisonRow>& rows,
                        const FigureSet& figures);
std::string Thesis003Tex(const std::vector<RunRecord>& runs,
                         const std::vector<ComparisonRow>& rows, const FigureSet& figures);
std::string Paper004Tex(const std::vector<RunRecord>& runs, const std::vector<ComparisonRow>& rows,
                        const FigureSet& figures);
// The performance profiles of time and area (report/performance_profile.h):
// their tables and fig_profile_time, fig_profile_area.
std::string ProfilesTex(const std::vector<RunRecord>& runs, const FigureSet& figures);
// Time per step of every configuration, and fig_timing (an appendix).
std::string PerformanceTex(const std::vector<RunRecord>& runs, const FigureSet& figures);

// The closing parts (paper/closing_sections.cc).
// \icpbenchtally, "Verdicts: N match, N differ, N no data" over every row,
// and \icpbenchclaims, their number: what the abstract states.
std::string TallyTex(const PaperComparisons& comparisons);
// DIR/paper/claims.json, what the results browser's Claims view shows: one
// object per row, {paper, id, item, where, quote, published, measured, rule,
// verdict, reason, note} (id, where, quote and note empty for rows made in
// code).
std::string ClaimsJson(const PaperComparisons& comparisons);
// A paper's discussion: a paragraph for each difference (rows that share a
// reason share it), what the rows without data need, or that nothing differs.
std::string DiscussionTex(const std::vector<ComparisonRow>& rows);
// What the comparison cannot show: simulated data, the machines of the runs,
// and the claims not reproduced (no data) with why.
std::string LimitationsTex(const std::vector<RunRecord>& runs,
                           const PaperComparisons& comparisons);
// The tally, overall (the line "Verdicts: ...") and per paper, and the best
// configurations of the performance profiles.
std::string ConclusionTex(const std::vector<RunRecord>& runs,
                          const PaperComparisons& comparisons);

}  // namespace icp

#endif  // ICPBENCH_PAPER_SECTIONS_H_
