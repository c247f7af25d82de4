#include "algorithms/landmark_tracking/landmark_tracking.h"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "algorithms/landmark_tracking/belief_association.h"
#include "algorithms/registry.h"
#include "core/polar_sighting.h"

namespace icp {

void Describe(LandmarkTrackingParams& p, ParamSet& set) {
  set.Add("inner", &p.inner, "the CSP contractor that propagates a match (hc3, hc4, bc4, ...)");
  set.Add("association", &p.association,
          "how a track picks its return: belief (Fig. 6 masses, Royère fusion, pignistic "
          "decision) or first (the first consistent return)",
          {"belief", "first"});
  set.Add("track_timeout", &p.track_timeout,
          "steps a track survives without a match before it is dropped", Range::Closed(0, 1000));
}

void Describe(DeadReckoningParams&, ParamSet&) {}

namespace {

using WorldBox = std::array<Interval, 2>;

double Width(const Interval& x) { return x.hi() - x.lo(); }

// Paper 002 §3.5's criterion: the share of the track's box that the
// return's box covers, in percent.
double OverlapPercent(const WorldBox& observation, const WorldBox& track) {
  const Interval x = Intersect(observation[0], track[0]);
  const Interval y = Intersect(observation[1], track[1]);
  if (x.IsEmpty() || y.IsEmpty()) return 0;
  const double area = Width(track[0]) * Width(track[1]);
  return area > 0 ? 100 * Width(x) * Width(y) / area : 100;
}

const LandmarkObservationView& ViewOf(const Views& views) {
  if (!views.landmark_observations)
    throw std::invalid_argument("the step offers no landmark-observations view");
  return *views.landmark_observations;
}

Box PoseOf(const Box& box, const std::array<int, 3>& at) {
  return Box({box[at[0]], box[at[1]], box[at[2]]});
}

// The pose with x and y cut to the prior's (the map's bounds: the robot is on
// the map); the heading is left as it is, unwrapped.
Box WithinPrior(Box pose, const Box& prior) {
  pose[0] = Intersect(pose[0], prior[0]);
  pose[1] = Intersect(pose[1], prior[1]);
  return pose;
}

// The step's CSP (eq. 5-7 and every match's eq. 10-11 so far) and its box.
struct StepCsp {
  ConstraintSystem csp;
  Box box;
  std::array<int, 3> pose{0, 1, 2};  // the new pose's variables
};

// The CSP of a step: the previous pose, the odometry and the new pose, or
// the prior alone at the start.
StepCsp PredictionCsp(const Box& previous, const LandmarkObservationView& view, bool restart) {
  StepCsp s;
  if (restart || !view.odometry) {
    s.csp.AddVariable("x", view.prior[0]);
    s.csp.AddVariable("y", view.prior[1]);
    s.csp.AddVariable("theta", view.prior[2]);
  } else {
    const Box predicted = WithinPrior(PredictPose(previous, *view.odometry), view.prior);
    std::array<Expr, 3> from = {s.csp.AddVariable("x0", previous[0]),
                                s.csp.AddVariable("y0", previous[1]),
                                s.csp.AddVariable("theta0", previous[2])};
    std::array<Expr, 3> to = {s.csp.AddVariable("x", predicted[0]),
                              s.csp.AddVariable("y", predicted[1]),
                              s.csp.AddVariable("theta", predicted[2])};
    s.pose = {3, 4, 5};
    AddWheelOdometry(s.csp, from, to, *view.odometry, "");
  }
  s.box = s.csp.domains();
  return s;
}

class LandmarkTracker : public Estimator {
 public:
  LandmarkTracker(ContractorFactory inner, bool belief, int track_timeout)
      : inner_(inner), belief_(belief), track_timeout_(track_timeout) {}
  StepResult Step(const Views& views, const StopCondition& stop) override;
  Properties RunProperties() const override {
    return {{"restarts", restarts_}, {"cancelled_matches", cancelled_total_}};
  }

 private:
  struct Track {
    int landmark = 0;
    int type = 0;
    WorldBox box;  // where its last return was (eq. 8-9, after the match)
    int missed = 0;
  };

