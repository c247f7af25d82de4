#include "harness/spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "algorithms/registry.h"
#include "core/near_names.h"
#include "harness/yaml_documents.h"
#include "problems/registry.h"

namespace icp {

namespace {

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key,
                         const std::string& message) const {
    Fail(node.Mark(), key, message);
  }
  [[noreturn]] void Fail(const YAML::Mark& mark, const std::string& key,
                         const std::string& message) const {
    std::ostringstream out;
    out << source_;
    if (mark.line >= 0) out << ":" << mark.line + 1 << ":" << mark.column + 1;
    out << ": " << (key.empty() ? "" : "key '" + key + "': ") << message;
    throw SpecError(out.str());
  }

  // A mapping key as text; yaml-cpp's own conversion error names no file.
  std::string Key(const YAML::Node& key, const std::string& where) const {
    if (!key.IsScalar())
      Fail(key, where,
           std::string("a key must be a single value, not a ") +
               (key.IsSequence() ? "list" : key.IsMap() ? "mapping" : "null"));
    // yaml-cpp reads a merge key as a plain key named "<<".
    if (key.Scalar() == "<<" && key.Tag() != "tag:yaml.org,2002:str" && key.Tag() != "!")
      Fail(key, where, "YAML merge keys (<<) are not supported: write the keys out (an alias "
                       "*name repeats a whole value)");
    return key.Scalar();
  }

