#include "experiments/thesis003/marina_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <memory>
#include <tuple>
#include <utility>

#include "algorithms/registry.h"
#include "core/estimate.h"
#include "experiments/thesis003/marina.h"
#include "harness/metrics.h"
#include "harness/spec.h"
#include "problems/marina_sonar/marina_sonar.h"
#include "problems/registry.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kNone = "no ok run of experiment marina or marina-*";
constexpr const char* kTruthColour = "black";
constexpr const char* kBoxColour = "#e377c2";  // the thesis' pink boxes
constexpr const char* kCentreColour = "#d62728";
constexpr const char* kReckonedColour = "#1f77b4";
constexpr const char* kParticleColour = "#2ca02c";
// Boxes drawn: every 20th set-membership step (about a metre wide, drawn at
// every step they merge into one band; 20 steps apart, about 12 m, they
// stay apart on the printed page), every 50th dead-reckoning box (they
// grow, so fewer keep the drawing readable); particles: the whole first
// cloud, then 60 of every 10th step.
constexpr int kSetBoxesEvery = 20;
constexpr int kReckonedBoxesEvery = 50;
constexpr int kParticlesEvery = 10;
constexpr int kParticlesPerStep = 60;
constexpr double kFrameMargin = 10;  // m around what a frame shows

bool OfMarina(const RunRecord& r) { return IsMarinaExperiment(ExperimentOf(r)); }

std::string StartOf(const RunRecord& r) {
  const auto start = r.spec.problem_params.find("start");
  return start == r.spec.problem_params.end() ? ProblemDefaults(r.spec.problem)["start"]
                                              : start->second;
}

std::string Setting(const RunRecord& r) {
  const std::string params = CompactParams(r.spec.problem_params);
  return r.spec.problem + (params.empty() ? "" : " {" + params + "}") + ", seed " +
         std::to_string(r.spec.seed);
}

std::vector<double> BoxRow(const Interval& x, const Interval& y) {
  return {x.lo(), x.hi(), y.lo(), y.hi()};
}

const RunRecord* WithSteps(const std::vector<const RunRecord*>& drawn, bool particles) {
  for (const RunRecord* r : drawn)
    if (!r->steps.empty() && (r->spec.algorithm == "particle-filter") == particles) return r;
  return nullptr;
}

void SkipOrDraw(const FigureText& text, const std::vector<const RunRecord*>& drawn,
                const std::vector<MapPanel>& panels, int cols, const std::string& out_dir,
                PlotOutput* out) {
  if (panels.empty()) return SkipFigure(text, drawn, out);
  PlotMapFigure(text, panels, cols, out_dir, out);
}

}  // namespace

namespace {

// The configuration a marina claim judges (experiments/thesis003/claims.yaml).
bool Judged(const RunRecord& r) {
  const auto param = [&](const char* name) {
    const auto it = r.spec.algorithm_params.find(name);
    return it == r.spec.algorithm_params.end() ? std::string() : it->second;
  };
  if (r.spec.algorithm == "q-relaxed") return param("auto_q") == "false";
  if (r.spec.algorithm == "particle-filter") return param("inject") == "0";
  return true;
}

}  // namespace

std::vector<const RunRecord*> MarinaFigureRuns(const std::vector<RunRecord>& runs,
                                               const std::string& start) {
  // Runs with steps first; runs stored with `record: runs` only where no
  // run with steps takes their place, so that the figures can name them.
  auto drawable = [](const RunRecord& r) {
    return r.status == RunStatus::kOk && (!r.steps.empty() || RecordedRunsOnly(r));
  };
  const RunRecord* reference = nullptr;
  auto rank = [](const RunRecord& r) {
    return std::make_tuple(r.steps.empty(), ExperimentOf(r) != kThesis003Marina,
                           ExperimentOf(r) != kThesis003MarinaDrive, StartOf(r) != "known",
                           r.spec.seed);
  };
  for (const RunRecord& r : runs) {
    if (!drawable(r) || !OfMarina(r) || (!start.empty() && StartOf(r) != start)) continue;
    if (!reference || rank(r) < rank(*reference)) reference = &r;
  }
  std::vector<const RunRecord*> out;
  if (!reference) return out;
  // One run per algorithm: the configuration the claims judge (set
  // membership guaranteed, auto_q=false; the filter without injection),
  // chosen before the data are read; else the first in the store.
  for (const RunRecord& r : runs) {
    if (!drawable(r) || ExperimentOf(r) != ExperimentOf(*reference) ||
        r.spec.problem != reference->spec.problem ||
        r.spec.problem_params != reference->spec.problem_params ||
        r.spec.seed != reference->spec.seed)
      continue;
    auto same = std::find_if(out.begin(), out.end(), [&](const RunRecord* o) {
      return o->spec.algorithm == r.spec.algorithm;
    });
    if (same == out.end())
      out.push_back(&r);
    else if (std::make_pair(r.steps.empty(), !Judged(r)) <
             std::make_pair((*same)->steps.empty(), !Judged(**same)))
      *same = &r;
  }
  std::stable_sort(out.begin(), out.end(), [](const RunRecord* a, const RunRecord* b) {
    return AlgorithmLess(a->spec.algorithm, b->spec.algorithm);
  });
  return out;
}

