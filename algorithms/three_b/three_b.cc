#include "algorithms/three_b/three_b.h"

#include <algorithm>
#include <cmath>

namespace icp {

void Describe(ShavingParams& p, ParamSet& set) {
  set.Add("slices", &p.slices, "slices per bound (slice width = domain width / slices)",
          Range::Closed(1, 100000));
  set.Add("ratio", &p.ratio, "relative width decrease that starts another shaving round",
          Range::HalfOpen(0, 1));
  set.Add("epsilon", &p.epsilon, "smallest relative slice width (bound precision)",
          Range::Positive(1));
  set.Add("max_rounds", &p.max_rounds, "shaving rounds allowed per contraction",
          Range::AtLeast(1));
  set.Add("warm_start", &p.warm_start,
          "start a trial from the same bound's previous trial when its slice lies inside");
}

ThreeBContractor::ThreeBContractor(std::string name, std::unique_ptr<Contractor> inner,
                                   const ShavingParams& params)
    : name_(std::move(name)), inner_(std::move(inner)), params_(params) {}

bool ThreeBContractor::Trial(const Box& box, int var, const Interval& slice, LastTrial& last,
                             ContractContext& inner_context, WorkCounters& work) {
  trial_ = box;
  trial_[var] = slice;
  changed_.assign(1, var);
  if (params_.warm_start && !last.slice.IsEmpty() && slice.IsSubsetOf(last.slice)) {
    // last.result holds every solution with var in last.slice, and box has
    // only shrunk since: every solution sought lies in it.
    changed_.clear();
    for (int i = 0; i < static_cast<int>(trial_.size()); ++i) {
      trial_[i] = Intersect(trial_[i], last.result[i]);
      if (trial_[i].IsEmpty()) {
        last.slice = Interval::Empty();
        return false;
      }
      if (i == var || !(trial_[i] == last.result[i])) changed_.push_back(i);
    }
  }
  inner_context.SetChanged(changed_);
  ++work.inner_calls;
  const ContractSummary s = inner_->Contract(trial_, inner_context);
  work += s.work;
  // A stopped contraction is sound but maybe short of a fixpoint, which the
  // next start from it would take it for.
  const bool usable = s.status != ContractStatus::kEmpty && s.status != ContractStatus::kStopped;
  last.slice = usable ? slice : Interval::Empty();
  if (usable) last.result = trial_;
  return s.status != ContractStatus::kEmpty;
}

bool ThreeBContractor::Shave(Box& box, int var, bool left, ContractContext& inner_context,
                             WorkCounters& work) {
  Interval x = box[var];
  if (!x.IsBounded()) return true;  // an infinite side cannot be sliced
  const double slice_width = x.Width() / params_.slices;
  if (slice_width <= params_.epsilon * std::max(1.0, x.Mag())) return true;
  LastTrial& last = last_trials_[2 * var + (left ? 0 : 1)];
  for (int k = 0; k < params_.slices && !inner_context.stop().ShouldStop(); ++k) {
    const bool last_slice = k == params_.slices - 1;
    Interval slice =
        left ? Interval(x.lo(), last_slice ? x.hi() : std::min(x.hi(), x.lo() + slice_width))
             : Interval(last_slice ? x.lo() : std::max(x.lo(), x.hi() - slice_width), x.hi());
    if (Trial(box, var, slice, last, inner_context, work)) {
      // Every solution with x in the slice lies in trial_, so none is
      // beyond trial_'s bound on this side.
      x = left ? Interval(trial_[var].lo(), x.hi()) : Interval(x.lo(), trial_[var].hi());
      box[var] = x;
      return true;
    }
    if ((left && slice.hi() >= x.hi()) || (!left && slice.lo() <= x.lo())) return false;
    x = left ? Interval(slice.hi(), x.hi()) : Interval(x.lo(), slice.lo());
    box[var] = x;
  }
  return true;
}

ContractSummary ThreeBContractor::Contract(Box& box, ContractContext& context) {
  ContractSummary summary;
  const Box start = box;
  auto fail = [&](ContractStatus status, const std::string& message) {
    if (status == ContractStatus::kEmpty) box.SetEmpty();
    summary.status = status;
    summary.message = message;
    return summary;
  };
  ContractSummary first = inner_->Contract(box, context);
  ++summary.work.inner_calls;
  summary.work += first.work;
  if (first.status == ContractStatus::kEmpty) return fail(ContractStatus::kEmpty, "");
  // Box is now at a fixpoint of the inner contractor, up to its precision;
  // each shave and each spread of new bounds changes one variable of it.
  ContractContext inner_context(context.stop());
  last_trials_.assign(2 * box.size(), LastTrial());  // trials of another box say nothing here
  for (int round = 0; round < params_.max_rounds; ++round) {
    bool shrank = false;
    for (int var = 0; var < static_cast<int>(box.size()); ++var) {
      if (context.stop().ShouldStop())
        return fail(ContractStatus::kStopped, "stopped (time limit)");
      const Interval before = box[var];
      if (!Shave(box, var, true, inner_context, summary.work) ||
          !Shave(box, var, false, inner_context, summary.work))
        return fail(ContractStatus::kEmpty, "");
      if (!ShrankByMoreThan(before, box[var], params_.ratio)) continue;
      shrank = true;
      // Spread the new bounds before shaving the next variable.
      inner_context.SetChanged(std::span(&var, 1));
      ++summary.work.inner_calls;
      ContractSummary s = inner_->Contract(box, inner_context);
      summary.work += s.work;
      if (s.status == ContractStatus::kEmpty) return fail(ContractStatus::kEmpty, "");
    }
    if (!shrank) break;
  }
  summary.status = StatusOf(start, box);
  return summary;
}

namespace {
template <class InnerParams, class Inner>
std::unique_ptr<Contractor> MakeThreeB(const std::string& name, const ParamMap& params,
                                       const ConstraintSystem& csp) {
  auto p = ParseParams<ThreeBParams<InnerParams>>(name, params);
  auto inner = std::make_unique<Inner>(std::make_shared<CompiledSystem>(csp), p.inner);
  return std::make_unique<ThreeBContractor>(name, std::move(inner), p.shaving);
}
}  // namespace

std::unique_ptr<Contractor> MakeThreeBBC4(const ParamMap& params, const ConstraintSystem& csp) {
  return MakeThreeB<BC4Params, BC4Contractor>("3b-bc4", params, csp);
}

std::unique_ptr<Contractor> MakeThreeBHC4(const ParamMap& params, const ConstraintSystem& csp) {
  return MakeThreeB<HC4Params, HC4Contractor>("3b-hc4", params, csp);
}

}  // namespace icp
