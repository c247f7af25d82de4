// What the parts of the report share and callers do not see: text on one
// line, the Markdown and CSV writers and the runs-per-configuration table.
#ifndef ICPBENCH_REPORT_REPORT_INTERNAL_H_
#define ICPBENCH_REPORT_REPORT_INTERNAL_H_

#include <ostream>
#include <string>
#include <vector>

#include "report/report.h"

namespace icp::detail::report {

// text on one line: line breaks and tabs become spaces.
std::string OneLine(std::string text);

// One table as `report --format md` writes it: a level-2 title, the table,
// its notes as paragraphs and its items as a list.
void WriteMarkdown(const TextTable& t, std::ostream& out);

// A CSV number: 6 significant digits, "" for NaN, "inf"/"-inf".
std::string FormatCsvNumber(double v);
// A CSV field, quoted (RFC 4180) when it holds a comma, quote or line break.
std::string CsvField(const std::string& text);

// The runs-per-configuration table and its failure list (md, tex), and the
// same table as CSV.
TextTable GroupTable(const std::vector<GroupSummary>& groups);
std::string GroupCsv(const std::vector<GroupSummary>& groups);

}  // namespace icp::detail::report

#endif  // ICPBENCH_REPORT_REPORT_INTERNAL_H_
