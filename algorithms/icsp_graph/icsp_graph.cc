#include "algorithms/icsp_graph/icsp_graph.h"

#include "algorithms/registry.h"
#include "algorithms/window/window_estimator.h"

namespace icp {

void Describe(IcspGraphParams& p, ParamSet& set) {
  set.Add("inner", &p.inner, "the CSP contractor that solves the ICSPs (hc4, bc4, 3b-bc4, ...)");
  DescribeCarry(&p.carry, set);
}

namespace {
std::unique_ptr<Estimator> Make(const std::string& owner, const ParamMap& params, bool local) {
  const auto p = ParseParams<IcspGraphParams>(owner, params);
  return std::make_unique<WindowEstimator>(InnerContractorFactory(owner, p.inner), ParamMap{},
                                           ParseCarry(p.carry), local);
}
}  // namespace

ParamMap ResolveIcspGraph(const std::string& owner, const ParamMap& values) {
  const ParamMap resolved = ResolveParams<IcspGraphParams>(owner, values);
  InnerContractorFactory(owner, resolved.at("inner"));
  return resolved;
}

std::unique_ptr<Contractor> MakeDigoContractor(const ParamMap& params, const ConstraintSystem& csp) {
  const auto p = ParseParams<IcspGraphParams>("digo", params);
  return InnerContractorFactory("digo", p.inner)({}, csp);
}

std::unique_ptr<Contractor> MakeLicContractor(const ParamMap& params, const ConstraintSystem& csp) {
  const auto p = ParseParams<IcspGraphParams>("lic", params);
  CspView view;
  view.csp = csp;
  return std::make_unique<LocalIcspContractor>(InnerContractorFactory("lic", p.inner), ParamMap{}, csp,
                                               NewestIcsps(view));
}

std::unique_ptr<Estimator> MakeDigo(const ParamMap& params, std::uint64_t /*seed*/) {
  return Make("digo", params, false);
}

std::unique_ptr<Estimator> MakeLic(const ParamMap& params, std::uint64_t /*seed*/) {
  return Make("lic", params, true);
}

}  // namespace icp
