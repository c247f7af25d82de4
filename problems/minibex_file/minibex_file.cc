#include "problems/minibex_file/minibex_file.h"

#include "core/constraint_contractor.h"
#include "core/minibex_parser.h"

namespace icp {

void Describe(MinibexFileParams& p, ParamSet& set) {
  set.Add("file", &p.file, "path of the Minibex file");
}

namespace {
class MinibexFileProblem : public Problem {
 public:
  explicit MinibexFileProblem(ConstraintSystem csp) : csp_(std::move(csp)) {}
  std::string_view Name() const override { return "minibex-file"; }
  int NumSteps() const override { return 1; }
  bool Next(Step* step) override {
    if (done_) return false;
    done_ = true;
    *step = Step();
    step->views.space.names = csp_.names();
    CspView view;
    view.csp = csp_;
    for (int i = 0; i < csp_.num_variables(); ++i) view.states.push_back({0, i});
    step->views.csp = std::move(view);
    // Each constraint, once the file's loops are expanded, is one
    // measurement; which are outliers is unknown.
    MeasurementSetView set;
    set.prior = csp_.domains();
    set.measurements = ConstraintContractors(csp_);
    step->views.measurement_set = std::move(set);
    return true;
  }

 private:
  ConstraintSystem csp_;
  bool done_ = false;
};
}  // namespace

namespace {
MinibexFileParams Parse(const std::string& owner, const ParamMap& params) {
  auto p = ParseParams<MinibexFileParams>(owner, params);
  if (p.file.empty()) throw ParamError(owner + ".file = \"\": a file path is required");
  return p;
}
}  // namespace

ParamMap ResolveMinibexFile(const std::string& owner, const ParamMap& values) {
  ParseMinibexFile(Parse(owner, values).file);
  return ResolveParams<MinibexFileParams>(owner, values);
}

std::unique_ptr<Problem> MakeMinibexFile(const ParamMap& params, std::uint64_t) {
  return std::make_unique<MinibexFileProblem>(ParseMinibexFile(Parse("minibex-file", params).file));
}

}  // namespace icp
