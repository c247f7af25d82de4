#include "problems/minibex_file/minibex_file.h"

#include "core/constraint_contractor.h"
#include "core/minibex_parser.h"

namespace icp {

void Describe(MinibexFileParams& p, ParamSet& set) {
  set.Add("file", &p.file, "path of the Minibex file");
}

namespace {
Step MinibexFileStep(const ConstraintSystem& csp) {
  Step step;
  step.views.space.names = csp.names();
  CspView view;
  view.csp = csp;
  for (int i = 0; i < csp.num_variables(); ++i) view.states.push_back({0, i});
  step.views.csp = std::move(view);
  // Each constraint, once the file's loops are expanded, is one
  // measurement; which are outliers is unknown.
  MeasurementSetView set;
  set.prior = csp.domains();
  set.measurements = ConstraintContractors(csp);
  step.views.measurement_set = std::move(set);
  return step;
}
}  // namespace

namespace {
MinibexFileParams Parse(const std::string& owner, const ParamMap& params) {
  auto p = ParseParams<MinibexFileParams>(owner, params);
  if (p.file.empty()) throw ParamError(owner + ".file = \"\": a file path is required");
  return p;
}
}  // namespace

ParamMap ResolveMinibexFile(const std::string& owner, const ParamMap& values) {
  // A file that cannot be read or parsed is a bad parameter value: a spec
  // then names its own line and key beside the file's.
  try {
    ParseMinibexFile(Parse(owner, values).file);
  } catch (const MinibexError& e) {
    throw ParamError(owner + ".file: " + e.what());
  }
  return ResolveParams<MinibexFileParams>(owner, values);
}

std::unique_ptr<Problem> MakeMinibexFile(const ParamMap& params, std::uint64_t) {
  return std::make_unique<SingleStepProblem>(
      "minibex-file", [csp = ParseMinibexFile(Parse("minibex-file", params).file)] {
        return MinibexFileStep(csp);
      });
}

}  // namespace icp
