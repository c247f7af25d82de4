// Parameters of plugins (algorithms, problems): each plugin keeps a plain
// struct with defaults in its initialisers, and one Describe function that
// binds every field to a ParamSet with its name, range and a one-line doc.
// The registry, the CLI and the harness set, validate and list parameters
// through that binding only, e.g. (algorithms/hc4/hc4.cc):
//   void Describe(HC4Params& p, ParamSet& set) {
//     set.Add("ratio", &p.ratio, "...", Range::HalfOpen(0, 1));
//   }
#ifndef ICPBENCH_CORE_PARAMS_H_
#define ICPBENCH_CORE_PARAMS_H_

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace icp {

// key -> value text, as given on a command line or in a spec.
using ParamMap = std::map<std::string, std::string>;

// A bad parameter name or value. what() names the owner, the field, the value
// and the rule, e.g. "hc4.ratio = -1: must be in [0, 1)".
class ParamError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A numeric range [min, max] with optionally open ends.
struct Range {
  double min;
  double max;
  bool min_open = false;
  bool max_open = false;
  static Range Closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range HalfOpen(double lo, double hi) { return {lo, hi, false, true}; }
  static Range Positive(double hi) { return {0, hi, true, false}; }
  static Range AtLeast(double lo) { return {lo, 1e308, false, false}; }
  bool Contains(double v) const;
  std::string ToString() const;
};

// What the registry lists for one parameter.
struct ParamInfo {
  std::string name;
  std::string type;           // "double", "int", "bool", "string"
  std::string default_value;  // as text
  std::string range;          // "[0, 1)", "one of a|b", "" when free
  std::string doc;
};
// The choices a string parameter's range lists ("one of a|b": a and b);
// empty for any other range (a free string, a number's interval).
std::vector<std::string> ChoicesOf(const ParamInfo& info);

class ParamSet {
 public:
  explicit ParamSet(std::string owner) : owner_(std::move(owner)) {}

  void Add(const std::string& name, double* field, const std::string& doc, Range range);
  // An int field allows the integers of range, cut to the int type, and
  // lists them so ("[1, 2147483647]"); its text may be any decimal spelling
  // of an exact integer ("1e7", "2.5e3").
  void Add(const std::string& name, int* field, const std::string& doc, Range range);
  void Add(const std::string& name, bool* field, const std::string& doc);
  void Add(const std::string& name, std::string* field, const std::string& doc,
           std::vector<std::string> choices = {});
  // Binds the fields of a nested parameter struct under "prefix.".
  void Nest(const std::string& prefix, const std::function<void(ParamSet&)>& describe);

  // Parses text into the named field; throws ParamError for an unknown name
  // (listing the known ones), unparsable text or a value out of range.
  void Set(const std::string& name, const std::string& value);
  void SetAll(const ParamMap& values);
  // Checks every field's current value; throws ParamError on the first bad one.
  void Validate() const;
  // The fields with their current values.
  std::vector<ParamInfo> Describe() const;
  ParamMap Values() const;
  const std::string& owner() const { return owner_; }

 private:
  struct Entry {
    ParamInfo info;
    std::function<void(const std::string&)> set;   // parse + store
    std::function<std::string()> get;              // current value as text
    std::function<void()> validate;                // throws ParamError
  };
  std::function<std::string(const std::string&)> Where(const std::string& name) const;
  std::string owner_;
  std::vector<Entry> entries_;
};

// Reads a plugin's parameter struct from key=value text: defaults from the
// struct, every given key checked by name and range. Describe(P&, ParamSet&)
// is found by argument-dependent lookup.
template <class P>
P ParseParams(const std::string& owner, const ParamMap& values) {
  P params;
  ParamSet set(owner);
  Describe(params, set);
  set.SetAll(values);
  set.Validate();
  return params;
}

// The effective parameters of P from key=value text: every declared field,
// defaults filled in, each value in its canonical spelling (what identifies
// a run). Throws ParamError like ParseParams.
template <class P>
ParamMap ResolveParams(const std::string& owner, const ParamMap& values) {
  P params;
  ParamSet set(owner);
  Describe(params, set);
  set.SetAll(values);
  set.Validate();
  return set.Values();
}

// The parameters of P with their defaults, for listings.
template <class P>
std::vector<ParamInfo> DefaultParams(const std::string& owner) {
  P params;
  ParamSet set(owner);
  Describe(params, set);
  return set.Describe();
}

// Number formatting shared by parameter and result printing: the shortest
// text that reads back to the same double.
std::string FormatDouble(double v);
// A decimal number (sign, fraction, exponent; inf and infinity too), as a
// parameter's or a spec's text: false for anything else (NaN, hexadecimal,
// blanks, trailing text, a non-zero value that underflows to 0 such as 1e-400).
bool ParseDouble(const std::string& text, double* out);

}  // namespace icp

#endif  // ICPBENCH_CORE_PARAMS_H_
