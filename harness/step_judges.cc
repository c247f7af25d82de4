#include "harness/step_judges.h"

#include <utility>

namespace icp {

void StepJudges::Judge(const Step& step, TakenStep* taken) {
  StepResult& result = taken->result;
  StepRecord& r = taken->record;
  post_states_.Judge(step, &result.properties);
  coverage_.Add(step, *result.estimate, &result.properties);
  landmarks_.Judge(step, result.landmarks, &result.properties);
  associations_.Judge(step, result.associations, r.contained, &result.properties);
  for (Property& p : result.properties) r.properties.push_back(std::move(p));
  result.properties.clear();
  for (const Property& p : step.annotations) r.properties.push_back(p);
  for (Property& p : result.estimate->Extras()) r.properties.push_back(std::move(p));
  if (!result.summary.message.empty()) r.properties.push_back({"message", result.summary.message});
  guarantee_.Judge(&r);
}

Properties StepJudges::RunProperties() const {
  Properties out = guarantee_.RunProperties();
  coverage_.AppendRunProperties(&out);
  for (Property& p : landmarks_.RunProperties()) out.push_back(std::move(p));
  for (Property& p : associations_.RunProperties()) out.push_back(std::move(p));
  return out;
}

}  // namespace icp
