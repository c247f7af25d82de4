#include "core/params.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "core/near_names.h"

namespace icp {

bool Range::Contains(double v) const {
  if (std::isnan(v)) return false;
  if (min_open ? !(v > min) : !(v >= min)) return false;
  if (max_open ? !(v < max) : !(v <= max)) return false;
  return true;
}

std::string Range::ToString() const {
  std::string hi = max >= 1e308 ? "+oo" : FormatDouble(max);
  return (min_open ? "(" : "[") + FormatDouble(min) + ", " + hi + (max_open ? ")" : "]");
}

std::string FormatDouble(double v) {
  if (std::isinf(v)) return v > 0 ? "+oo" : "-oo";
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

bool ParseDouble(const std::string& text, double* out) {
  // Decimal only: strtod also reads hexadecimal (0x10 as 16, 0x0.1p0) and
  // skips leading blanks, neither of which a spec means.
  if (text.empty() || text.find_first_of("xX \t\n\r\f\v") != std::string::npos) return false;
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || std::isnan(v)) return false;
  // A value below the least double (1e-400) is not 0: refused, not rounded to it.
  if (errno == ERANGE && v == 0) return false;
  *out = v;
  return true;
}

namespace {

// The integers a range allows, as an int parameter holds them: open ends
// moved in to the next integer, ends beyond the int type (AtLeast's 1e308)
// cut to it.
struct IntegerRange {
  long long lo;
  long long hi;
  bool Contains(long long v) const { return v >= lo && v <= hi; }
  std::string ToString() const {
    return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  }
};
IntegerRange IntegersIn(const Range& r) {
  constexpr double kMin = std::numeric_limits<int>::min();
  constexpr double kMax = std::numeric_limits<int>::max();
  const double lo = r.min_open ? std::floor(r.min) + 1 : std::ceil(r.min);
  const double hi = r.max_open ? std::ceil(r.max) - 1 : std::floor(r.max);
  return {static_cast<long long>(std::max(lo, kMin)), static_cast<long long>(std::min(hi, kMax))};
}

// The outcome of reading an integer parameter's text.
enum class IntegerText { kInteger, kTooLarge, kNotAnInteger };

// Reads decimal text with an optional sign, fraction and exponent ("12",
// "+1e7", "2.5e3", "10000000.0": specs written by hand and YAML's floats
// often spell integers so) whose value is an exact integer. The digits are
// checked, not a double, so "2147483647.0000001" is no integer. kTooLarge:
// an integer beyond +-1e10 (outside any int range), *out unset.
IntegerText ReadInteger(const std::string& text, long long* out) {
  std::size_t i = 0;
  const bool negative = i < text.size() && text[i] == '-';
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
  std::string digits;      // the significand's digits, the point removed
  long long exponent = 0;  // value = digits * 10^exponent
  const auto digit = [&text](std::size_t at) {
    return at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]));
  };
  for (; digit(i); ++i) digits += text[i];
  if (i < text.size() && text[i] == '.') {
    for (++i; digit(i); ++i, --exponent) digits += text[i];
  }
  if (digits.empty()) return IntegerText::kNotAnInteger;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const bool negative_exponent = i < text.size() && text[i] == '-';
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    if (i == text.size()) return IntegerText::kNotAnInteger;
    long long e = 0;
    for (; digit(i); ++i)
      e = std::min(e * 10 + (text[i] - '0'), 1000000000LL);  // saturates: 1e999999999 is too large
    exponent += negative_exponent ? -e : e;
  }
  if (i != text.size()) return IntegerText::kNotAnInteger;
  // Drop leading zeros, and trailing ones into the exponent.
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
  while (!digits.empty() && digits.back() == '0') {
    digits.pop_back();
    ++exponent;
  }
  if (digits.empty()) {  // zero, however written
    *out = 0;
    return IntegerText::kInteger;
  }
  if (exponent < 0) return IntegerText::kNotAnInteger;
  if (static_cast<long long>(digits.size()) + exponent > 10) return IntegerText::kTooLarge;
  long long v = 0;
  for (char c : digits) v = v * 10 + (c - '0');
  for (long long k = 0; k < exponent; ++k) v *= 10;
  *out = negative ? -v : v;
  return IntegerText::kInteger;
}

// A parameter's name must be writable as `--param NAME=VALUE`, as a spec's
// key and in a run key: '.'-separated words (a nested set's prefix), each a
// letter or digit, then letters, digits, '_' or '-'.
bool ValidParamName(const std::string& name) {
  bool word_start = true;
  for (char c : name) {
    const bool alphanumeric = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (word_start) {
      if (!alphanumeric) return false;
      word_start = false;
    } else if (c == '.') {
      word_start = true;
    } else if (!alphanumeric && c != '_' && c != '-') {
      return false;
    }
  }
  return !word_start;
}

// Two fields of one name would be one key for two values: the run key would
// show one, the algorithm read the other.
template <class Entries>
void CheckNewName(const std::string& owner, const std::string& name, const Entries& entries) {
  if (!ValidParamName(name))
    throw ParamError(owner + ": parameter '" + name +
                     "' is not a valid name: a letter or digit, then letters, digits, '_' or '-' "
                     "(a nested set adds 'prefix.')");
  for (const auto& e : entries)
    if (e.info.name == name) throw ParamError(owner + ": parameter '" + name + "' is declared twice");
}
}  // namespace

std::function<std::string(const std::string&)> ParamSet::Where(const std::string& name) const {
  // Captures the owner by value: nested sets are temporaries.
  return [owner = owner_, name](const std::string& value) {
    return owner + "." + name + " = " + value;
  };
}

