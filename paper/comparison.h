// Published vs measured, row by row: what a seed paper reports, what the
// store measures, the rule (with its tolerance) that decides whether they
// match, and, when they differ, the reason — measured (a number from the
// store, or a measurement docs/ records, cited), known by construction
// (another implementation, machine or data set), or "not yet measured".
// The rules are code, so the verdicts follow the stored numbers.
#ifndef ICPBENCH_PAPER_COMPARISON_H_
#define ICPBENCH_PAPER_COMPARISON_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "report/report.h"

namespace icp {

enum class Verdict {
  kMatch,
  kDiffers,
  kNoData,  // the store lacks the runs; the reason names the spec that makes them
};
std::string_view ToString(Verdict verdict);  // "match", "differs", "no data"

struct ComparisonRow {
  std::string item;       // "Table 1: BC3 / HC4"
  std::string published;  // "1.96"
  std::string measured;   // "42.5"
  std::string rule;       // "within a factor 1.5"
  Verdict verdict = Verdict::kNoData;
  std::string reason;  // why it differs, or which spec produces the runs
  // From a claims file (paper/claims.h); empty for rows made in code.
  std::string id{};     // "table1-bc3-ratio"
  std::string where{};  // "Table 1"
  std::string quote{};  // the paper's words
  std::string note{};   // e.g. where the source contradicts itself
};

// How many rows have each verdict.
struct VerdictTally {
  int match = 0;
  int differ = 0;
  int no_data = 0;
};
VerdictTally Tally(const std::vector<ComparisonRow>& rows);
// "Verdicts: 12 match, 5 differ, 3 no data".
std::string ToString(const VerdictTally& tally);

// The reason text for a difference no measurement explains.
inline constexpr char kNotMeasured[] = "differs; reason not yet measured";

// |log(measured / published)| <= log(factor): both positive, finite.
bool WithinFactor(double measured, double published, double factor);

// The table of rows: #, item, published, measured, verdict; each row's rule
// and reason follow in the list below, numbered like the rows.
TextTable ComparisonTable(const std::string& title, const std::vector<ComparisonRow>& rows);

}  // namespace icp

#endif  // ICPBENCH_PAPER_COMPARISON_H_
