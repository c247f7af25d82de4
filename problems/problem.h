// A problem is a seeded stream of steps with their truth (DESIGN.md): a
// localization problem yields one step per time step, a static one a single
// step. Each step offers views (core/view.h) to the estimators; a problem
// never sees what an estimator made of them.
#ifndef ICPBENCH_PROBLEMS_PROBLEM_H_
#define ICPBENCH_PROBLEMS_PROBLEM_H_

#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/view.h"

namespace icp {

struct Step {
  Views views;
  // The true state of the step, one value per component of views.space;
  // empty when unknown. A periodic component (a heading) is unwrapped: any
  // representative modulo its period is the same state.
  std::vector<double> truth;
  // With a CSP view: the truth of every CSP variable, in the frame of the
  // view's domains (a solution of the CSP inside them); empty when unknown.
  // For tests that check a contractor keeps the truth.
  std::vector<double> csp_truth;
  // What the problem reports of the step beside its truth, recorded with
  // the step's properties (e.g. car-track's GPS box in use, gps_x_lo ...,
  // for paper 000's Fig. 3); for reports and figures, never for estimators.
  Properties annotations;
  // Landmarks (states that do not move, StateRef::Landmark): the true
  // position of each, by identity, and how a landmark's components (a Box
  // in StateRef's component order) give its position box (paper 004 eq.
  // 12). For the landmark metrics (held, MPV, MDW), never for estimators;
  // empty and unset without landmarks.
  std::map<int, std::array<double, 3>> landmark_truth;
  std::function<std::array<Interval, 3>(const Box&)> landmark_position;
  // The landmarks the map metrics (MPV, MDW) average over: those the drive
  // can locate (paper 004 averages over "the converged landmarks"; which
  // ones is the problem's to say, from the truth, so that every estimator
  // is scored on the same ones).
  std::vector<int> scored_landmarks;
  // With a landmark-observation view: the landmark (TypedLandmark::id) each
  // observation truly comes from, -1 for a spurious return. For the
  // association metrics, never for estimators; empty without that view.
  std::vector<int> observation_truth;
};

class Problem {
 public:
  virtual ~Problem() = default;
  virtual std::string_view Name() const = 0;
  // Fills step with the next step and returns true, or returns false when
  // the stream is over.
  virtual bool Next(Step* step) = 0;
  // Number of steps the stream will yield, for progress reports.
  virtual int NumSteps() const = 0;
  // A hint before the first step: the estimator reads only this view, so a
  // problem may leave out the others where they cost (car-track's window CSP
  // under a particle filter). Without it every view is made.
  virtual void ServeOnly(View needed) { static_cast<void>(needed); }
};

// A static problem: one step, made when it is asked for.
class SingleStepProblem : public Problem {
 public:
  SingleStepProblem(std::string name, std::function<Step()> make)
      : name_(std::move(name)), make_(std::move(make)) {}
  std::string_view Name() const override { return name_; }
  int NumSteps() const override { return 1; }
  bool Next(Step* step) override {
    if (done_) return false;
    done_ = true;
    *step = make_();
    return true;
  }

 private:
  std::string name_;
  std::function<Step()> make_;
  bool done_ = false;
};

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_PROBLEM_H_
