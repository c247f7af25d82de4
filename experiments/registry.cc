#include "experiments/registry.h"

#include "experiments/paper000/paper000.h"
#include "experiments/paper002/paper002.h"
#include "experiments/paper004/paper004.h"
#include "experiments/thesis003/thesis003.h"

namespace icp {

const std::vector<PaperInfo>& Papers() {
  static const std::vector<PaperInfo> kPapers = {
      {"paper000", "HC4, BC3, BC4, 3B-BC4 on the car track: Table 1, Figs 2-4", &Paper000ReportTables,
       &Paper000Figures},
      {"paper002", "a robot at a corridor's end tracking typed landmarks: association and accuracy, Figs 9 and 11",
       &Paper002Tables, &Paper002Figures},
      {"thesis003", "relaxed solvers on lines and beacons (Figs 5.2, 5.5-5.7, a table); marina sonar vs particle filter (ch. 6); the city without GPS (Fig. 4.17)",
       &Thesis003Tables, &Thesis003Figures},
      {"paper004", "real-time vs post-localization and consistency on the car track (Figs 12-13)",
       &Paper004Tables, &Paper004Figures},
  };
  return kPapers;
}

std::vector<TextTable> PaperTables(const std::vector<RunRecord>& runs) {
  std::vector<TextTable> out;
  for (const PaperInfo& p : Papers()) {
    for (TextTable& t : p.tables(runs)) out.push_back(std::move(t));
  }
  return out;
}

void PaperFigures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                  PlotOutput* out) {
  for (const PaperInfo& p : Papers()) p.figures(runs, out_dir, out);
}

}  // namespace icp
