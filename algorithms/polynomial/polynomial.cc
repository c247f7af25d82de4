#include "algorithms/polynomial/polynomial.h"

#include "core/box_polynomial.h"

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

namespace {

class PolynomialEstimator : public RelaxedEstimator {
 public:
  explicit PolynomialEstimator(const PolynomialParams& p) : RelaxedEstimator(p.relaxed), p_(p) {}

 protected:
  RelaxedSolution Solve(const Box& prior, const MeasurementSetView& view, const StateSpace&,
                        const StopCondition& stop) override {
    RelaxedSolution out;
    out.hulls_by_q = ByQ(prior, view.measurements, stop, &out.summary);
    const int m = static_cast<int>(view.measurements.size());
    out.q = ChooseQ(params().q, params().auto_q, m,
                    [&](int q) { return !out.hulls_by_q[q].IsEmpty(); });
    out.estimate = std::make_unique<BoxEstimate>(out.hulls_by_q[std::min(out.q, m)]);
    return out;
  }

 private:
  // by_q[q], q = 0..m: the coefficient of degree m - q.
  std::vector<Box> ByQ(const Box& prior, const SharedContractors& ms, const StopCondition& stop,
                       ContractSummary* summary) const {
    const int m = static_cast<int>(ms.size());
    std::vector<Box> by_q(m + 1, prior);
    bool stopped = false;
    if (p_.approximation == "c1") {
      for (int q = 0; q < m; ++q) {
        QIntersectionContractor relaxed(ms, q);
        for (int i = 0; i < p_.p && !by_q[q].IsEmpty(); ++i) {
          ContractContext context(stop);
          const Box before = by_q[q];
          const ContractSummary s = relaxed.Contract(by_q[q], context);
          summary->work += s.work;
          stopped = stopped || s.status == ContractStatus::kStopped;
          if (by_q[q] == before) break;
        }
      }
    } else if (p_.approximation == "c2") {
      for (int q = 0; q < m; ++q)
        for (int i = 0; i < p_.p && !by_q[q].IsEmpty(); ++i) {
          bool s = false;
          const Box before = by_q[q];
          by_q[q] = HornerSortTransform(before, ms, stop, &summary->work, &s)[m - q];
          stopped = stopped || s;
          if (by_q[q] == before) break;
        }
    } else {
      SharedContractors repeated;
      for (int i = 0; i < p_.p; ++i) repeated.insert(repeated.end(), ms.begin(), ms.end());
      const std::vector<Box> coefficients =
          HornerSortTransform(prior, repeated, stop, &summary->work, &stopped);
      for (int q = 0; q < m; ++q) by_q[q] = coefficients[(m - q) * p_.p];
    }
    for (Box& b : by_q)
      if (b.IsEmpty()) b.SetEmpty();
    if (stopped) summary->status = ContractStatus::kStopped;
    return by_q;
  }

  PolynomialParams p_;
};

}  // namespace

std::unique_ptr<Estimator> MakePolynomial(const ParamMap& params, std::uint64_t) {
  return std::make_unique<PolynomialEstimator>(ParseParams<PolynomialParams>("polynomial", params));
}

}  // namespace icp
