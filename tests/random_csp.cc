#include "tests/random_csp.h"

#include <cmath>
#include <string>

#include "core/random.h"
#include "core/tape.h"

namespace icp::testing {

namespace {
class Generator {
 public:
  Generator(std::uint64_t seed, ConstraintSystem* csp, int num_vars, bool discontinuous)
      : rng_(seed), csp_(csp), num_vars_(num_vars), discontinuous_(discontinuous) {}

  Expr Random(int depth) {
    if (depth <= 0 || Pick(4) == 0) return Leaf();
    std::uint64_t op = Pick(14);
    if (!discontinuous_ && (op == 5 || op == 13)) op = 0;
    switch (op) {
      case 0: case 1: return Random(depth - 1) + Random(depth - 1);
      case 2: return Random(depth - 1) - Random(depth - 1);
      case 3: case 4: return Random(depth - 1) * Random(depth - 1);
      case 5: return Random(depth - 1) / Random(depth - 1);
      case 6: return Sqr(Random(depth - 1));
      case 7: return Pow(Random(depth - 1), 3 + static_cast<int>(Pick(2)));
      case 8: return Sin(Random(depth - 1));
      case 9: return Cos(Random(depth - 1));
      case 10: return Exp(Random(depth - 1) / 4.0);
      case 11: return Sqrt(Abs(Random(depth - 1)));
      case 12: return Atan(Random(depth - 1));
      default: return Min(Random(depth - 1), Random(depth - 1));
    }
  }
  std::uint64_t Pick(std::uint64_t n) { return UniformIndex(rng_, n); }
  double Uniform(double lo, double hi) { return UniformReal(rng_, lo, hi); }

 private:
  Expr Leaf() {
    if (Pick(3) == 0) return csp_->Constant(Interval(std::round(Uniform(-3, 3) * 8) / 8));
    return csp_->Var(static_cast<int>(Pick(num_vars_)));
  }
  RandomEngine rng_;
  ConstraintSystem* csp_;
  int num_vars_;
  bool discontinuous_;
};
}  // namespace

RandomCsp MakeRandomCsp(std::uint64_t seed, const RandomCspOptions& o) {
  RandomCsp out;
  Generator gen(seed, &out.csp, 1, o.discontinuous_ops);
  const int n = o.min_variables + static_cast<int>(gen.Pick(o.max_variables - o.min_variables + 1));
  Generator g(seed * 7919 + 1, &out.csp, n, o.discontinuous_ops);
  Box point_box;
  for (int i = 0; i < n; ++i) {
    const double p = g.Uniform(-2, 2);
    out.point.push_back(p);
    point_box.push_back(Interval(p));
    const double lo = p - g.Uniform(0, o.domain_half_width);
    const double hi = p + g.Uniform(0, o.domain_half_width);
    out.csp.AddVariable("v" + std::to_string(i), Interval(lo, hi));
  }
  const int m = o.min_constraints + static_cast<int>(g.Pick(o.max_constraints - o.min_constraints + 1));
  std::vector<Interval> slots;
  for (int tries = 0; static_cast<int>(out.csp.constraints().size()) < m && tries < 50 * m; ++tries) {
    Expr f = g.Random(1 + static_cast<int>(g.Pick(o.max_depth)));
    Tape tape(out.csp.graph(), Constraint{f.id(), Interval()});
    if (tape.variables().empty()) continue;
    Interval value = tape.Forward(point_box, slots);
    if (value.IsEmpty() || !value.IsBounded() || value.Width() > 1e6) continue;
    out.csp.AddConstraint(f, value);
  }
  return out;
}

}  // namespace icp::testing
