#include "harness/landmark_metrics.h"

#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace icp {

std::map<int, std::array<double, 6>> LandmarkBoxesOf(const Properties& properties) {
  std::map<int, std::array<double, 6>> out;
  for (const Property& p : properties) {
    int n = 0;
    char axis = 0;
    char end[3] = {};
    if (std::sscanf(p.name.c_str(), "L%d_%c_%2s", &n, &axis, end) != 3) continue;
    const std::string which(end);
    if ((axis != 'x' && axis != 'y' && axis != 'z') || (which != "lo" && which != "hi")) continue;
    const std::optional<double> v = NumberProperty({p}, p.name);
    if (!v) continue;
    auto [it, inserted] = out.try_emplace(n);
    if (inserted) it->second.fill(std::numeric_limits<double>::quiet_NaN());
    it->second[2 * (axis - 'x') + (which == "hi")] = *v;
  }
  return out;
}

void LandmarkJudge::Judge(const Step& step, const std::map<int, Box>& landmarks,
                          Properties* out) {
  if (landmarks.empty() || !step.landmark_position) return;
  scored_ = step.scored_landmarks;
  std::int64_t contained = 0;
  for (const auto& [n, components] : landmarks) {
    const std::array<Interval, 3> box = step.landmark_position(components);
    last_[n] = box;
    const std::string prefix = "L" + std::to_string(n) + "_";
    const char* const axes[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      const bool empty = box[axis].IsEmpty();
      out->push_back({prefix + axes[axis] + "_lo", empty ? kInf : box[axis].lo()});
      out->push_back({prefix + axes[axis] + "_hi", empty ? -kInf : box[axis].hi()});
    }
    const auto truth = step.landmark_truth.find(n);
    if (truth == step.landmark_truth.end()) continue;
    truth_[n] = truth->second;
    bool held = true;
    for (int axis = 0; axis < 3; ++axis) held = held && box[axis].Contains(truth->second[axis]);
    out->push_back({prefix + "held", static_cast<std::int64_t>(held)});
    contained += held;
    held_ += held;
    ++judged_;
  }
  out->push_back({"landmarks", static_cast<std::int64_t>(landmarks.size())});
  out->push_back({"landmarks_contained", contained});
}

Properties LandmarkJudge::RunProperties() const {
  if (last_.empty()) return {};
  Properties out = {{"landmarks_mapped", static_cast<std::int64_t>(last_.size())},
                    {"landmarks_scored", static_cast<std::int64_t>(scored_.size())}};
  if (judged_ > 0)
    out.push_back({"landmark_consistency", static_cast<double>(held_) / static_cast<double>(judged_)});
  for (const auto& [n, t] : truth_) {
    const std::string prefix = "L" + std::to_string(n) + "_truth_";
    out.push_back({prefix + "x", t[0]});
    out.push_back({prefix + "y", t[1]});
    out.push_back({prefix + "z", t[2]});
  }
  if (scored_.empty()) return out;
  double volume = 0, width[3] = {0, 0, 0};
  for (int n : scored_) {
    const auto it = last_.find(n);
    double w[3];
    for (int axis = 0; axis < 3; ++axis) {
      // Never reported, or emptied (a failed run): no width to average.
      w[axis] = it == last_.end() || it->second[axis].IsEmpty() ? kInf : it->second[axis].Width();
      width[axis] += w[axis];
    }
    volume += w[0] == kInf || w[1] == kInf || w[2] == kInf ? kInf : w[0] * w[1] * w[2];
  }
  const double n = static_cast<double>(scored_.size());
  out.push_back({"mpv", volume / n});
  out.push_back({"mdw_x", width[0] / n});
  out.push_back({"mdw_y", width[1] / n});
  out.push_back({"mdw_z", width[2] / n});
  return out;
}

}  // namespace icp
