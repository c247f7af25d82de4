#include "core/params.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

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

namespace {
bool ParseDouble(const std::string& text, double* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || std::isnan(v)) return false;
  *out = v;
  return true;
}
bool ParseInt(const std::string& text, int* out) {
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *out);
  return ec == std::errc() && end == text.data() + text.size() && !text.empty();
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
    *field = v;
  };
  entries_.push_back(std::move(e));
}

void ParamSet::Add(const std::string& name, int* field, const std::string& doc, Range range) {
  Entry e;
  e.info = {name, "int", std::to_string(*field), range.ToString(), doc};
  e.get = [field] { return std::to_string(*field); };
  e.validate = [where = Where(name), field, range] {
    if (!range.Contains(*field))
      throw ParamError(where(std::to_string(*field)) + ": must be in " + range.ToString());
  };
  e.set = [where = Where(name), field, range](const std::string& text) {
    int v;
    if (!ParseInt(text, &v)) throw ParamError(where(text) + ": not an integer");
    if (!range.Contains(v)) throw ParamError(where(text) + ": must be in " + range.ToString());
    *field = v;
  };
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
  entries_.push_back(std::move(e));
}

void ParamSet::Add(const std::string& name, std::string* field, const std::string& doc,
                   std::vector<std::string> choices) {
  std::string range;
  for (const auto& c : choices) range += (range.empty() ? "one of " : "|") + c;
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
  entries_.push_back(std::move(e));
}

void ParamSet::Nest(const std::string& prefix, const std::function<void(ParamSet&)>& describe) {
  ParamSet inner(owner_ + "." + prefix);
  describe(inner);
  for (Entry& e : inner.entries_) {
    e.info.name = prefix + "." + e.info.name;
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
  for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.info.name;
  throw ParamError("unknown parameter '" + name + "' for " + owner_ +
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
