#include "algorithms/polynomial/polynomial.h"

#include <string>
#include <vector>

#include "core/box_polynomial.h"
#include "core/memory_budget.h"

namespace icp {

void Describe(PolynomialParams& p, ParamSet& set) {
  Describe(p.relaxed, set);
  set.Add("approximation", &p.approximation,
          "c1: repeated q-relaxed intersection; c2: repeated relaxed composition; c3: Horner over "
          "the measurements repeated p times",
          {"c1", "c2", "c3"});
  set.Add("p", &p.p, "repetitions of the approximation (Fig. 5.2: 10, 30 for c1)",
          Range::Closed(1, 10000));
}

std::vector<Box> RepeatedSortTransform(const Box& prior, const SharedContractors& ms, int p,
                                       const StopCondition& stop, WorkCounters* work,
                                       bool* stopped) {
  SharedContractors repeated;
  for (int i = 0; i < p; ++i) repeated.insert(repeated.end(), ms.begin(), ms.end());
  // Every coefficient of the p m contractors is kept while they run.
  const std::size_t boxes = repeated.size() + 1;
  CheckMemory(2 * boxes * (sizeof(Box) + prior.size() * sizeof(Interval) + 16),
              "polynomial approximation=c3: the " + std::to_string(boxes) +
                  " coefficients of p x m = " + std::to_string(p) + " x " +
                  std::to_string(ms.size()) + " contractors (lower p)");
  return HornerSortTransform(prior, repeated, stop, work, stopped);
}

// by_q[q], q = 0..m: the coefficient of degree m - q.
std::vector<Box> PolynomialHullsByQ(const PolynomialParams& params, const Box& prior,
                                    const SharedContractors& ms, const StopCondition& stop,
                                    ContractSummary* summary) {
  const int m = static_cast<int>(ms.size());
  std::vector<Box> by_q(m + 1, prior);
  bool stopped = false;
  if (params.approximation == "c1") {
    for (int q = 0; q < m; ++q) {
      QIntersectionContractor relaxed(ms, q);
      for (int i = 0; i < params.p && !by_q[q].IsEmpty(); ++i) {
        ContractContext context(stop);
        const Box before = by_q[q];
        const ContractSummary s = relaxed.Contract(by_q[q], context);
        summary->work += s.work;
        stopped = stopped || s.status == ContractStatus::kStopped;
        if (by_q[q] == before) break;
      }
    }
  } else if (params.approximation == "c2") {
    // Coefficient m - q of the Horner evaluation, p times from the prior.
    // The first pass is the same for every q: one evaluation serves them
    // all; the later ones compute only the coefficient they need.
    if (!prior.IsEmpty()) {
      const std::vector<Box> first =
          HornerSortTransform(prior, ms, stop, &summary->work, &stopped);
      for (int q = 0; q < m; ++q) by_q[q] = first[m - q];
    }
    // Past the stop condition the later passes are left out (sound).
    for (int q = 0; q < m && !stop.ShouldStop(); ++q) {
      if (by_q[q] == prior) continue;  // a pass that changed nothing is a fixpoint
      for (int i = 1; i < params.p && !by_q[q].IsEmpty() && !stop.ShouldStop(); ++i) {
        bool s = false;
        const Box before = by_q[q];
        by_q[q] = HornerCoefficient(before, ms, m - q, stop, &summary->work, &s);
        stopped = stopped || s;
        if (by_q[q] == before) break;
      }
    }
    stopped = stopped || stop.ShouldStop();
  } else {
    const std::vector<Box> coefficients =
        RepeatedSortTransform(prior, ms, params.p, stop, &summary->work, &stopped);
    for (int q = 0; q < m; ++q) by_q[q] = coefficients[(m - q) * params.p];
  }
  for (Box& b : by_q)
    if (b.IsEmpty()) b.SetEmpty();
  if (stopped) {
    summary->status = ContractStatus::kStopped;
    summary->message = stop.ShouldStop()
                           ? "time limit reached: the contractions not yet made count as the "
                             "identity (sound, wider)"
                           : "a measurement's contraction stopped short";
  }
  return by_q;
}

namespace {

class PolynomialEstimator : public RelaxedEstimator {
 public:
  explicit PolynomialEstimator(const PolynomialParams& p) : RelaxedEstimator(p.relaxed), p_(p) {}

 protected:
  RelaxedSolution Solve(const Box& prior, const MeasurementSetView& view, const StateSpace&,
                        int least_q, const StopCondition& stop) override {
    RelaxedSolution out;
    out.hulls_by_q = PolynomialHullsByQ(p_, prior, view.measurements, stop, &out.summary);
    const int m = static_cast<int>(view.measurements.size());
    out.q = ChooseQ(least_q, params().auto_q, m,
                    [&](int q) { return !out.hulls_by_q[q].IsEmpty(); });
    out.estimate = std::make_unique<BoxEstimate>(out.hulls_by_q[std::min(out.q, m)]);
    return out;
  }

 private:
  PolynomialParams p_;
};

}  // namespace

std::unique_ptr<Estimator> MakePolynomial(const ParamMap& params, std::uint64_t) {
  return std::make_unique<PolynomialEstimator>(ParseParams<PolynomialParams>("polynomial", params));
}

}  // namespace icp
