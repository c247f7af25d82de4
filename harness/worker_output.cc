#include "harness/worker_output.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string_view>
#include <type_traits>
#include <variant>

#include "core/estimate.h"
#include "core/rounding.h"
#include "harness/metrics.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nlohmann::json D(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}
double D(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "inf") return kInf;
  if (s == "-inf") return -kInf;
  return kNaN;
}

nlohmann::json PropertiesToJson(const Properties& properties) {
  nlohmann::json out = nlohmann::json::array();
  for (const Property& p : properties) {
    nlohmann::json value;
    std::visit([&](const auto& v) {
      if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>) value = D(v); else value = v;
    }, p.value);
    out.push_back({p.name, TypeName(p), value});
  }
  return out;
}

Properties PropertiesFromJson(const nlohmann::json& j) {
  Properties out;
  for (const auto& p : j) {
    const std::string type = p.at(1).get<std::string>();
    Property prop{p.at(0).get<std::string>(), std::int64_t{0}};
    if (type == "int") prop.value = p.at(2).get<std::int64_t>();
    else if (type == "real") prop.value = D(p.at(2));
    else prop.value = p.at(2).get<std::string>();
    out.push_back(std::move(prop));
  }
  return out;
}

nlohmann::json StepToJson(const StepRecord& s) {
  nlohmann::json vars = nlohmann::json::array();
  for (const VariableRecord& v : s.vars) vars.push_back({v.name, D(v.lo), D(v.hi), D(v.truth)});
  return {s.step, s.status, vars, s.contained, D(s.area), D(s.centre_error),
          D(s.solve_time_s), s.estimate, PropertiesToJson(s.properties)};
}

StepRecord StepFromJson(const nlohmann::json& s) {
  StepRecord sr;
  sr.step = s.at(0).get<int>();
  sr.status = s.at(1).get<std::string>();
  for (const auto& v : s.at(2)) sr.vars.push_back({v.at(0).get<std::string>(), D(v.at(1)), D(v.at(2)), D(v.at(3))});
  sr.contained = s.at(3).get<int>();
  sr.area = D(s.at(4));
  sr.centre_error = D(s.at(5));
  sr.solve_time_s = D(s.at(6));
  sr.estimate = s.at(7).get<std::string>();
  sr.properties = PropertiesFromJson(s.at(8));
  return sr;
}

nlohmann::json MetricsToJson(const RunMetrics& m) {
  nlohmann::json corridors = nlohmann::json::array();
  for (const Corridor& c : m.corridors)
    corridors.push_back({c.var, D(c.mean_lower), D(c.mean_upper), D(c.min_lower), D(c.max_upper)});
  return {m.steps, D(m.mean_area), D(m.consistency_rate), D(m.centre_rmse), D(m.time_mean_s),
          D(m.time_median_s), D(m.time_p90_s), D(m.time_mean_ci_lo_s), D(m.time_mean_ci_hi_s),
          corridors};
}

RunMetrics MetricsFromJson(const nlohmann::json& j) {
  RunMetrics m;
  m.steps = j.at(0).get<int>();
  double* fields[] = {&m.mean_area, &m.consistency_rate, &m.centre_rmse, &m.time_mean_s,
                      &m.time_median_s, &m.time_p90_s, &m.time_mean_ci_lo_s, &m.time_mean_ci_hi_s};
  for (std::size_t i = 0; i < std::size(fields); ++i) *fields[i] = D(j.at(i + 1));
  for (const auto& c : j.at(9))
    m.corridors.push_back({c.at(0).get<std::string>(), D(c.at(1)), D(c.at(2)), D(c.at(3)), D(c.at(4))});
  return m;
}

std::string Dump(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

std::string SerializeSummary(const RunRecord& r) {
  return Dump({{"status", ToString(r.status)}, {"reason", r.reason},
               {"wall_time_s", D(r.wall_time_s)}, {"metrics", MetricsToJson(r.metrics)},
               {"properties", PropertiesToJson(r.properties)}});
}

RunRecord DeserializeSummary(const std::string& text, const RunSpec& spec) {
  const nlohmann::json j = nlohmann::json::parse(text);
  RunRecord r;
  r.spec = spec;
  r.status = ParseRunStatus(j.at("status").get<std::string>());
  r.reason = j.at("reason").get<std::string>();
  r.wall_time_s = D(j.at("wall_time_s"));
  r.metrics = MetricsFromJson(j.at("metrics"));
  r.properties = PropertiesFromJson(j.at("properties"));
  return r;
}

std::string UnreadableWorkerOutput(const std::string& what) {
  return "invalid result: unreadable worker output (" + what + ")";
}

StepFileWriter::StepFileWriter(const std::string& path)
    : path_(path), file_(std::fopen(path.c_str(), "we")) {
  if (file_ == nullptr) Fail();
}

StepFileWriter::~StepFileWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void StepFileWriter::Write(const StepRecord& s) {
  const std::string line = Dump(StepToJson(s)) + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size()) Fail();
  // Each step reaches the file before the next one starts: a worker that
  // crashes or hangs and is killed loses none of its finished steps
  // (RecoverStepFile keeps them). One write a step costs the 20,000 steps of
  // a car-track lap under 0.1 s.
  if (std::fflush(file_) != 0) Fail();
}

void StepFileWriter::Close() {
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) Fail();
}

void StepFileWriter::Fail() const {
  throw std::runtime_error("cannot write the step file " + path_ + ": " + std::strerror(errno));
}

RunMetrics RecoverStepFile(const std::string& path, std::uint64_t seed) {
  std::fstream file(path, std::ios::in | std::ios::binary);
  if (!file) return RunMetrics{};
  MetricsAccumulator metrics;
  std::uintmax_t kept_bytes = 0;
  std::string line;
  // A line is kept only if it ends in a newline and parses: the one the
  // kill cut short is neither.
  while (std::getline(file, line) && !file.eof()) {
    try {
      metrics.Add(StepFromJson(nlohmann::json::parse(line)));
    } catch (const std::exception&) {
      break;
    }
    kept_bytes += line.size() + 1;
  }
  file.close();
  std::error_code ec;
  std::filesystem::resize_file(path, kept_bytes, ec);
  if (ec) return RunMetrics{};
  return metrics.Finish(seed);
}

StepSource ReadStepFile(const std::string& path, int count) {
  auto in = std::make_shared<std::ifstream>(path);
  if (!*in) throw WorkerOutputError("cannot open the step file " + path);
  return [in, path, count, read = 0](StepRecord* step) mutable {
    std::string line;
    if (!std::getline(*in, line)) {
      if (read != count)
        throw WorkerOutputError("the step file " + path + " holds " + std::to_string(read) +
                                " steps, the run " + std::to_string(count));
      return false;
    }
    try {
      *step = StepFromJson(nlohmann::json::parse(line));
    } catch (const std::exception& e) {
      throw WorkerOutputError("step file " + path + " line " + std::to_string(read + 1) + ": " + e.what());
    }
    ++read;
    return true;
  };
}

namespace {
constexpr std::string_view kStepFilePrefix = ".steps-";
constexpr std::string_view kStepFileSuffix = ".ndjson";
}  // namespace

std::string StepFilePath(const std::string& dir, const std::string& tag) {
  return (std::filesystem::path(dir) / (std::string(kStepFilePrefix) + std::to_string(getpid()) + "-" +
                                        tag + std::string(kStepFileSuffix)))
      .string();
}

void RemoveStaleStepFiles(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(kStepFilePrefix) && name.ends_with(kStepFileSuffix))
      std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace icp