MapFrame MarinaMapFrame(const ParamMap& problem_params) {
  const auto p = ParseParams<MarinaSonarParams>("marina-sonar", problem_params);
  const MarinaMap map = LoadMarinaMap(p.map.empty() ? ShippedMarinaMapPath() : p.map);
  MapFrame f;
  f.walls = map.image->pixels();
  f.origin_x = map.image->frame().origin_x;
  f.origin_y = map.image->frame().origin_y;
  f.pixel_size = map.image->frame().pixel_size;
  f.x = MapXBounds(f);
  f.y = MapYBounds(f);
  return f;
}

std::vector<Box> MarinaDeadReckoning(const RunRecord& run) {
  std::unique_ptr<Problem> problem =
      FindProblem(run.spec.problem).make(run.spec.problem_params, run.spec.seed);
  std::vector<Box> boxes;
  Step step;
  while (problem->Next(&step)) {
    const MeasurementSetView& m = *step.views.measurement_set;
    boxes.push_back(boxes.empty() || !m.predict ? m.prior : m.predict(boxes.back()));
  }
  return boxes;
}

ParticleReplay ReplayParticles(const RunRecord& run, int every, int per_step) {
  std::unique_ptr<Problem> problem =
      FindProblem(run.spec.problem).make(run.spec.problem_params, run.spec.seed);
  std::unique_ptr<Estimator> filter =
      FindAlgorithm(run.spec.algorithm).make(run.spec.algorithm_params, run.spec.seed);
  ParticleReplay out;
  Step step;
  while (problem->Next(&step)) {
    const int k = step.views.step;
    if (k == 0) out.prior = step.views.measurement_set->prior;
    const StepResult result = filter->Step(step.views, StopCondition());
    const auto* cloud = dynamic_cast<const ParticleEstimate*>(result.estimate.get());
    if (!cloud) throw std::invalid_argument(run.spec.algorithm + ": no particle estimate");
    out.means.push_back(cloud->Centre());
    if (k > 0 && k % every != 0) continue;
    const cv::Mat& p = cloud->particles();
    const int n = k == 0 ? p.rows : std::min(per_step, p.rows);
    for (int i = 0; i < n; ++i) {
      const int row = k == 0 ? i : i * p.rows / n;  // spread over the cloud
      (k == 0 ? out.first_cloud : out.later).push_back({p.at<double>(row, 0), p.at<double>(row, 1)});
    }
  }
  return out;
}

std::vector<std::vector<double>> TruthTrack(const RunRecord& run) {
  std::vector<std::vector<double>> track;
  for (const StepRecord& s : run.steps)
    if (s.vars.size() >= 2) track.push_back({s.vars[0].truth, s.vars[1].truth});
  return track;
}

MapPanel DeadReckoningPanel(const RunRecord& run, const std::vector<Box>& reckoned,
                            const MapFrame& map) {
  MapLayer boxes{MapLayer::Kind::kBoxes,
                 "dead-reckoning box (every " + std::to_string(kReckonedBoxesEvery) + "th step)",
                 kReckonedColour, {}};
  MapLayer centre{MapLayer::Kind::kTrack, "dead reckoning (box centre)", kReckonedColour, {}};
  for (std::size_t k = 0; k < reckoned.size(); ++k) {
    const Box& b = reckoned[k];
    centre.rows.push_back({b[0].Mid(), b[1].Mid()});
    if (k % kReckonedBoxesEvery == 0 || k + 1 == reckoned.size())
      boxes.rows.push_back(BoxRow(b[0], b[1]));
  }
  MapPanel panel{"Fig. 6.7: dead reckoning against the truth (" + Setting(run) + ")", map,
                 {boxes, centre, {MapLayer::Kind::kTrack, "truth", kTruthColour, TruthTrack(run)}}};
  FrameToShow(panel.layers, kFrameMargin, MapXBounds(map), MapYBounds(map), &panel.frame);
  return panel;
}

MapPanel SetMembershipPanel(const RunRecord& run, int boxes_every, const MapFrame& map) {
  MapLayer boxes{MapLayer::Kind::kBoxes,
                 boxes_every == 1 ? std::string("set-membership box (every step)")
                                  : "set-membership box (every " + std::to_string(boxes_every) +
                                        "th step)",
                 kBoxColour, {}};
  MapLayer centre{MapLayer::Kind::kTrack, "box centre", kCentreColour, {}};
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    const StepRecord& s = run.steps[k];
    if (s.vars.size() < 2 || IsEmptyEstimate(s)) {
      centre.rows.push_back({kNaN, kNaN});  // a gap where the set is empty
      continue;
    }
    const VariableRecord &x = s.vars[0], &y = s.vars[1];
    centre.rows.push_back({(x.lo + x.hi) / 2, (y.lo + y.hi) / 2});
    if (k % boxes_every == 0) boxes.rows.push_back({x.lo, x.hi, y.lo, y.hi});
  }
  MapPanel panel{"start=" + StartOf(run) + ": " + RunLabel(run) + ", consistency " +
                     FormatNumber(run.metrics.consistency_rate),
                 map,
                 {boxes, {MapLayer::Kind::kTrack, "truth", kTruthColour, TruthTrack(run)}, centre}};
  FrameToShow(panel.layers, kFrameMargin, MapXBounds(map), MapYBounds(map), &panel.frame);
  return panel;
}

