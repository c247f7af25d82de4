// The adapter that turns any CSP contractor into an estimator (DESIGN.md
// "Estimator over contractor"): at each step it contracts the CSP view's
// window and returns the newest state's box. It owns the sliding-window
// memory: with `carry`, states that the previous window also held start from
// the previous result (matched by StateRef, never by position):
//   none   every window starts from its measurements alone;
//   first  the window's oldest state starts from the previous result (paper
//          000 §4.3), the others from their measurements;
//   all    every state the two windows share (a filter that forgets nothing).
// An empty previous result (the track was lost) carries nothing.
// Landmarks (states that do not move, StateRef::landmark) are kept for the
// whole run, not only from the previous window: unless carry is none, a
// landmark's domain starts from its last result in any earlier window (a
// static landmark's true position never moves, so its earlier box still
// holds it: paper 004's DIGO keeps landmark domains across windows).
//
// With local = true it is paper 004's LIC instead of its DIGO: of the
// window it solves only the newest step's ICSPs (CspView::icsps), each alone:
// the motion ICSPs first (the prediction), then every observation ICSP from
// that predicted box, the results intersected. The other constraints of the
// window are not used. A view without ICSPs counts each constraint as one.
//
// Every step reports the estimate of every landmark so far
// (StepResult::landmarks).
//
// Each step also reports the window's oldest state's box (post_step,
// post_<name>_lo/hi: paper 004's post-localization, the last report for a
// state being its final box) and the mean x-y area of the window's states
// (window_mean_area).
//
// Sound when the contractor is: a carried interval holds every solution of
// the previous window, so intersecting it keeps every solution of this one.
#ifndef ICPBENCH_ALGORITHMS_WINDOW_WINDOW_ESTIMATOR_H_
#define ICPBENCH_ALGORITHMS_WINDOW_WINDOW_ESTIMATOR_H_

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/estimator.h"
#include "core/constraint_system.h"
#include "core/view.h"
#include "core/params.h"

namespace icp {

using ContractorFactory = std::unique_ptr<Contractor> (*)(const ParamMap&, const ConstraintSystem&);

enum class Carry { kNone, kFirst, kAll };

// The parameters of a windowed contractor: the contractor's own, at the top
// level, and `carry`.
template <class ContractorParams>
struct WindowParams {
  ContractorParams contractor;
  std::string carry = "first";
};
void DescribeCarry(std::string* carry, ParamSet& set);
template <class ContractorParams>
void Describe(WindowParams<ContractorParams>& p, ParamSet& set) {
  Describe(p.contractor, set);
  DescribeCarry(&p.carry, set);
}

// The domain of a state that starts from `carried` (the previous result)
// instead of `fresh` (its measurements): their intersection, taken modulo
// `period` for a periodic component (a heading), in carried's frame.
Interval CarryInto(const Interval& fresh, const Interval& carried, double period);

// Paper 004's LIC as a contractor: the motion ICSPs in turn (the
// prediction), then every other ICSP alone from the predicted box, by the
// contractor make_contractor builds for it; the results intersected. Sound
// when that contractor is: the intersection of boxes that each keep every
// solution keeps every solution.
class LocalIcspContractor : public Contractor {
 public:
  LocalIcspContractor(ContractorFactory make_contractor, ParamMap contractor_params,
                      const ConstraintSystem& csp, std::vector<CspView::Icsp> icsps);
  std::string_view Name() const override { return "lic"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  std::vector<std::unique_ptr<Contractor>> motions_;
  std::vector<std::unique_ptr<Contractor>> observations_;
};

// The ICSPs LIC solves at a step: those of the view's newest step; without
// ICSPs in the view, every constraint as one.
std::vector<CspView::Icsp> NewestIcsps(const CspView& view);

class WindowEstimator : public Estimator {
 public:
  // contractor_params: the contractor's own parameters (carry removed).
  WindowEstimator(ContractorFactory make_contractor, ParamMap contractor_params, Carry carry,
                  bool local = false);
  StepResult Step(const Views& views, const StopCondition& stop) override;
  Properties RunProperties() const override { return WorkProperties(total_work_); }

 private:
  // The initial box: the view's domains with the carried states.
  Box InitialBox(const CspView& view, const StateSpace& space) const;

  ContractorFactory make_contractor_;
  ParamMap contractor_params_;
  Carry carry_;
  bool local_;
  std::vector<StateRef> previous_states_;  // sorted, as windows are
  Box previous_box_;                        // empty: nothing to carry
  std::map<StateRef, Interval> landmarks_;  // every landmark state's last result
  WorkCounters total_work_;
};

// A CSP algorithm's parameters without `carry`: the contractor's own.
ParamMap ContractorParams(const ParamMap& params);
Carry ParseCarry(const std::string& text);  // "none" | "first" | "all"

// The registry's entry points for a contractor with parameters P made by F.
template <class P, ContractorFactory F>
std::unique_ptr<Estimator> MakeWindowEstimator(const ParamMap& params, std::uint64_t /*seed*/) {
  const WindowParams<P> parsed = ParseParams<WindowParams<P>>("window", params);
  return std::make_unique<WindowEstimator>(F, ContractorParams(params), ParseCarry(parsed.carry));
}

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_WINDOW_WINDOW_ESTIMATOR_H_
