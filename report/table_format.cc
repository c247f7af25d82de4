// How a TextTable is written: Markdown and LaTeX (cells escaped for each),
// and the CSV fields and numbers.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "report/report.h"
#include "report/report_internal.h"

namespace icp {

namespace detail::report {

namespace {

std::string MarkdownCell(const std::string& cell) {
  std::string out;
  for (char c : OneLine(cell)) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string OneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return text;
}

void WriteMarkdown(const TextTable& t, std::ostream& out) {
  out << "## " << t.title << "\n\n";
  if (!t.rows.empty() || !t.omit_if_empty) {
    out << "|";
    for (const std::string& h : t.headers) out << " " << MarkdownCell(h) << " |";
    out << "\n|";
    for (bool n : t.numeric) out << (n ? " ---: |" : " :--- |");
    out << "\n";
    for (const auto& row : t.rows) {
      out << "|";
      for (const std::string& c : row) out << " " << MarkdownCell(c) << " |";
      out << "\n";
    }
    out << "\n";
  }
  for (const std::string& n : t.notes) out << n << "\n\n";
  for (const std::string& i : t.items) out << "- " << OneLine(i) << "\n";
  if (!t.items.empty()) out << "\n";
}

std::string FormatCsvNumber(double v) {
  if (std::isnan(v)) return "";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace detail::report

using detail::report::OneLine;

namespace {

// a, b, ..., z, aa, ab, ...: the markers of long cells.
std::string MarkerName(std::size_t index) {
  std::string name;
  for (std::size_t i = index + 1; i > 0; i = (i - 1) / 26) name.insert(name.begin(), 'a' + (i - 1) % 26);
  return name;
}

}  // namespace

std::string TexEscape(const std::string& text) {
  static const std::vector<std::pair<std::string, std::string>> kMap = {
      {"\\", "\\textbackslash{}"}, {"_", "\\_"}, {"&", "\\&"}, {"%", "\\%"}, {"#", "\\#"},
      {"{", "\\{"}, {"}", "\\}"}, {"$", "\\$"}, {"~", "\\textasciitilde{}"},
      {"^", "\\textasciicircum{}"}, {"—", "---"}, {"µ", "$\\mu$"}, {"²", "$^2$"},
      {"×", "$\\times$"}, {"∞", "$\\infty$"}, {"…", "\\ldots{}"}, {"≤", "$\\leq$"},
      {"≥", "$\\geq$"}, {"§", "\\S{}"}, {"−", "$-$"}, {"±", "$\\pm$"}, {"≈", "$\\approx$"},
      {"ρ", "$\\rho$"}, {"τ", "$\\tau$"}, {"π", "$\\pi$"}, {"Ξ", "$\\Xi$"}, {"ψ", "$\\psi$"},
      {"θ", "$\\theta$"}, {"η", "$\\eta$"}, {"³", "$^3$"}, {"°", "$^\\circ$"},
      {"ε", "$\\varepsilon$"}, {"·", "$\\cdot$"}, {"–", "--"},
      {"<", "$<$"}, {">", "$>$"}, {"|", "\\textbar{}"}};
  std::string out;
  const std::string line = OneLine(text);
  for (std::size_t i = 0; i < line.size();) {
    bool matched = false;
    for (const auto& [from, to] : kMap) {
      if (line.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        matched = true;
        break;
      }
    }
    if (matched) continue;
    const auto byte = static_cast<unsigned char>(line[i]);
    if (byte < 0x80) {
      out += line[i++];
      continue;
    }
    // Other UTF-8: pdflatex's utf8 input typesets the Latin-1 letters; any
    // other character (a store in 結果, an emoji in a parameter) stops it,
    // so it is written as its code point.
    const int length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : byte >= 0xC0 ? 2 : 1;
    char32_t code = length == 1 ? 0 : byte & (0x7F >> length);
    bool valid = length > 1 && i + length <= line.size();
    for (int k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(line[i + k]);
      valid = (next & 0xC0) == 0x80;
      code = (code << 6) | (next & 0x3F);
    }
    if (valid && code >= 0xC0 && code <= 0xFF && code != 0xD7 && code != 0xF7) {
      out += line.substr(i, length);
    } else if (valid) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "[U+%04X]", static_cast<unsigned>(code));
      out += hex;
    } else {
      out += "?";  // not UTF-8
    }
    i += valid ? length : 1;
  }
  return out;
}

namespace {

// Whether column i of the table wraps in LaTeX (TextTable::wrap_cm).
bool IsWrapped(const TextTable& table, std::size_t i) {
  return i < table.wrap_cm.size() && table.wrap_cm[i] > 0;
}

// A wrapped cell escaped, with a break allowed after each comma, so that a
// configuration's "{epsilon=2,mode=pave}" does not run into the next column.
std::string BreakableAfterCommas(const std::string& text) {
  std::string out;
  for (char c : TexEscape(text)) {
    out += c;
    if (c == ',') out += "\\allowbreak{}";
  }
  return out;
}

}  // namespace

TextTable WithLongCellsAsNotes(TextTable table, std::size_t max_chars) {
  std::map<std::string, std::string> markers;  // text -> "(a)"
  std::vector<std::string> notes;
  for (auto& row : table.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      const bool numeric = i < table.numeric.size() && table.numeric[i];
      const bool wrapped = IsWrapped(table, i);
      // Characters, not bytes: "²" is one.
      const std::size_t length = static_cast<std::size_t>(std::count_if(
          row[i].begin(), row[i].end(), [](char c) { return (c & 0xC0) != 0x80; }));
      if (numeric || wrapped || length <= max_chars) continue;
      auto [it, added] = markers.emplace(row[i], "");
      if (added) {
        it->second = "(" + MarkerName(markers.size() - 1) + ")";
        notes.push_back(it->second + " " + row[i]);
      }
      row[i] = it->second;
    }
  }
  table.notes.insert(table.notes.begin(), notes.begin(), notes.end());  // right below it
  return table;
}

std::string TexTable(const TextTable& table) {
  const TextTable t = WithLongCellsAsNotes(table, kMaxTexCellChars);
  std::ostringstream out;
  out << "% " << OneLine(t.title) << "\n";
  if (!t.rows.empty() || !t.omit_if_empty) {
    out << "\\begin{table}[htbp]\n\\centering\n\\small\n\\caption{" << TexEscape(t.title)
        << "}\n"
        // Set in a box (scratch register 0, local to the float), then shrunk
        // to the line width when wider and to kMaxTexTableHeight of the text
        // height when taller (a float taller than the page leaves a blank
        // page), never enlarged.
        << "\\sbox0{%\n"
        << "\\begin{tabular}{";
    for (std::size_t i = 0; i < t.numeric.size(); ++i) {
      if (IsWrapped(t, i))
        out << ">{\\raggedright\\arraybackslash}p{" << FormatNumber(t.wrap_cm[i]) << "cm}";
      else
        out << (t.numeric[i] ? 'r' : 'l');
    }
    out << "}\n\\toprule\n";
    for (std::size_t i = 0; i < t.headers.size(); ++i) {
      out << (i ? " & " : "") << TexEscape(t.headers[i]);
    }
    out << " \\\\\n\\midrule\n";
    for (const auto& row : t.rows) {
      for (std::size_t i = 0; i < row.size(); ++i) {
        out << (i ? " & " : "")
            << (IsWrapped(t, i) ? BreakableAfterCommas(row[i]) : TexEscape(row[i]));
      }
      out << " \\\\\n";
    }
    out << "\\bottomrule\n\\end{tabular}}%\n"
        << "\\ifdim\\wd0>\\linewidth\\sbox0{\\resizebox{\\linewidth}{!}{\\usebox0}}\\fi\n"
        << "\\ifdim\\dimexpr\\ht0+\\dp0\\relax>" << kMaxTexTableHeight
        << "\\textheight\\sbox0{\\resizebox*{!}{" << kMaxTexTableHeight << "\\textheight}{\\usebox0}}\\fi\n"
        << "\\usebox0\n\\end{table}\n\n";
  }
  for (const std::string& n : t.notes) out << TexEscape(n) << "\n\n";
  if (!t.items.empty()) {
    out << "\\begin{itemize}\n";
    for (const std::string& i : t.items) out << "\\item " << TexEscape(i) << "\n";
    out << "\\end{itemize}\n\n";
  }
  return out.str();
}

}  // namespace icp
