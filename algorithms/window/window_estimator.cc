#include "algorithms/window/window_estimator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>

#include "algorithms/contraction_check.h"

namespace icp {

void DescribeCarry(std::string* carry, ParamSet& set) {
  set.Add("carry", carry,
          "window states starting from the previous result: none, the oldest (first, paper "
          "000) or all shared ones",
          {"none", "first", "all"});
}

ParamMap ContractorParams(const ParamMap& params) {
  ParamMap out = params;
  out.erase("carry");
  return out;
}

Carry ParseCarry(const std::string& text) {
  if (text == "none") return Carry::kNone;
  if (text == "all") return Carry::kAll;
  if (text == "first") return Carry::kFirst;
  throw ParamError("carry = " + text + ": must be one of none|first|all");
}

Properties WorkProperties(const WorkCounters& work) {
  return {{"revise_calls", work.revise_calls},
          {"newton_steps", work.newton_steps},
          {"bisections", work.bisections},
          {"inner_calls", work.inner_calls}};
}

Interval CarryInto(const Interval& fresh, const Interval& carried, double period) {
  if (period <= 0) return Intersect(fresh, carried);
  // fresh + period Z covers the line: nothing to remove, and carried's frame
  // is kept.
  if (fresh.Width() >= period || carried.IsEmpty()) return carried;
  if (fresh.IsEmpty()) return fresh;
  if (!(carried.Width() < kInf)) return carried;
  // The hull of carried's intersections with the shifts of fresh it meets;
  // each shift is enclosed (a multiple of a rounded period is not exact).
  Interval out = Interval::Empty();
  const double first = std::floor((carried.lo() - fresh.hi()) / period) - 1;
  const double last = std::ceil((carried.hi() - fresh.lo()) / period) + 1;
  if (last - first > 1000) return carried;
  for (double m = first; m <= last; ++m)
    out = Hull(out, Intersect(carried, fresh + Interval(m) * Interval(period)));
  return out;
}

namespace {
// The oldest robot state's time in the view; -1 without robot states.
int OldestTime(const CspView& view) {
  int oldest = -1;
  for (const StateRef& s : view.states)
    if (!s.is_landmark() && (oldest < 0 || s.time < oldest)) oldest = s.time;
  return oldest;
}

// Paper 004 §4.2's post-localization and Fig. 2's second reading, as step
// properties: the box of the window's oldest state (post_step, its time, and
// post_<name>_lo/hi), which is the box that state keeps once the next window
// drops it, smoothed by every later measurement of its windows; and the mean
// x-y area of the window's states (window_mean_area). An empty box reports
// the oldest state empty (+inf, -inf) and no area.
void ReportWindowStates(const CspView& view, const StateSpace& space, const Box& box,
                        Properties* out) {
  const int oldest = OldestTime(view);
  if (oldest < 0) return;
  out->push_back({"post_step", static_cast<std::int64_t>(oldest)});
  const bool empty = box.IsEmpty();
  for (std::size_t i = 0; i < view.states.size(); ++i) {
    const StateRef& s = view.states[i];
    if (s.is_landmark() || s.time != oldest) continue;
    const std::string& name = space.names[s.component];
    out->push_back({"post_" + name + "_lo", empty ? kInf : box[i].lo()});
    out->push_back({"post_" + name + "_hi", empty ? -kInf : box[i].hi()});
  }
  if (empty || space.x < 0 || space.y < 0) return;
  // x and y of each state time, by position in the window.
  std::map<int, std::pair<int, int>> xy;
  for (std::size_t i = 0; i < view.states.size(); ++i) {
    const StateRef& s = view.states[i];
    if (s.is_landmark()) continue;
    auto [it, inserted] = xy.try_emplace(s.time, -1, -1);
    if (s.component == space.x) it->second.first = static_cast<int>(i);
    if (s.component == space.y) it->second.second = static_cast<int>(i);
  }
  double sum = 0;
  int count = 0;
  for (const auto& [time, ix_iy] : xy) {
    if (ix_iy.first < 0 || ix_iy.second < 0) continue;
    sum += (Interval(box[ix_iy.first].Width()) * Interval(box[ix_iy.second].Width())).hi();
    ++count;
  }
  if (count > 0) out->push_back({"window_mean_area", sum / count});
}
}  // namespace

LocalIcspContractor::LocalIcspContractor(ContractorFactory make_contractor,
                                         ParamMap contractor_params, const ConstraintSystem& csp,
                                         std::vector<CspView::Icsp> icsps) {
  for (const CspView::Icsp& icsp : icsps)
    (icsp.motion ? motions_ : observations_)
        .push_back(make_contractor(contractor_params, csp.WithConstraints(icsp.constraints)));
}

ContractSummary LocalIcspContractor::Contract(Box& box, ContractContext& context) {
  ContractSummary total;
  const Box initial = box;
  auto solve = [&](Contractor& c, Box& b) {
    ContractContext own(context.stop());
    const ContractSummary s = c.Contract(b, own);
    total.work += s.work;
    if (s.status == ContractStatus::kStopped) total.status = ContractStatus::kStopped;
  };
  for (auto& motion : motions_)
    if (!box.IsEmpty()) solve(*motion, box);
  const Box predicted = box;
  for (auto& observation : observations_) {
    if (box.IsEmpty()) break;
    Box b = predicted;
    solve(*observation, b);
    box = Intersect(box, b);
  }
  if (box.IsEmpty()) {
    box.SetEmpty();
    total.status = ContractStatus::kEmpty;
  } else if (total.status != ContractStatus::kStopped) {
    total.status = StatusOf(initial, box);
  }
  return total;
}

std::vector<CspView::Icsp> NewestIcsps(const CspView& view) {
  std::vector<CspView::Icsp> out;
  for (const CspView::Icsp& icsp : view.icsps)
    if (icsp.time == view.newest) out.push_back(icsp);
  if (view.icsps.empty())
    for (int c = 0; c < static_cast<int>(view.csp.constraints().size()); ++c)
      out.push_back({view.newest, false, {c}});
  return out;
}

WindowEstimator::WindowEstimator(ContractorFactory make_contractor, ParamMap contractor_params,
                                 Carry carry, bool local)
    : make_contractor_(make_contractor),
      contractor_params_(std::move(contractor_params)),
      carry_(carry),
      local_(local) {}

Box WindowEstimator::InitialBox(const CspView& view, const StateSpace& space) const {
  Box box = view.csp.domains();
  if (carry_ == Carry::kNone) return box;
  for (std::size_t i = 0; i < view.states.size(); ++i) {
    const StateRef& s = view.states[i];
    if (!s.is_landmark()) continue;
    // A landmark's components are intersected as they are: a problem gives
    // a landmark its domains in one frame from its first sighting on.
    const auto it = landmarks_.find(s);
    if (it != landmarks_.end()) box[i] = Intersect(box[i], it->second);
  }
  if (previous_box_.size() == 0) return box;
  const int oldest = OldestTime(view);
  for (std::size_t i = 0; i < view.states.size(); ++i) {
    const StateRef& s = view.states[i];
    if (s.is_landmark() || s.time >= view.newest || (carry_ == Carry::kFirst && s.time != oldest)) continue;
    const auto it = std::lower_bound(previous_states_.begin(), previous_states_.end(), s);
    if (it == previous_states_.end() || !(*it == s)) continue;
    box[i] = CarryInto(box[i], previous_box_[it - previous_states_.begin()],
                       space.Period(s.component));
  }
  return box;
}

StepResult WindowEstimator::Step(const Views& views, const StopCondition& stop) {
  const CspView& view = *views.csp;
  Box box = InitialBox(view, views.space);
  const Box initial = box;
  std::unique_ptr<Contractor> contractor =
      local_ ? std::make_unique<LocalIcspContractor>(make_contractor_, contractor_params_, view.csp,
                                                     NewestIcsps(view))
             : ComposeWithCspView(make_contractor_(contractor_params_, view.csp), view);
  StepResult result;
  const auto start = std::chrono::steady_clock::now();
  ContractContext context(stop);
  result.summary = contractor->Contract(box, context);
  result.solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (std::string why = InvalidContractionReason(initial, box, view.csp.names()); !why.empty())
    throw InvalidResult(why);
  total_work_ += result.summary.work;
  result.properties = WorkProperties(result.summary.work);
  ReportWindowStates(view, views.space, box, &result.properties);

  Box newest = NewestState(view, box, views.space.size());
  if (box.IsEmpty()) newest.SetEmpty();
  result.estimate = std::make_unique<BoxEstimate>(std::move(newest));

  previous_states_ = view.states;
  if (!std::is_sorted(previous_states_.begin(), previous_states_.end()))
    throw std::invalid_argument("the CSP view's states are not in StateRef's order");
  if (!box.IsEmpty()) {
    for (std::size_t i = 0; i < view.states.size(); ++i)
      if (view.states[i].is_landmark()) landmarks_[view.states[i]] = box[i];
  }
  // landmarks_ is in StateRef order: each landmark's components in turn.
  for (const auto& [state, interval] : landmarks_) result.landmarks[state.landmark].push_back(interval);
  previous_box_ = box.IsEmpty() ? Box() : std::move(box);
  return result;
}

}  // namespace icp