MapPanel ParticlePanel(const RunRecord& run, const ParticleReplay& replay, const MapFrame& map) {
  MapLayer mean{MapLayer::Kind::kTrack, "weighted mean (stored)", kParticleColour, {}};
  for (const StepRecord& s : run.steps) {
    const std::optional<double> x = NumberProperty(s.properties, "mean_x");
    const std::optional<double> y = NumberProperty(s.properties, "mean_y");
    mean.rows.push_back({x ? *x : kNaN, y ? *y : kNaN});
  }
  const double area = replay.prior[0].Width() * replay.prior[1].Width();
  MapPanel panel{
      "Fig. 6.9: " + std::to_string(replay.first_cloud.size()) + " particles over " +
          FormatNumber(area) + " m², " + RunLabel(run) + "\n(" + Setting(run) + ")",
      map,
      {{MapLayer::Kind::kPoints,
        "particles, every " + std::to_string(kParticlesEvery) + "th step (sample)", "#9ad29a",
        replay.later},
       {MapLayer::Kind::kPoints, "particles, first step", "#ff7f0e", replay.first_cloud},
       {MapLayer::Kind::kBoxes, "prior", "#ff7f0e", {BoxRow(replay.prior[0], replay.prior[1])}},
       {MapLayer::Kind::kTrack, "truth", kTruthColour, TruthTrack(run)},
       mean}};
  FrameToShow(panel.layers, kFrameMargin, MapXBounds(map), MapYBounds(map), &panel.frame);
  return panel;
}

void MarinaFigures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                   PlotOutput* out) {
  const std::vector<const RunRecord*> drawn = MarinaFigureRuns(runs);
  const RunRecord* reference = WithSteps(drawn, false);
  if (!reference) reference = WithSteps(drawn, true);
  if (!reference) {  // none, or stored with `record: runs`: the messages say which
    for (const char* name : {"fig6_7_dead_reckoning", "fig6_8_marina_tracks", "fig6_9_particles",
                             "fig6_errors"})
      SkipFigure({name, "", kNone}, drawn, out);
    return;
  }
  MapFrame map;
  try {
    map = MarinaMapFrame(reference->spec.problem_params);
  } catch (const std::exception& e) {
    out->messages.push_back(std::string("marina figures: map not drawn: ") + e.what());
  }
  // Fig. 6.7.
  try {
    const MapPanel panel = DeadReckoningPanel(*reference, MarinaDeadReckoning(*reference), map);
    PlotMapFigure({"fig6_7_dead_reckoning", panel.title, kNone}, panel.frame, panel.layers,
                  out_dir, out);
  } catch (const std::exception& e) {
    out->messages.push_back(std::string("fig6_7_dead_reckoning: skipped: ") + e.what());
  }
  // Fig. 6.8: set membership, one panel per start.
  std::vector<MapPanel> panels;
  std::vector<const RunRecord*> named;
  for (const char* start : {"known", "area", "unknown"}) {
    const std::vector<const RunRecord*> at = MarinaFigureRuns(runs, start);
    named.insert(named.end(), at.begin(), at.end());
    if (const RunRecord* r = WithSteps(at, false))
      panels.push_back(SetMembershipPanel(*r, kSetBoxesEvery, map));
  }
  SkipOrDraw({"fig6_8_marina_tracks",
              "Fig. 6.8: set-membership boxes and centres against the truth from each start, "
              "the guaranteed configuration (auto_q=false) where the store has it",
              kNone},
             named, panels, 1, out_dir, out);
  // Fig. 6.9: the particle filter from the thesis' prior (else any start).
  const RunRecord* filter = WithSteps(MarinaFigureRuns(runs, "area"), true);
  if (!filter) filter = WithSteps(drawn, true);
  const FigureText particles{"fig6_9_particles", "",
                             "no ok particle-filter run of experiment marina or marina-*"};
  if (!filter) {
    SkipFigure(particles, drawn, out);
  } else {
    try {
      const MapPanel panel =
          ParticlePanel(*filter, ReplayParticles(*filter, kParticlesEvery, kParticlesPerStep), map);
      PlotMapFigure({particles.name, panel.title, particles.skip_reason}, panel.frame,
                    panel.layers, out_dir, out);
    } catch (const std::exception& e) {
      out->messages.push_back(particles.name + ": skipped: " + e.what());
    }
  }
  PlotCentreErrorFigure(
      {"fig6_errors", "Marina: centre error over time (" + Setting(*drawn[0]) + ")", kNone}, drawn,
      out_dir, out);
}

}  // namespace icp
