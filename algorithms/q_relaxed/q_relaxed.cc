#include "algorithms/q_relaxed/q_relaxed.h"

#include <string>

#include "core/paving.h"

namespace icp {

void Describe(QRelaxedParams& p, ParamSet& set) {
  Describe(p.relaxed, set);
  set.Add("mode", &p.mode, "contract: the fixpoint box; pave: a paving of boxes narrower than epsilon",
          {"contract", "pave"});
  set.Add("epsilon", &p.epsilon, "pave: width below which a box is not bisected (state units)",
          Range::Positive(1e300));
  set.Add("ratio", &p.ratio, "fixpoint: relative width decrease that counts as progress",
          Range::HalfOpen(0, 1));
  set.Add("max_iterations", &p.max_iterations, "fixpoint: q-intersections per contraction at most",
          Range::AtLeast(1));
  set.Add("max_boxes", &p.max_boxes, "pave: boxes at most; past it the paving stops (soundly)",
          Range::AtLeast(1));
}

namespace {

// Why a stopped solve stopped: the stop condition (the run's time limit),
// or a measurement's own contraction that stopped short.
std::string StopMessage(const StopCondition& stop, const std::string& what) {
  return (stop.ShouldStop() ? "time limit reached: " : "a contraction stopped short: ") + what;
}

class QRelaxedEstimator : public RelaxedEstimator {
 public:
  explicit QRelaxedEstimator(const QRelaxedParams& p) : RelaxedEstimator(p.relaxed), p_(p) {}

 protected:
  RelaxedSolution Solve(const Box& prior, const MeasurementSetView& view, const StateSpace&,
                        int least_q, const StopCondition& stop) override {
    const int m = static_cast<int>(view.measurements.size());
    RelaxedSolution out;
    int contracted_q = -1;
    Box contracted;
    auto contract = [&](int q) {
      if (q == contracted_q) return contracted;
      Box box = prior;
      if (q < m) {
        FixpointContractor fixpoint = Repeated(view.measurements, q);
        ContractContext context(stop);
        const ContractSummary s = fixpoint.Contract(box, context);
        out.summary.work += s.work;
        if (s.status == ContractStatus::kStopped) {
          out.summary.status = s.status;
          out.summary.message = StopMessage(stop, "the fixpoint was cut short");
        }
        if (s.status == ContractStatus::kEmpty) box.SetEmpty();
      }
      contracted_q = q;
      contracted = box;
      return box;
    };
    out.q = ChooseQ(least_q, params().auto_q, m, [&](int q) { return !contract(q).IsEmpty(); });
    if (p_.mode == "contract") {
      out.estimate = std::make_unique<BoxEstimate>(contract(out.q));
      return out;
    }
    // Paving: from the q whose fixpoint is non-empty, upward while the
    // paving is empty (a finer set can vanish where its hull does not).
    std::int64_t bisections = 0;
    bool truncated = false, stopped = false;
    std::vector<Box> boxes;
    int paved_q = -1;
    auto pave = [&](int q) {
      boxes.clear();
      paved_q = q;
      if (q >= m) {
        boxes.push_back(prior);
        return true;
      }
      FixpointContractor fixpoint = Repeated(view.measurements, q);
      PavingResult paving = Pave(prior, fixpoint, p_.epsilon, p_.max_boxes, stop);
      out.summary.work += paving.work;
      bisections += paving.bisections;
      truncated = truncated || paving.truncated;
      stopped = stopped || paving.stopped;
      boxes = std::move(paving.boxes);
      return !boxes.empty();
    };
    out.q = ChooseQ(out.q, params().auto_q, m, pave);
    if (paved_q != out.q) pave(out.q);
    out.estimate = std::make_unique<PavingEstimate>(prior.size(), std::vector<Box>{}, std::move(boxes));
    out.properties = {{"bisections", bisections}, {"truncated", static_cast<std::int64_t>(truncated)}};
    // A paving cut short by the time limit is the run's timeout (kStopped),
    // not a max_boxes truncation: the harness records it as such.
    if (stopped) {
      out.summary.status = ContractStatus::kStopped;
      out.summary.message = StopMessage(stop, "paving truncated, its unfinished boxes kept whole");
    } else if (truncated && out.summary.status != ContractStatus::kStopped) {
      out.summary.message = "paving truncated at max_boxes";
    }
    return out;
  }

 private:
  // The repeated q-relaxed intersection of the measurements.
  FixpointContractor Repeated(const SharedContractors& measurements, int q) const {
    return FixpointContractor(std::make_shared<QIntersectionContractor>(measurements, q), p_.ratio,
                              p_.max_iterations);
  }

  QRelaxedParams p_;
};

}  // namespace

std::unique_ptr<Estimator> MakeQRelaxed(const ParamMap& params, std::uint64_t) {
  return std::make_unique<QRelaxedEstimator>(ParseParams<QRelaxedParams>("q-relaxed", params));
}

}  // namespace icp
