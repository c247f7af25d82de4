// What an estimator consumes of a problem's step (DESIGN.md "A problem is a
// stream of steps with their truth, offering views"):
//   - the CSP view, for ICP: constraints over a window of states, each
//     variable tagged with the state and time step it stands for;
//   - the measurement-set view, for the relaxed solvers: a prior box and one
//     contractor per measurement, some of which may be outliers;
//   - the probabilistic view, for the particle filter: a prior and a motion
//     model to sample, a measurement likelihood to weigh with;
//   - the landmark-observation view, for estimators that associate sensor
//     returns with a map themselves (paper 002): the map of typed
//     landmarks, the step's odometry and its typed polar returns.
// A problem offers some of them at every step; an algorithm needs one. The
// harness records a pair whose views do not meet as skipped.
#ifndef ICPBENCH_CORE_VIEW_H_
#define ICPBENCH_CORE_VIEW_H_

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/box.h"
#include "core/constraint_system.h"
#include "core/contractor.h"
#include "core/estimate.h"
#include "core/random.h"

namespace icp {

enum class View { kCsp, kMeasurementSet, kProbabilistic, kLandmarkObservations };
// "csp", "measurement-set", "probabilistic", "landmark-observations": the
// words of `icpbench list`.
std::string_view ToString(View view);

// The state a CSP variable stands for (DESIGN.md "States that do not move
// have their own identity"): component `component` of the robot's state at
// time step `time` (absolute, so the same state in two windows has the same
// identity), or, with landmark >= 0, component `component` of landmark
// `landmark`'s parameters, a state that does not move (time is then 0).
// Ordered robot states first, by (time, component), then landmarks, by
// (landmark, component): a CSP view lists its states in this order.
struct StateRef {
  static constexpr int kRobot = -1;
  int time = 0;
  int component = 0;
  int landmark = kRobot;

  static StateRef Landmark(int landmark, int component) { return {0, component, landmark}; }
  bool is_landmark() const { return landmark != kRobot; }