  // yaml-cpp keeps the first of duplicated keys silently and lets lookups
  // see only it, so every mapping of the document is checked once up front.
  // Once: an alias is its anchor's node (the same mark), so nested aliases,
  // each naming the one before twice, cost no more than their text.
  void CheckDocument(const YAML::Node& node, const std::string& where) const {
    if ((node.IsSequence() || node.IsMap()) && node.Mark().pos >= 0 &&
        !checked_.insert(node.Mark().pos).second)
      return;
    if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i)
        CheckDocument(node[i], where + "[" + std::to_string(i) + "]");
    } else if (node.IsMap()) {
      std::map<std::string, YAML::Mark> seen;
      for (const auto& kv : node) {
        const std::string k = Key(kv.first, where);
        const auto [it, inserted] = seen.emplace(k, kv.first.Mark());
        if (!inserted)
          Fail(kv.first, Join(where, k),
               "duplicated key (first at line " + std::to_string(it->second.line + 1) + ":" +
                   std::to_string(it->second.column + 1) + ")");
        CheckDocument(kv.second, Join(where, k));
      }
    }
  }

  void CheckKeys(const YAML::Node& map, const std::string& where,
                 const std::set<std::string>& allowed) const {
    if (!map.IsMap()) Fail(map, where, "expected a mapping");
    for (const auto& kv : map) {
      const std::string k = Key(kv.first, where);
      if (!allowed.count(k)) {
        std::string known;
        for (const auto& a : allowed) known += (known.empty() ? "" : ", ") + a;
        Fail(kv.first, Join(where, k),
             "unknown key" + DidYouMean(k, {allowed.begin(), allowed.end()}) +
                 " (expected one of: " + known + ")");
      }
    }
  }

  static std::string Join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
  }

  // Runs are stored under SPEC#name, read back after the last '#'.
  std::string ExperimentName(const YAML::Node& node, const std::string& key) const {
    std::string name = Scalar(node, key);
    if (name.find('#') != std::string::npos)
      Fail(node, key, "'" + name + "': an experiment's name cannot hold '#' (runs are stored under SPEC#NAME)");
    // Empty, it would be stored without its '#' and read back from the
    // spec's path; a control character (NUL cut it short) is not a name.
    if (name.find_first_not_of(" \t") == std::string::npos)
      Fail(node, key, "an experiment's name cannot be empty");
    for (const char c : name)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        Fail(node, key, "an experiment's name cannot hold a control character");
    return name;
  }

  std::string Scalar(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) Fail(node, key, "expected a single value");
    return node.Scalar();
  }

  // A timeout in seconds; inf (YAML's .inf too) or any huge value means no
  // limit (the runner and StopCondition treat them so).
  double Timeout(const YAML::Node& node, const std::string& key) const {
    return Positive(node, key);
  }

  // record: steps (every step row) or runs (the run row only); true for steps.
  bool RecordSteps(const YAML::Node& node, const std::string& key) const {
    const std::string text = Scalar(node, key);
    if (text != "steps" && text != "runs") Fail(node, key, "'" + text + "' must be steps or runs");
    return text == "steps";
  }

  // A memory limit in MiB; 0 means none.
  double MemoryLimit(const YAML::Node& node, const std::string& key) const {
    const std::string text = Scalar(node, key);
    double zero = 1;
    if (ParseDouble(text, &zero) && zero == 0) return 0;  // 0, 0.0, -0
    const double v = Positive(node, key);
    if (v < kMinMemoryLimitMb)
      Fail(node, key, "'" + text + "' is below the least a worker needs (" +
                          std::to_string(static_cast<int>(kMinMemoryLimitMb)) + " MiB; 0: no limit)");
    return v;
  }

  // A number > 0; inf in YAML's spellings (.inf, .Inf, .INF) too.
  double Positive(const YAML::Node& node, const std::string& key) const {
    const std::string text = Scalar(node, key);
    if (text == ".inf" || text == ".Inf" || text == ".INF") return kInf;
    double v = 0;
    if (!ParseDouble(text, &v) || !(v > 0)) Fail(node, key, "'" + text + "' is not a positive number");
    return v;
  }

  std::vector<std::uint64_t> Seeds(const YAML::Node& parent, const std::string& where,
                                   std::vector<std::uint64_t> fallback) const {
    const YAML::Node seeds = parent["seeds"];
    const YAML::Node reps = parent["repetitions"];
    if (seeds && reps) Fail(reps, Join(where, "repetitions"), "give seeds or repetitions, not both");
    auto as_seed = [&](const YAML::Node& n, const std::string& key) {
      const std::string text = Scalar(n, key);
      std::uint64_t v = 0;
      std::size_t used = 0;
      try {
        v = std::stoull(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      // Decimal digits only: stoull also read 0x10 as 16 and skipped leading blanks.
      if (used == text.size() && !text.empty() && text.find_first_not_of("0123456789") == std::string::npos)
        return v;
      // An integer spelt as integer parameters may be ("1.0", "1e3"), up to
      // 2^53, where a double still holds every integer; and exactly (the
      // decimal's enclosure a point): 9007199254740993.0 is not 2^53.
      Interval exact;
      const bool decimal = text.find_first_not_of("0123456789.eE+-") == std::string::npos;
      if (decimal && ParseDecimal(text, &exact) && exact.IsPoint()) {
        const double d = exact.lo();
        if (d >= 0 && d <= 9007199254740992.0 && d == std::floor(d)) return static_cast<std::uint64_t>(d);
      }
      Fail(n, key, "'" + text + "' is not a non-negative integer below 2^64 (in digits; with a "
                   "point or an exponent, at most 2^53)");
    };
    if (seeds) {
      std::vector<std::uint64_t> out;
      if (seeds.IsSequence()) {
        for (std::size_t i = 0; i < seeds.size(); ++i)
          out.push_back(as_seed(seeds[i], Join(where, "seeds[" + std::to_string(i) + "]")));
      } else {
        out.push_back(as_seed(seeds, Join(where, "seeds")));
      }
      if (out.empty()) Fail(seeds, Join(where, "seeds"), "no seeds");
      return out;
    }
    if (reps) {
      const std::uint64_t n = as_seed(reps, Join(where, "repetitions"));
      if (n < 1 || n > 100000) Fail(reps, Join(where, "repetitions"), "must be in [1, 100000]");
      std::vector<std::uint64_t> out;
      for (std::uint64_t s = 1; s <= n; ++s) out.push_back(s);
      return out;
    }
    return fallback;
  }

  // name: or {name:, params:} -> name and the grid of parameter maps.
  std::pair<std::string, std::vector<ParamMap>> Plugin(const YAML::Node& node,
                                                       const std::string& where) const {
    if (node.IsScalar()) return {node.Scalar(), {ParamMap{}}};
    CheckKeys(node, where, {"name", "params"});
    if (!node["name"]) Fail(node, where, "missing 'name'");
    std::string name = Scalar(node["name"], Join(where, "name"));
    std::vector<ParamMap> grid = {ParamMap{}};
    if (const YAML::Node params = node["params"]) {
      if (!params.IsMap()) Fail(params, Join(where, "params"), "expected a mapping of key: value");
      for (const auto& kv : params) {
        const std::string key = Key(kv.first, Join(where, "params"));
        const std::string at = Join(where, "params." + key);
        std::vector<std::string> values;
        if (kv.second.IsMap()) {
          // A composite's inner parameters are flat, dotted names.
          const std::string first =
              kv.second.size() > 0 ? Key(kv.second.begin()->first, at) : "name";
          Fail(kv.second, at,
               "expected a value or a list of values, not a mapping (an inner parameter is "
               "written with a dot: '" + key + "." + first + ": VALUE')");
        }
        if (kv.second.IsSequence()) {
          if (kv.second.size() == 0) Fail(kv.second, at, "an empty list of values");
          for (std::size_t i = 0; i < kv.second.size(); ++i)
            values.push_back(Scalar(kv.second[i], at + "[" + std::to_string(i) + "]"));
        } else {
          values.push_back(Scalar(kv.second, at));
        }
        // Checked before expanding: a huge grid must not exhaust memory first.
        if (grid.size() * values.size() > kMaxRuns)
          Fail(kv.second, at, "the parameter grid has more than " + std::to_string(kMaxRuns) +
                                  " points (the limit of a run matrix)");
        std::vector<ParamMap> next;
        for (const ParamMap& base : grid)
          for (const std::string& v : values) {
            ParamMap m = base;
            m[key] = v;
            next.push_back(std::move(m));
          }
        grid = std::move(next);
      }
    }
    return {name, grid};
  }

  // Resolves each grid point to its effective parameters (ParamResolver);
  // ParamError becomes a SpecError at the node.
  template <class Resolve>
  std::vector<ParamMap> ResolveGrid(const YAML::Node& node, const std::string& where,
                                    const std::string& name, const std::vector<ParamMap>& grid,
                                    Resolve resolve) const {
    std::vector<ParamMap> out;
    for (const ParamMap& m : grid) {
      try {
        out.push_back(resolve(name, m));
      } catch (const std::invalid_argument& e) {
        Fail(node.IsMap() && node["params"] ? node["params"] : node, where, e.what());
      }
    }
    return out;
  }

  void Experiment(const YAML::Node& node, const std::string& where, const std::string& name,
                  double timeout, double memory_limit, bool record_steps,
                  const std::vector<std::uint64_t>& seeds, Spec* spec,
                  std::set<std::string>* seen) const {
    const YAML::Node algorithms = node["algorithms"];
    const YAML::Node problems = node["problems"];
    if (!algorithms || !algorithms.IsSequence() || algorithms.size() == 0)
      Fail(algorithms ? algorithms : node, Join(where, "algorithms"), "expected a non-empty list");
    if (!problems || !problems.IsSequence() || problems.size() == 0)
      Fail(problems ? problems : node, Join(where, "problems"), "expected a non-empty list");
    struct Entry {
      std::string name;
      std::vector<ParamMap> grid;
      YAML::Node node;
      std::string at;
    };
    std::vector<Entry> algs, probs;
    std::set<std::string> legacy_carry;
    // The matrix's size is checked as each entry is read, before anything is
    // resolved or expanded: many large grids (YAML aliases make them cheap to
    // write) must not exhaust memory before the limit is seen.
    double a_points = 0, p_points = 0;
    auto check_size = [&](const YAML::Node& at_node, const std::string& at) {
      const double runs = std::max(a_points, 1.0) * std::max(p_points, 1.0) *
                              static_cast<double>(std::max<std::size_t>(seeds.size(), 1)) +
                          static_cast<double>(spec->runs.size());
      if (runs > static_cast<double>(kMaxRuns))
        Fail(at_node, at, "the run matrix has at least " +
                              std::to_string(static_cast<unsigned long long>(std::min(runs, 1e18))) +
                              " runs, more than the limit of " + std::to_string(kMaxRuns) +
                              "; split the spec (each shard expands the whole matrix)");
    };
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
      const std::string at = Join(where, "algorithms[" + std::to_string(i) + "]");
      auto [alg, grid] = Plugin(algorithms[i], at);
      try {
        FindAlgorithm(alg);
      } catch (const std::invalid_argument& e) {
        Fail(algorithms[i], at, e.what());
      }
      a_points += static_cast<double>(grid.size());
      check_size(algorithms[i], at);
      algs.push_back({alg, grid, algorithms[i], at});
    }
    for (std::size_t i = 0; i < problems.size(); ++i) {
      const std::string at = Join(where, "problems[" + std::to_string(i) + "]");
      auto [prob, grid] = Plugin(problems[i], at);
      p_points += static_cast<double>(grid.size());
      check_size(problems[i], at);
      const ProblemInfo* info = nullptr;
      try {
        info = &FindProblem(prob);
      } catch (const std::invalid_argument& e) {
        Fail(problems[i], at, e.what());
      }
      // car-track's `carry` moved to the algorithms (issue 8): a spec that
      // still gives it there means it for every algorithm of the experiment.
      for (ParamMap& m : grid)
        if (prob == "car-track" && m.count("carry")) {
          legacy_carry.insert(m["carry"]);
          m.erase("carry");
        }
      probs.push_back({prob, ResolveGrid(problems[i], at, prob, grid, info->resolve), problems[i], at});
      if (info->note)
        for (const ParamMap& resolved : probs.back().grid)
          if (std::string note = info->note(resolved);
              !note.empty() && std::find(spec->notes.begin(), spec->notes.end(), note) == spec->notes.end())
            spec->notes.push_back(std::move(note));
    }
    if (legacy_carry.size() > 1)
      Fail(problems, Join(where, "problems"),
           "car-track.carry moved to the algorithms; give one value per experiment, or write "
           "{name: hc4, params: {carry: [...]}}");
    for (Entry& a : algs) {
      const AlgorithmInfo& info = FindAlgorithm(a.name);
      if (!legacy_carry.empty()) {
        bool declared = false;
        for (const ParamInfo& p : info.params(a.name)) declared |= p.name == "carry";
        if (declared)
          for (ParamMap& m : a.grid)
            if (!m.count("carry")) m["carry"] = *legacy_carry.begin();
      }
      a.grid = ResolveGrid(a.node, a.at, a.name, a.grid, info.resolve);
    }
    for (const Entry& p : probs) {
      const ProblemInfo& pinfo = FindProblem(p.name);
      for (const Entry& a : algs) {
        const AlgorithmInfo& ainfo = FindAlgorithm(a.name);
        std::string skip;
        bool offered = false;
        for (View v : pinfo.offers) offered |= v == ainfo.needs;
        if (!offered)
          skip = a.name + " needs the " + std::string(ToString(ainfo.needs)) + " view, which " +
                 p.name + " does not offer";
        for (const ParamMap& pp : p.grid)
          for (const ParamMap& ap : a.grid)
            for (std::uint64_t seed : seeds) {
              PlannedRun run{
                  RunSpec{a.name, ap, p.name, pp, seed, timeout, memory_limit, record_steps}, name,
                  skip};
              if (seen->insert(run.spec.Key()).second) spec->runs.push_back(std::move(run));
            }
      }
    }
  }

 private:
  std::string source_;
  mutable std::set<int> checked_;  // CheckDocument's collections, by text position
};

}  // namespace

