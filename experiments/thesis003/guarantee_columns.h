// The columns a thesis 003 table gives a set-membership configuration for
// its guarantee (harness/guarantee.h): on how many steps the outlier
// assumption held, the consistency over those steps (1 when the guarantee
// holds), the median steps to re-acquire a lost truth, and the dominant
// reason of the steps that missed it. Pooled over a group's ok runs.
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_GUARANTEE_COLUMNS_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_GUARANTEE_COLUMNS_H_

#include <map>
#include <string>
#include <vector>

#include "report/report.h"

namespace icp {

struct GuaranteeSummary {
  int judged = 0;          // steps with assumption_held
  int held = 0;            // ... equal to 1
  int held_contained = 0;  // ... whose estimate holds the truth
  int misses = 0;          // steps with a miss_reason
  std::map<std::string, int> miss_categories;  // misses per category (MissCategory)
  std::string dominant;    // the most frequent miss category
  int dominant_count = 0;
  double median_reacquire = 0;          // NaN when no loss episode ended
  double ConsistencyWhereHeld() const;  // NaN when it never held
};
GuaranteeSummary SummariseGuarantee(const GroupSummary& g);

// Appended to a table's headers, numeric flags, rows and notes.
std::vector<std::string> GuaranteeHeaders();
std::vector<bool> GuaranteeNumeric();
std::vector<std::string> GuaranteeCells(const GroupSummary& g);
std::string GuaranteeNote();

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_GUARANTEE_COLUMNS_H_
