// GET /api/runs/ID/steps/N/estimate: the estimate of a stored run at step N,
// which the store does not keep (a paving's boxes, an accumulator's counts, a
// particle cloud; issue 34). The server re-runs the run's definition (its
// algorithm, problem, effective parameters and seed, as ExecuteRun does) in
// its own process up to step N, within a time limit, and says whether the
// re-run's hull equals the stored step's (matches_store). The store is only
// read.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>

#include "algorithms/registry.h"
#include "harness/runner.h"
#include "harness/results_store_internal.h"
#include "problems/registry.h"
#include "web/api.h"

namespace icp::web {

namespace {

constexpr double kTimeLimitS = 10;        // a re-run longer than this is a 503
// Re-runs at once at most: the rest of the server's threads stay free for
// the quick answers (ten slow re-runs had made a summary wait 9 s).
constexpr int kMaxReruns = 2;
std::atomic<int> reruns_in_flight{0};
constexpr std::size_t kMaxBoxes = 5000;   // a paving's boxes sent, inner first
constexpr int kMaxCells = 200;            // an accumulator image's rows and columns
constexpr int kMaxParticles = 2000;       // particles sent

// The definition of a stored run, to be re-run.
struct StoredRun {
  std::string algorithm, problem, status;
  ParamMap algorithm_params, problem_params;
  std::uint64_t seed = 0;
};

StoredRun LoadRun(const StoreReader& store, const std::string& id) {
  Query q(store,
          "SELECT algorithm, algorithm_params, problem, problem_params, seed, status FROM runs "
          "WHERE id = ?",
          {id});
  if (!q.Step()) throw HttpError(404, "no run with id " + id);
  auto text = [&](int i) {
    const unsigned char* t = sqlite3_column_text(q.stmt(), i);
    return t == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(t));
  };
  StoredRun run;
  run.algorithm = text(0);
  run.algorithm_params = detail::ParamsFromJson(text(1), store.path());
  run.problem = text(2);
  run.problem_params = detail::ParamsFromJson(text(3), store.path());
  run.seed = static_cast<std::uint64_t>(sqlite3_column_int64(q.stmt(), 4));
  run.status = text(5);
  return run;
}

nlohmann::json Range(const Interval& v) { return {Number(v.lo()), Number(v.hi())}; }

// A box's x-y rectangle: [x lo, x hi, y lo, y hi].
nlohmann::json Rect(const Box& b, int x, int y) {
  return {Number(b[x].lo()), Number(b[x].hi()), Number(b[y].lo()), Number(b[y].hi())};
}

nlohmann::json Components(const Box& box, const StateSpace& space) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < box.size(); ++i)
    out.push_back({{"name", static_cast<int>(i) < space.size() ? space.names[i] : "v" + std::to_string(i)},
                   {"lo", Number(box[i].lo())}, {"hi", Number(box[i].hi())}});
  return out;
}

// The inner boxes, then the boundary ones, at most kMaxBoxes in all.
nlohmann::json PavingData(const PavingEstimate& p, int x, int y) {
  nlohmann::json inner = nlohmann::json::array(), boundary = nlohmann::json::array();
  std::size_t sent = 0;
  for (const Box& b : p.inner())
    if (sent++ < kMaxBoxes) inner.push_back(Rect(b, x, y));
  for (const Box& b : p.boundary())
    if (sent++ < kMaxBoxes) boundary.push_back(Rect(b, x, y));
  return {{"inner", inner}, {"boundary", boundary}, {"inner_count", p.inner().size()},
          {"boundary_count", p.boundary().size()}, {"truncated", sent > kMaxBoxes}};
}

// The counts, row r covering y, downsampled by block maxima to at most
// kMaxCells x kMaxCells.
nlohmann::json AccumulatorData(const AccumulatorEstimate& a) {
  const Grid& g = a.grid();
  const cv::Mat& counts = a.counts();
  const int fr = (g.rows() + kMaxCells - 1) / kMaxCells, fc = (g.cols() + kMaxCells - 1) / kMaxCells;
  const int rows = (g.rows() + fr - 1) / fr, cols = (g.cols() + fc - 1) / fc;
  nlohmann::json cells = nlohmann::json::array();
  for (int r = 0; r < rows; ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (int c = 0; c < cols; ++c) {
      double max = 0;
      cv::minMaxLoc(counts(cv::Range(r * fr, std::min(g.rows(), (r + 1) * fr)),
                           cv::Range(c * fc, std::min(g.cols(), (c + 1) * fc))),
                    nullptr, &max);
      row.push_back(static_cast<int>(max));
    }
    cells.push_back(row);
  }
  return {{"x", Range(g.search()[g.x()])}, {"y", Range(g.search()[g.y()])},
          {"grid_rows", g.rows()}, {"grid_cols", g.cols()}, {"rows", rows}, {"cols", cols},
          {"downsampled", fr > 1 || fc > 1}, {"threshold", a.threshold()}, {"counts", cells}};
}

// At most kMaxParticles particles, spread evenly over the cloud.
nlohmann::json ParticleData(const ParticleEstimate& p, int x, int y) {
  const cv::Mat& m = p.particles();
  const int n = std::min(kMaxParticles, m.rows);
  nlohmann::json xs = nlohmann::json::array(), ys = nlohmann::json::array(),
                 ws = nlohmann::json::array();
  for (int i = 0; i < n; ++i) {
    const int row = static_cast<int>(static_cast<long long>(i) * m.rows / n);
    xs.push_back(Number(m.at<double>(row, x)));
    ys.push_back(Number(m.at<double>(row, y)));
    ws.push_back(Number(p.weights()[row]));
  }
  return {{"x", xs}, {"y", ys}, {"weights", ws}, {"total", m.rows}, {"subsampled", n < m.rows}};
}