  // Adds the return's eq. 10-11 with landmark l and propagates; keeps them
  // when the box stays non-empty.
  bool TryMatch(StepCsp& s, const PolarObservation& o, const TypedLandmark& l,
                const StopCondition& stop);
  // The return track t follows, -1 for none (§3.5), among the returns not
  // associated yet (associations[i] < 0).
  int Follow(StepCsp& s, const Track& t, const std::vector<PolarObservation>& observations,
             const std::vector<int>& associations, const StopCondition& stop);

  const TypedLandmark& Landmark(int id) const { return (*map_)[index_of_.at(id)]; }

  ContractorFactory inner_;
  bool belief_;
  std::shared_ptr<const std::vector<TypedLandmark>> map_;
  std::map<int, std::size_t> index_of_;  // a landmark's place in map_ by identity
  int track_timeout_;
  std::vector<Track> tracks_;
  Box pose_;
  bool started_ = false;
  WorkCounters work_;
  int cancelled_ = 0;
  std::int64_t cancelled_total_ = 0;
  std::int64_t restarts_ = 0;
};

bool LandmarkTracker::TryMatch(StepCsp& s, const PolarObservation& o, const TypedLandmark& l,
                               const StopCondition& stop) {
  ConstraintSystem trial = s.csp;
  AddPolarSighting(trial, trial.Var(s.pose[0]), trial.Var(s.pose[1]), trial.Var(s.pose[2]), l.x,
                   l.y, o);
  Box box = s.box;
  ContractContext context(stop);
  work_ += inner_({}, trial)->Contract(box, context).work;
  if (box.IsEmpty()) return false;
  s.csp = std::move(trial);
  s.box = std::move(box);
  return true;
}

int LandmarkTracker::Follow(StepCsp& s, const Track& t,
                            const std::vector<PolarObservation>& observations,
                            const std::vector<int>& associations, const StopCondition& stop) {
  const Box pose = PoseOf(s.box, s.pose);
  std::vector<int> frame;
  std::vector<double> overlap;
  for (int i = 0; i < static_cast<int>(observations.size()); ++i) {
    if (associations[i] >= 0 || observations[i].type != t.type) continue;
    frame.push_back(i);
    overlap.push_back(OverlapPercent(SightingWorldBox(pose, observations[i]), t.box));
  }
  if (belief_) {
    // Beyond kMaxObservations returns of one type, the best overlaps.
    while (static_cast<int>(frame.size()) > kMaxObservations) {
      const auto worst = std::min_element(overlap.begin(), overlap.end()) - overlap.begin();
      frame.erase(frame.begin() + worst);
      overlap.erase(overlap.begin() + worst);
    }
    std::vector<OverlapMasses> triplets;
    for (double o : overlap) triplets.push_back(MassesFromOverlap(o));
    const int chosen = DecideByBelief(triplets).observation;
    if (chosen < 0) return -1;
    const int i = frame[chosen];
    const TypedLandmark& l = Landmark(t.landmark);
    if (TryMatch(s, observations[i], l, stop)) return i;
    ++cancelled_;
    return -1;
  }
  for (std::size_t j = 0; j < frame.size(); ++j) {
    if (overlap[j] <= 0) continue;
    if (TryMatch(s, observations[frame[j]], Landmark(t.landmark), stop)) return frame[j];
    ++cancelled_;
  }
  return -1;
}

StepResult LandmarkTracker::Step(const Views& views, const StopCondition& stop) {
  const LandmarkObservationView& view = ViewOf(views);
  if (!view.map) throw std::invalid_argument("the landmark-observations view has no map");
  if (view.map != map_) {
    map_ = view.map;
    index_of_.clear();
    for (std::size_t i = 0; i < map_->size(); ++i) index_of_[(*map_)[i].id] = i;
  }
  work_ = WorkCounters();
  cancelled_ = 0;
  const std::vector<PolarObservation>& observations = view.observations;
  const int n = static_cast<int>(observations.size());

  // The prediction (eq. 5-7), propagated once; from the prior at the start
  // or after a loss.
  const bool restart = !started_ || pose_.IsEmpty();
  if (started_ && restart) ++restarts_;
  if (restart) tracks_.clear();
  StepCsp s = PredictionCsp(pose_, view, restart);
  {
    ContractContext context(stop);
    work_ += inner_({}, s.csp)->Contract(s.box, context).work;
  }
  started_ = true;

  std::vector<int> associations(n, -1);  // the landmark of each return, -1 none yet
  auto accept = [&](int i, int landmark) {
    associations[i] = landmark;
    return SightingWorldBox(PoseOf(s.box, s.pose), observations[i]);
  };
  auto associated = [&](int landmark) {
    return std::find(associations.begin(), associations.end(), landmark) != associations.end();
  };

  // Following the tracks (§3.5).
  if (!s.box.IsEmpty()) {
    for (Track& t : tracks_) {
      const int i = Follow(s, t, observations, associations, stop);
      if (i < 0) {
        ++t.missed;
        continue;
      }
      t.box = accept(i, t.landmark);
      t.missed = 0;
    }
    std::erase_if(tracks_, [&](const Track& t) { return t.missed > track_timeout_; });
  }

  // Starting tracks (§3.4): the landmarks of the return's type inside its
  // world box, in map order, the first consistent one.
  for (int i = 0; i < n && !s.box.IsEmpty(); ++i) {
    if (associations[i] >= 0) continue;
    const WorldBox world = SightingWorldBox(PoseOf(s.box, s.pose), observations[i]);
    for (const TypedLandmark& l : *map_) {
      if (l.type != observations[i].type || associated(l.id)) continue;
      if (!world[0].Contains(l.x) || !world[1].Contains(l.y)) continue;
      if (!TryMatch(s, observations[i], l, stop)) continue;
      const WorldBox box = accept(i, l.id);
      auto existing = std::find_if(tracks_.begin(), tracks_.end(),
                                   [&](const Track& t) { return t.landmark == l.id; });
      if (existing != tracks_.end()) {
        existing->box = box;
        existing->missed = 0;
      } else {
        tracks_.push_back({l.id, l.type, box, 0});
      }
      break;
    }
  }

  pose_ = PoseOf(s.box, s.pose);
  cancelled_total_ += cancelled_;
  StepResult result;
  result.estimate = std::make_unique<BoxEstimate>(pose_);
  result.summary.work = work_;
  result.properties = WorkProperties(work_);
  result.properties.push_back({"tracks", static_cast<std::int64_t>(tracks_.size())});
  const auto unmatched = std::count(associations.begin(), associations.end(), -1);
  result.properties.push_back({"matched", static_cast<std::int64_t>(n - unmatched)});
  result.properties.push_back({"cancelled_matches", static_cast<std::int64_t>(cancelled_)});
  result.associations = std::move(associations);
  if (pose_.IsEmpty()) result.summary.status = ContractStatus::kEmpty;
  return result;
}

// Odometry alone: the pose box through eq. 5-7, step after step.
class DeadReckoning : public Estimator {
 public:
  StepResult Step(const Views& views, const StopCondition&) override {
    const LandmarkObservationView& view = ViewOf(views);
    pose_ = started_ && view.odometry ? WithinPrior(PredictPose(pose_, *view.odometry), view.prior)
                                      : view.prior;
    started_ = true;
    StepResult result;
    result.estimate = std::make_unique<BoxEstimate>(pose_);
    return result;
  }

 private:
  Box pose_;
  bool started_ = false;
};

}  // namespace

ParamMap ResolveLandmarkTracking(const std::string& owner, const ParamMap& values) {
  const ParamMap resolved = ResolveParams<LandmarkTrackingParams>(owner, values);
  InnerContractorFactory(owner, resolved.at("inner"));
  return resolved;
}

std::unique_ptr<Estimator> MakeLandmarkTracking(const ParamMap& params, std::uint64_t /*seed*/) {
  const auto p = ParseParams<LandmarkTrackingParams>("landmark-tracking", params);
  return std::make_unique<LandmarkTracker>(InnerContractorFactory("landmark-tracking", p.inner),
                                           p.association == "belief", p.track_timeout);
}

std::unique_ptr<Estimator> MakeDeadReckoning(const ParamMap& params, std::uint64_t /*seed*/) {
  ParseParams<DeadReckoningParams>("dead-reckoning", params);
  return std::make_unique<DeadReckoning>();
}

}  // namespace icp
