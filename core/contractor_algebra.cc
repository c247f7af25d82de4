#include "core/contractor_algebra.h"

#include <stdexcept>
#include <utility>
#include <vector>
#include <string>

#include "core/relaxed_intersection.h"

namespace icp {

namespace {
// Adds a part's summary to the total; true when the part ended the
// contraction (empty box or stop), with the total's status set.
bool Absorb(const ContractSummary& part, Box& box, ContractSummary& total) {
  total.work += part.work;
  if (part.status == ContractStatus::kEmpty) box.SetEmpty();
  if (part.status != ContractStatus::kEmpty && part.status != ContractStatus::kStopped) return false;
  total.status = part.status;
  total.message = part.message;
  return true;
}

// Each part applied to its own copy of box, into out (reused across calls,
// so its boxes keep their storage); a part the stop condition cut short, or
// never reached, leaves its copy as it was (sound). A part marked in
// `known_empty` is not applied: its box is left empty. Sets *stopped when
// the stop condition cut the pass short.
void ApplyEach(const SharedContractors& parts, const Box& box, ContractContext& context, WorkCounters& work,
               bool* stopped, std::vector<Box>& out, const std::vector<char>* known_empty = nullptr) {
  out.resize(parts.size());
  *stopped = false;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (known_empty && (*known_empty)[i]) {
      out[i].SetEmpty();
      continue;
    }
    out[i] = box;
    if (*stopped) continue;
    if (context.stop().ShouldStop()) {
      *stopped = true;
      continue;
    }
    ContractContext fresh(context.stop());
    const ContractSummary s = parts[i]->Contract(out[i], fresh);
    work += s.work;
    if (s.status == ContractStatus::kEmpty) out[i].SetEmpty();
    if (s.status == ContractStatus::kStopped) *stopped = true;
  }
}

// Writes result (a subset of box, by construction) into box and sets the
// summary's status.
void Finish(Box result, bool stopped, Box& box, ContractSummary& summary) {
  if (result.IsEmpty()) result.SetEmpty();
  const ContractStatus status = StatusOf(box, result);
  box = std::move(result);
  summary.status = stopped && !box.IsEmpty() ? ContractStatus::kStopped : status;
  if (summary.status == ContractStatus::kStopped) summary.message = "stopped before every part ran";
}
}  // namespace

ContractSummary SequenceContractor::Contract(Box& box, ContractContext& context) {
  const Box before = box;
  ContractSummary summary;
  ContractContext fresh(context.stop());
  for (std::size_t i = 0; i < parts_.size(); ++i)
    if (Absorb(parts_[i]->Contract(box, i == 0 ? context : fresh), box, summary)) return summary;
  summary.status = StatusOf(before, box);
  return summary;
}

ContractSummary FixpointContractor::Contract(Box& box, ContractContext& context) {
  const Box start = box;
  ContractSummary summary;
  ContractContext fresh(context.stop());
  for (int it = 0; it < max_iterations_; ++it) {
    const Box before = box;
    if (Absorb(inner_->Contract(box, it == 0 ? context : fresh), box, summary)) return summary;
    bool shrank = false;
    for (std::size_t i = 0; i < box.size() && !shrank; ++i)
      shrank = ShrankByMoreThan(before[i], box[i], ratio_);
    if (!shrank) break;
  }
  summary.status = StatusOf(start, box);
  return summary;
}

ContractSummary IntersectionContractor::Contract(Box& box, ContractContext& context) {
  ContractSummary summary;
  if (box.IsEmpty()) return {ContractStatus::kEmpty, "", {}};
  bool stopped = false;
  Box result = box;
  std::vector<Box> contracted;
  ApplyEach(parts_, box, context, summary.work, &stopped, contracted);
  for (const Box& b : contracted) result = Intersect(result, b);
  Finish(result, stopped, box, summary);
  return summary;
}

ContractSummary UnionContractor::Contract(Box& box, ContractContext& context) {
  ContractSummary summary;
  if (box.IsEmpty()) return {ContractStatus::kEmpty, "", {}};
  bool stopped = false;
  Box result(box.size());
  result.SetEmpty();
  std::vector<Box> contracted;
  ApplyEach(parts_, box, context, summary.work, &stopped, contracted);
  for (const Box& b : contracted) result = Hull(result, b);
  Finish(result, stopped, box, summary);
  return summary;
}

QIntersectionContractor::QIntersectionContractor(SharedContractors parts, int q)
    : parts_(std::move(parts)), q_(q) {
  if (q < 0) throw std::invalid_argument("q-intersection: q = " + std::to_string(q) + " must be >= 0");
}

ContractSummary QIntersectionContractor::Contract(Box& box, ContractContext& context) {
  ContractSummary summary;
  if (box.IsEmpty()) return {ContractStatus::kEmpty, "", {}};
  if (q_ >= static_cast<int>(parts_.size())) return summary;
  // A part that emptied a box holding this one has no point in it either:
  // its box stays empty (the repeated q-intersection of a fixpoint calls
  // it on ever smaller boxes, and an outlier's box empties early).
  const bool inside_last = contracted_.size() == parts_.size() && last_input_.size() == box.size() &&
                           !last_input_.IsEmpty() && box.IsSubsetOf(last_input_);
  known_empty_.assign(parts_.size(), 0);
  if (inside_last)
    for (std::size_t i = 0; i < parts_.size(); ++i) known_empty_[i] = contracted_[i].IsEmpty() ? 1 : 0;
  bool stopped = false;
  ApplyEach(parts_, box, context, summary.work, &stopped, contracted_, &known_empty_);
  last_input_ = box;
  if (stopped) last_input_.SetEmpty();  // the parts not applied left their copies whole
  Finish(Intersect(RelaxedIntersection(contracted_, q_, box.size()), box), stopped, box, summary);
  return summary;
}

}  // namespace icp