// The kind's own data; only the hull when the state has no x-y position.
nlohmann::json KindData(const Estimate& e, const StateSpace& space) {
  if (const auto* a = dynamic_cast<const AccumulatorEstimate*>(&e)) return AccumulatorData(*a);
  if (space.x < 0 || space.y < 0) return nlohmann::json::object();
  if (const auto* p = dynamic_cast<const PavingEstimate*>(&e)) return PavingData(*p, space.x, space.y);
  if (const auto* p = dynamic_cast<const ParticleEstimate*>(&e))
    return ParticleData(*p, space.x, space.y);
  return {{"box", Rect(e.Hull(), space.x, space.y)}};
}

bool SameDouble(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// Whether the re-run's step record has the stored step's variables and bounds.
bool MatchesStore(const StoreReader& store, const std::string& id, const std::string& step,
                  const StepRecord& rerun) {
  Query q(store, "SELECT var, lo, hi FROM step_values WHERE run_id = ? AND step = ? ORDER BY pos",
          {id, step});
  auto column = [&](int i) {
    return sqlite3_column_type(q.stmt(), i) == SQLITE_NULL ? NAN : sqlite3_column_double(q.stmt(), i);
  };
  std::size_t i = 0;
  for (; q.Step(); ++i) {
    if (i >= rerun.vars.size()) return false;
    const VariableRecord& v = rerun.vars[i];
    if (v.name != reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 0)) ||
        !SameDouble(v.lo, column(1)) || !SameDouble(v.hi, column(2)))
      return false;
  }
  return i == rerun.vars.size() && i > 0;
}

void GetEstimate(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  const std::string id = RunId(req);
  const std::string step_text = req.matches[2];
  const long long wanted = std::stoll(step_text);
  StoreReader store(dir);
  const StoredRun run = LoadRun(store, id);
  if (run.status != "ok")
    throw HttpError(400, "run " + id + " is " + run.status + ": only a run that finished is re-run");
  {
    Query q(store, "SELECT 1 FROM steps WHERE run_id = ? AND step = ?", {id, step_text});
    if (!q.Step()) throw HttpError(404, "run " + id + " has no step " + step_text);
  }
  if (run.algorithm_params.count("python") != 0)
    throw HttpError(422, "run " + id + " uses the Python-registered algorithm " + run.algorithm +
                             ", which the server cannot re-run");
  std::unique_ptr<Problem> problem;
  std::unique_ptr<Estimator> estimator;
  const AlgorithmInfo* algorithm = nullptr;
  try {
    problem = FindProblem(run.problem).make(run.problem_params, run.seed);
    algorithm = &FindAlgorithm(run.algorithm);
    estimator = algorithm->make(run.algorithm_params, run.seed);
  } catch (const std::exception& e) {
    throw HttpError(422, "run " + id + " cannot be re-run: " + e.what());
  }
  struct Slot {  // one of the kMaxReruns, held while this re-run lasts
    Slot() : taken(++reruns_in_flight <= kMaxReruns) {}
    ~Slot() { --reruns_in_flight; }
    bool taken;
  } slot;
  if (!slot.taken) {
    res.set_header("Retry-After", "5");
    throw HttpError(503, "the server is re-running " + std::to_string(kMaxReruns) +
                             " other runs: retry in a few seconds");
  }
  const auto start = std::chrono::steady_clock::now();
  const StopCondition stop = StopCondition::After(std::chrono::duration<double>(kTimeLimitS));
  const std::string too_long = "re-running run " + id + " to step " + step_text +
                               " takes longer than the server's limit of " +
                               FormatDouble(kTimeLimitS) + " s";
  Step step;
  while (problem->Next(&step)) {
    if (stop.ShouldStop()) throw HttpError(503, too_long);
    const TakenStep taken = TakeStep(*estimator, algorithm->needs, step, stop);
    if (taken.result.summary.status == ContractStatus::kStopped && stop.ShouldStop())
      throw HttpError(503, too_long);
    if (step.views.step < wanted) continue;
    if (step.views.step > wanted)
      throw HttpError(500, "the re-run of run " + id + " has no estimate at step " + step_text);
    const Estimate& e = *taken.result.estimate;
    const StateSpace& space = step.views.space;
    const StepRecord& record = taken.record;
    nlohmann::json truth = nlohmann::json::array();
    for (double t : step.truth) truth.push_back(Number(t));
    SendJson(res, {{"run_id", std::stoll(id)}, {"step", wanted}, {"kind", e.Kind()},
                   {"hull", Components(e.Hull(), space)}, {"x", space.x}, {"y", space.y},
                   {"truth", truth}, {"contained", record.contained < 0 ? nlohmann::json(nullptr) : nlohmann::json(record.contained)},
                   {"data", KindData(e, space)},
                   {"matches_store", MatchesStore(store, id, step_text, record)},
                   {"rerun_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()}});
    return;
  }
  throw HttpError(500, "the re-run of run " + id + " ended before step " + step_text);
}

}  // namespace

void RegisterEstimateApi(httplib::Server& server, const std::string& dir) {
  using namespace std::placeholders;
  server.Get(R"(/api/runs/([^/]*)/steps/(\d{1,9})/estimate)", std::bind(GetEstimate, dir, _1, _2));
}

}  // namespace icp::web