  friend bool operator==(const StateRef&, const StateRef&) = default;
  friend auto operator<=>(const StateRef& a, const StateRef& b) {
    if (auto order = a.landmark <=> b.landmark; order != 0) return order;
    if (auto order = a.time <=> b.time; order != 0) return order;
    return a.component <=> b.component;
  }
};

struct CspView {
  // Its domains come from the measurements alone: nothing of an earlier
  // step's result is in them (an estimator carries that itself).
  ConstraintSystem csp;
  // One per CSP variable, in StateRef's order.
  std::vector<StateRef> states;
  // The time step whose state the step estimates (the window's newest).
  int newest = 0;
  // Constraints that are not expressions (a road map through the image
  // contractor), as contractors over csp's variables, each sound for its
  // constraint. An ICP algorithm contracts the CSP and these in turn to a
  // fixpoint (ComposeWithCspView); empty for most problems.
  std::vector<std::shared_ptr<Contractor>> extra_contractors;
  // The CSP as a graph of small ICSPs (paper 004 eq. 20-21), for estimators
  // that solve them one at a time (lic): each is what one motion or one
  // observation adds, its time step and its constraints (indices into
  // csp.constraints()). Empty when the problem does not group them.
  struct Icsp {
    int time = 0;
    bool motion = false;
    std::vector<int> constraints;
  };
  std::vector<Icsp> icsps;
};

// The contractor an ICP algorithm runs on a CSP view: csp_contractor alone
// when the view has no extra contractors, else the fixpoint of csp_contractor
// followed by each extra one (a component shrinking by less than 1 % of its
// width stops it; at most kCspViewFixpointIterations rounds). Sound when
// every part is.
inline constexpr int kCspViewFixpointIterations = 50;
std::unique_ptr<Contractor> ComposeWithCspView(std::unique_ptr<Contractor> csp_contractor,
                                               const CspView& view);

// The newest state's components of box, a box over view.csp's variables:
// one interval per component of a `size`-component state space. Throws
// std::invalid_argument when the view lacks a newest-state variable for some
// component (a problem's bug).
Box NewestState(const CspView& view, const Box& box, int size);

struct MeasurementSetView {
  // The search box: every component of the state.
  Box prior;
  // One contractor per measurement, each sound for its own measurement: it
  // never removes a state consistent with it.
  std::vector<std::shared_ptr<Contractor>> measurements;
  // Which measurements are outliers (inconsistent with the truth), when the
  // truth is known; empty otherwise. For metrics, never for estimators.
  std::vector<bool> outliers;
  // Which source (robot, sensor) made each measurement, numbered from 0, for
  // solvers that fuse per-source results (the distributed accumulator of
  // paper 003 §5.2.3); empty: one source.
  std::vector<int> sources;
  // For a stream of steps (a moving robot): a box enclosing every state of
  // this step reachable from a state of `previous`, a box of the previous
  // step's states (sound bounded-error motion); unset at the first step and
  // for static problems. A solver running as a filter intersects prior with
  // predict(its previous hull).
  std::function<Box(const Box& previous)> predict;
};

// A state drawn here may carry hidden components after the state space's
// (a sensor's bias the motion corrects): a filter carries them along and
// reports the space's components only.
struct ProbabilisticView {
  // Draws a state from the prior of the first step.
  std::function<std::vector<double>(RandomEngine&)> sample_prior;
  // Moves a state from the previous step to this one by a draw of the motion
  // model (identity at the first step).
  std::function<void(std::vector<double>& state, RandomEngine&)> sample_motion;
  // Log-likelihood of this step's measurements given a state, up to a
  // constant. Called concurrently from several threads (a filter weighs its
  // particles in parallel), so it must not write shared state.
  std::function<double(const std::vector<double>& state)> log_likelihood;
  // Draws a state from this step's global prior (anywhere the robot may be,
  // the past ignored), for the particles a filter injects to recover from a
  // wrong convergence (paper 003 §6.7); unset: nothing to inject from.
  std::function<std::vector<double>(RandomEngine&)> sample_global;
  // The regularisation this model needs, >= 0: after each resampling a
  // filter moves every particle's state-space components by a uniform draw
  // of standard deviation roughen times the weighted cloud's in that
  // component (a narrow motion model with a box likelihood leaves few
  // distinct particles otherwise); 0 for none. particle-filter's `roughen`
  // parameter overrides it.
  double roughen = 0;
};

// A point landmark of a map with a type (paper 002: corner, edge, other).
struct TypedLandmark {
  int id = 0;  // its identity, as the associations name it
  int type = 0;
  double x = 0, y = 0;  // m
};

// One return of a range-and-bearing sensor: its type and its polar
// coordinates in the robot's frame (bearing counterclockwise from the
// heading, rad), each an interval holding the true value when the return
// comes from a landmark (a spurious return comes from none).
struct PolarObservation {
  int type = 0;
  Interval range, bearing;
};

// A differential drive's odometry over one step (paper 002 §3.3): the wheel
// radii and the track width (m) and the wheels' rotations over the step
// (rad), each an interval holding the true value. The displacement is
// d = (R_r w_r + R_l w_l) / 2 and the turn (R_r w_r - R_l w_l) / L.
struct WheelOdometry {
  Interval right_radius, left_radius, track, right_rotation, left_rotation;
};

// Typed returns not yet associated with landmarks: the association is the
// estimator's job. The state is (x, y, heading).
struct LandmarkObservationView {
  // Step 0: the known start box; later steps: every pose the robot may be
  // in (the map's bounds, any heading), for an estimator that lost track.
  Box prior;
  // The motion from the previous step; unset at step 0.
  std::optional<WheelOdometry> odometry;
  // In the order the sensor reports them (by bearing).
  std::vector<PolarObservation> observations;
  // The map: every landmark the returns may come from, and the name of each
  // type (index = TypedLandmark::type).
  std::shared_ptr<const std::vector<TypedLandmark>> map;
  std::vector<std::string> type_names;
};

// Everything an estimator may see of a step. The truth is not here.
struct Views {
  int step = 0;
  StateSpace space;
  std::optional<CspView> csp;
  std::optional<MeasurementSetView> measurement_set;
  std::optional<ProbabilisticView> probabilistic;
  std::optional<LandmarkObservationView> landmark_observations;
  bool Offers(View view) const;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_VIEW_H_
