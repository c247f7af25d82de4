#include "harness/association_metrics.h"

#include <stdexcept>
#include <string>

namespace icp {

void AssociationJudge::Judge(const Step& step,
                             const std::optional<std::vector<int>>& estimated, int contained,
                             Properties* out) {
  // Nothing to score: an estimator that does not associate, no view to
  // associate, or no truth.
  if (!estimated || !step.views.landmark_observations) return;
  const std::vector<int>& truth = step.observation_truth;
  if (truth.size() != step.views.landmark_observations->observations.size()) return;
  const std::vector<int>& associations = *estimated;
  if (associations.size() != truth.size())
    throw std::invalid_argument("step " + std::to_string(step.views.step) + ": " +
                                std::to_string(associations.size()) + " associations for " +
                                std::to_string(truth.size()) + " returns");
  std::int64_t right = 0, wrong = 0, missed = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (associations[i] < 0) {
      if (truth[i] >= 0) ++missed;
    } else if (associations[i] == truth[i]) {
      ++right;
    } else {
      ++wrong;
    }
  }
  judged_ = true;
  right_ += right;
  wrong_ += wrong;
  missed_ += missed;
  if (wrong > 0) {
    all_right_ = false;
    ++wrong_steps_;
    if (contained == 0) ++wrong_losses_;
  }
  out->push_back({"associations_right", right});
  out->push_back({"associations_wrong", wrong});
  out->push_back({"associations_missed", missed});
  out->push_back({"assumption_held", std::int64_t{all_right_ ? 1 : 0}});
}

Properties AssociationJudge::RunProperties() const {
  if (!judged_) return {};
  return {{"associations_right", right_},
          {"associations_wrong", wrong_},
          {"associations_missed", missed_},
          {"wrong_association_steps", wrong_steps_},
          {"wrong_association_losses", wrong_losses_}};
}

}  // namespace icp