void ParamSet::Add(const std::string& name, double* field, const std::string& doc, Range range) {
  Entry e;
  e.info = {name, "double", FormatDouble(*field), range.ToString(), doc};
  e.get = [field] { return FormatDouble(*field); };
  e.validate = [where = Where(name), field, range] {
    if (!range.Contains(*field))
      throw ParamError(where(FormatDouble(*field)) + ": must be in " + range.ToString());
  };
  e.set = [where = Where(name), field, range](const std::string& text) {
    double v;
    if (!ParseDouble(text, &v)) throw ParamError(where(text) + ": not a number");
    if (!range.Contains(v)) throw ParamError(where(text) + ": must be in " + range.ToString());
    *field = v == 0 ? 0.0 : v;  // -0 is 0: one spelling, one run key
  };
  CheckNewName(owner_, e.info.name, entries_);
  entries_.push_back(std::move(e));
}

void ParamSet::Add(const std::string& name, int* field, const std::string& doc, Range range) {
  const IntegerRange integers = IntegersIn(range);
  Entry e;
  e.info = {name, "int", std::to_string(*field), integers.ToString(), doc};
  e.get = [field] { return std::to_string(*field); };
  e.validate = [where = Where(name), field, integers] {
    if (!integers.Contains(*field))
      throw ParamError(where(std::to_string(*field)) + ": must be in " + integers.ToString());
  };
  e.set = [where = Where(name), field, integers](const std::string& text) {
    long long v = 0;
    const IntegerText read = ReadInteger(text, &v);
    if (read == IntegerText::kNotAnInteger)
      throw ParamError(where(text) + ": must be an integer in " + integers.ToString());
    if (read == IntegerText::kTooLarge || !integers.Contains(v))
      throw ParamError(where(text) + ": must be in " + integers.ToString());
    *field = static_cast<int>(v);
  };
  CheckNewName(owner_, e.info.name, entries_);
  entries_.push_back(std::move(e));
}

void ParamSet::Add(const std::string& name, bool* field, const std::string& doc) {
  Entry e;
  e.info = {name, "bool", *field ? "true" : "false", "true|false", doc};
  e.get = [field] { return std::string(*field ? "true" : "false"); };
  e.validate = [] {};
  e.set = [where = Where(name), field](const std::string& text) {
    if (text == "true" || text == "1") {
      *field = true;
    } else if (text == "false" || text == "0") {
      *field = false;
    } else {
      throw ParamError(where(text) + ": must be true or false");
    }
  };
  CheckNewName(owner_, e.info.name, entries_);
  entries_.push_back(std::move(e));
}

namespace {
constexpr std::string_view kOneOf = "one of ";
}  // namespace

std::vector<std::string> ChoicesOf(const ParamInfo& info) {
  std::vector<std::string> choices;
  if (info.range.rfind(kOneOf, 0) != 0) return choices;
  const std::string list = info.range.substr(kOneOf.size());
  for (std::size_t start = 0;;) {
    const std::size_t bar = list.find('|', start);
    choices.push_back(list.substr(start, bar - start));
    if (bar == std::string::npos) return choices;
    start = bar + 1;
  }
}

void ParamSet::Add(const std::string& name, std::string* field, const std::string& doc,
                   std::vector<std::string> choices) {
  std::string range;
  for (const auto& c : choices) range += (range.empty() ? std::string(kOneOf) : "|") + c;
  Entry e;
  e.info = {name, "string", *field, range, doc};
  e.get = [field] { return *field; };
  auto check = [where = Where(name), choices, range](const std::string& v) {
    if (choices.empty()) return;
    for (const auto& c : choices)
      if (c == v) return;
    throw ParamError(where(v) + ": must be " + range);
  };
  e.validate = [field, check] { check(*field); };
  e.set = [field, check](const std::string& text) {
    check(text);
    *field = text;
  };
  CheckNewName(owner_, e.info.name, entries_);
  entries_.push_back(std::move(e));
}

void ParamSet::Nest(const std::string& prefix, const std::function<void(ParamSet&)>& describe) {
  ParamSet inner(owner_ + "." + prefix);
  describe(inner);
  for (Entry& e : inner.entries_) {
    e.info.name = prefix + "." + e.info.name;
    CheckNewName(owner_, e.info.name, entries_);
    entries_.push_back(std::move(e));
  }
}

void ParamSet::Set(const std::string& name, const std::string& value) {
  for (Entry& e : entries_) {
    if (e.info.name == name) {
      e.set(value);
      return;
    }
  }
  std::string known;
  std::vector<std::string> names;
  for (const Entry& e : entries_) {
    known += (known.empty() ? "" : ", ") + e.info.name;
    names.push_back(e.info.name);
  }
  throw ParamError("unknown parameter '" + name + "' for " + owner_ + DidYouMean(name, names) +
                   (known.empty() ? " (it takes none)" : " (known: " + known + ")"));
}

void ParamSet::SetAll(const ParamMap& values) {
  for (const auto& [name, value] : values) Set(name, value);
}

void ParamSet::Validate() const {
  for (const Entry& e : entries_) e.validate();
}

std::vector<ParamInfo> ParamSet::Describe() const {
  std::vector<ParamInfo> out;
  for (const Entry& e : entries_) {
    ParamInfo info = e.info;
    info.default_value = e.get();
    out.push_back(info);
  }
  return out;
}

ParamMap ParamSet::Values() const {
  ParamMap out;
  for (const Entry& e : entries_) out[e.info.name] = e.get();
  return out;
}

}  // namespace icp
