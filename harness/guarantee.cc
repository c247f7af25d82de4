#include "harness/guarantee.h"

#include <string>

#include "harness/metrics.h"

namespace icp {

void LossEpisodes::Add(int contained) {
  if (contained < 0) return;
  ++judged_;
  if (contained == 0) {
    if (!lost_) ++episodes_, length_ = 0;
    lost_ = true;
    ++length_;
    return;
  }
  if (lost_) reacquire_steps_.push_back(length_);
  lost_ = false;
}

namespace {

std::string Count(double v) { return std::to_string(static_cast<long long>(v)); }

}  // namespace

void GuaranteeJudge::Judge(StepRecord* step) {
  const bool was_lost = episodes_.lost();
  episodes_.Add(step->contained);
  const std::optional<double> bound = NumberProperty(step->properties, "q_bound");
  const std::optional<double> truth = NumberProperty(step->properties, "true_outliers");
  if (!bound || !truth || step->contained < 0) return;
  const std::optional<double> tracked = NumberProperty(step->properties, "tracked");
  if (!tracked || *tracked == 0) held_since_restart_ = true;
  const bool held_here = *truth <= *bound;
  held_since_restart_ = held_since_restart_ && held_here;
  step->properties.push_back({"assumption_held", std::int64_t{held_since_restart_ ? 1 : 0}});
  if (step->contained != 0) return;
  const std::optional<double> q = NumberProperty(step->properties, "q");
  std::string category, detail;
  if (!held_here) {
    category = "assumption violated";
    detail = Count(*truth) + " true outliers > q_bound " + Count(*bound);
  } else if (q && *q < *truth) {
    category = "auto_q under-counted outliers";
    detail = "q=" + Count(*q) + ", true " + Count(*truth);
  } else if (was_lost && !episode_category_.empty()) {
    category = episode_category_;  // the loss this step carries on
    detail = "since step " + std::to_string(episode_start_) + ": " + episode_detail_;
  } else if (!held_since_restart_) {
    category = "assumption violated";
    detail = "at an earlier step since the last restart";
  } else {
    category = "unexplained";
    detail =
        "assumption held, q=" + (q ? Count(*q) : std::string("?")) + " >= true " + Count(*truth);
  }
  if (!was_lost) {
    episode_category_ = category;
    episode_detail_ = detail;
    episode_start_ = step->step;
  }
  step->properties.push_back({"miss_reason", category + " (" + detail + ")"});
}

Properties GuaranteeJudge::RunProperties() const {
  Properties out;
  if (episodes_.judged() == 0) return out;
  out.push_back({"loss_episodes", std::int64_t{episodes_.episodes()}});
  if (!episodes_.reacquire_steps().empty())
    out.push_back({"reacquire_steps_median", Quantile(episodes_.reacquire_steps(), 0.5)});
  return out;
}

std::string MissCategory(const std::string& reason) { return reason.substr(0, reason.find(" (")); }

std::optional<double> RunRestarts(const RunRecord& r) {
  if (auto n = NumberProperty(r.properties, "resets")) return n;
  return NumberProperty(r.properties, "reinitialisations");
}

}  // namespace icp