namespace {

Spec ParseSpecText(const std::string& text, const std::string& source) {
  Reader reader(source);
  YAML::Node root;
  try {
    root = YAML::Load(text);
    // A second document ('---') is refused, not dropped (an empty one, as
    // a trailing '---' makes, is harmless).
    if (const std::optional<YAML::Mark> second = SecondDocumentMark(text))
      reader.Fail(*second, "",
                  "a second YAML document ('---'): a spec is one document (give its "
                  "experiments in one list, or one spec per file)");
  } catch (const YAML::ParserException& e) {
    std::ostringstream out;
    out << source << ":" << e.mark.line + 1 << ":" << e.mark.column + 1 << ": " << e.msg;
    // yaml-cpp says "illegal block entry" or the like for a tab it met in
    // the indentation: YAML indents with spaces only.
    if (e.mark.line >= 0 && IndentationHasATab(text, e.mark.line))
      out << " (line " << e.mark.line + 1 << " is indented with a tab: YAML indents with spaces)";
    else if (e.msg == "bad file")
      out << " (nested too deeply?)";
    throw SpecError(out.str());
  }
  if (!root || root.IsNull()) throw SpecError(source + ": empty spec");
  reader.CheckDocument(root, "");
  reader.CheckKeys(root, "",
                   {"name", "description", "timeout_s", "memory_limit_mb", "record", "seeds",
                    "repetitions", "experiments", "algorithms", "problems"});
  if (root["description"]) reader.Scalar(root["description"], "description");  // free text
  if (root["name"]) reader.ExperimentName(root["name"], "name");  // the spec's, checked either way
  const double timeout = root["timeout_s"] ? reader.Timeout(root["timeout_s"], "timeout_s") : 600;
  const double memory = root["memory_limit_mb"]
                            ? reader.MemoryLimit(root["memory_limit_mb"], "memory_limit_mb")
                            : kDefaultMemoryLimitMb;
  const bool record_steps = root["record"] ? reader.RecordSteps(root["record"], "record") : true;
  const std::vector<std::uint64_t> seeds = reader.Seeds(root, "", {1});
  Spec spec;
  spec.file = source;
  std::set<std::string> seen;
  if (const YAML::Node experiments = root["experiments"]) {
    if (root["algorithms"] || root["problems"])
      reader.Fail(root, "", "give 'experiments' or top-level 'algorithms'/'problems', not both");
    if (!experiments.IsSequence() || experiments.size() == 0)
      reader.Fail(experiments, "experiments", "expected a non-empty list");
    std::map<std::string, std::string> names;  // experiment name -> where it was given
    for (std::size_t i = 0; i < experiments.size(); ++i) {
      const YAML::Node e = experiments[i];
      const std::string where = "experiments[" + std::to_string(i) + "]";
      reader.CheckKeys(e, where,
                       {"name", "description", "algorithms", "problems", "seeds", "repetitions",
                        "timeout_s", "memory_limit_mb", "record"});
      if (e["description"]) reader.Scalar(e["description"], where + ".description");
      const std::string name =
          e["name"] ? reader.ExperimentName(e["name"], where + ".name") : "experiment" + std::to_string(i + 1);
      // Runs are stored under SPEC#name: two experiments of one name would mix.
      const auto [it, inserted] = names.emplace(name, where);
      if (!inserted)
        reader.Fail(e["name"] ? e["name"] : e, where + ".name",
                    "experiment '" + name + "' is already the name of " + it->second);
      const double t = e["timeout_s"] ? reader.Timeout(e["timeout_s"], where + ".timeout_s") : timeout;
      const double mem = e["memory_limit_mb"]
                             ? reader.MemoryLimit(e["memory_limit_mb"], where + ".memory_limit_mb")
                             : memory;
      const bool record =
          e["record"] ? reader.RecordSteps(e["record"], where + ".record") : record_steps;
      reader.Experiment(e, where, name, t, mem, record, reader.Seeds(e, where, seeds), &spec,
                        &seen);
    }
  } else {
    if (!root["algorithms"] && !root["problems"])
      reader.Fail(root, "", "a spec needs 'experiments' (a list of them), or 'algorithms' and "
                            "'problems' for one experiment");
    const std::string name = root["name"] ? reader.ExperimentName(root["name"], "name") : "main";
    reader.Experiment(root, "", name, timeout, memory, record_steps, seeds, &spec, &seen);
  }
  return spec;
}

}  // namespace

Spec ParseSpec(const std::string& text, const std::string& source) {
  try {
    return ParseSpecText(text, source);
  } catch (const YAML::Exception& e) {
    // A yaml-cpp error the reader did not foresee still names the file.
    std::ostringstream out;
    out << source;
    if (e.mark.line >= 0) out << ":" << e.mark.line + 1 << ":" << e.mark.column + 1;
    out << ": " << e.msg;
    throw SpecError(out.str());
  }
}

Spec LoadSpec(const std::string& path) { return ParseSpec(ReadSpecText(path), path); }

std::string ReadSpecText(const std::string& path) {
  // An ifstream opens a directory and then reads nothing ("empty spec").
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SpecError(path + ": is a directory");
  // A device (/dev/zero) would be read until memory runs out; a pipe ends
  // (`run <(make-spec)`), so it is read.
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_character_file(status) || std::filesystem::is_block_file(status) ||
      std::filesystem::is_socket(status))
    throw SpecError(path + ": is a device or a socket, not a spec file");
  std::ifstream in(path);
  if (!in) throw SpecError(path + ": cannot read the spec file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace icp
