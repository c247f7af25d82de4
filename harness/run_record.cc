#include "harness/run_record.h"

#include <stdexcept>

namespace icp {

namespace {

// The characters that structure a key; each is written with a backslash in
// front when it occurs inside a name or value, as is the backslash itself, so
// a key parses back to exactly one spec and two specs never share a key.
constexpr std::string_view kKeySpecials = "\\{}=,|";

void AppendEscaped(std::string_view text, std::string* out) {
  for (char c : text) {
    if (kKeySpecials.find(c) != std::string_view::npos) out->push_back('\\');
    out->push_back(c);
  }
}

void AppendPlugin(std::string_view name, const ParamMap& params, std::string* out) {
  AppendEscaped(name, out);
  out->push_back('{');
  bool first = true;
  for (const auto& [key, value] : params) {  // std::map: sorted by key
    if (!first) out->push_back(',');
    first = false;
    AppendEscaped(key, out);
    out->push_back('=');
    AppendEscaped(value, out);
  }
  out->push_back('}');
}

}  // namespace

std::string RunSpec::Key() const {
  std::string key;
  AppendPlugin(algorithm, algorithm_params, &key);
  key.push_back('|');
  AppendPlugin(problem, problem_params, &key);
  key += "|seed=";
  key += std::to_string(seed);
  return key;
}

std::string_view ToString(RunStatus status) {
  switch (status) {
    case RunStatus::kOk:
      return "ok";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kTimeout:
      return "timeout";
    case RunStatus::kSkipped:
      return "skipped";
  }
  return "unknown";
}

RunStatus ParseRunStatus(std::string_view text) {
  for (RunStatus s : {RunStatus::kOk, RunStatus::kFailed, RunStatus::kTimeout, RunStatus::kSkipped}) {
    if (text == ToString(s)) return s;
  }
  throw std::invalid_argument("run status '" + std::string(text) +
                              "': must be one of ok|failed|timeout|skipped");
}

std::string ExperimentOf(const std::string& spec_file) {
  const std::size_t hash = spec_file.rfind('#');
  return hash == std::string::npos ? "" : spec_file.substr(hash + 1);
}

}  // namespace icp
