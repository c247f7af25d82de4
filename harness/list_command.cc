#include "harness/list_command.h"

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "algorithms/registry.h"
#include "problems/registry.h"

namespace icp {

namespace {
struct Entry {
  std::string name;
  std::string description;
  std::vector<ParamInfo> params;
  bool test_only = false;
  std::string needs;               // algorithms: the view they need
  std::vector<std::string> offers;  // problems: the views they offer
};

std::vector<Entry> Entries(const std::string& what) {
  std::vector<Entry> out;
  if (what == "algorithms") {
    for (const AlgorithmInfo& a : Algorithms())
      out.push_back({a.name, a.description, a.params(a.name), a.test_only,
                     std::string(ToString(a.needs)), {}});
  } else if (what == "problems") {
    for (const ProblemInfo& p : Problems()) {
      std::vector<std::string> offers;
      for (View v : p.offers) offers.emplace_back(ToString(v));
      out.push_back({p.name, p.description, p.params(p.name), false, "", offers});
    }
  } else {
    throw std::invalid_argument("list " + what + ": expected 'algorithms' or 'problems'");
  }
  return out;
}
}  // namespace

std::string ListPlugins(const std::string& what, const std::string& format) {
  if (format != "text" && format != "json")
    throw std::invalid_argument("--format " + format + ": must be text or json");
  const std::vector<Entry> entries = Entries(what);
  if (format == "json") {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const Entry& e : entries) {
      nlohmann::ordered_json params = nlohmann::ordered_json::array();
      for (const ParamInfo& p : e.params)
        params.push_back({{"name", p.name}, {"type", p.type}, {"default", p.default_value},
                          {"range", p.range}, {"doc", p.doc}});
      nlohmann::ordered_json entry = {{"name", e.name}, {"description", e.description}};
      if (!e.needs.empty()) entry["needs"] = e.needs;
      if (what == "problems") entry["offers"] = e.offers;
      entry["params"] = params;
      if (e.test_only) entry["test_only"] = true;
      out.push_back(entry);
    }
    return out.dump(2) + "\n";
  }
  std::string text;
  for (const Entry& e : entries) {
    text += e.name + (e.test_only ? "  (test plugin)" : "") + "\n    " + e.description + "\n";
    if (!e.needs.empty()) text += "    needs: " + e.needs + "\n";
    if (what == "problems") {
      std::string offers;
      for (const std::string& v : e.offers) offers += (offers.empty() ? "" : ", ") + v;
      text += "    offers: " + offers + "\n";
    }
    for (const ParamInfo& p : e.params) {
      text += "    --param " + p.name + "=" + p.default_value + "  (" + p.type;
      if (!p.range.empty()) text += " " + p.range;
      text += ")  " + p.doc + "\n";
    }
  }
  return text;
}

}  // namespace icp
