// Paper 004's two estimators over a problem's graph of ICSPs (eq. 20-21;
// the visual-landmarks problem lists them in CspView::icsps):
//   digo  DIGO (§3.5, eq. 26): the inner contractor on the whole sub-graph
//         of the window's Xi steps (the problem's w), every landmark's
//         domain kept across windows, the poses carried from the previous
//         window (carry = all);
//   lic   LIC, the authors' earlier method: each ICSP of the newest step
//         solved alone (WindowEstimator's local mode), landmark domains
//         kept, the previous pose carried into the motion ICSP.
// Both are WindowEstimator with the contractor named by `inner` (any CSP
// algorithm of the registry, at its default parameters).
#ifndef ICPBENCH_ALGORITHMS_ICSP_GRAPH_ICSP_GRAPH_H_
#define ICPBENCH_ALGORITHMS_ICSP_GRAPH_ICSP_GRAPH_H_

#include <cstdint>
#include <memory>
#include <string>

#include "algorithms/estimator.h"
#include "core/constraint_system.h"
#include "core/params.h"

namespace icp {

struct IcspGraphParams {
  std::string inner = "hc4";   // the paper's: HC4
  std::string carry = "all";   // poses from the previous window: none|first|all
};
void Describe(IcspGraphParams& p, ParamSet& set);
// Also checks that inner names a CSP contractor.
ParamMap ResolveIcspGraph(const std::string& owner, const ParamMap& values);

// The contractors alone, on any CSP (`solve`, the property suites): digo's
// is its inner contractor on the whole CSP; lic's solves each constraint
// alone by its inner contractor and intersects the results.
std::unique_ptr<Contractor> MakeDigoContractor(const ParamMap& params, const ConstraintSystem& csp);
std::unique_ptr<Contractor> MakeLicContractor(const ParamMap& params, const ConstraintSystem& csp);

std::unique_ptr<Estimator> MakeDigo(const ParamMap& params, std::uint64_t seed);
std::unique_ptr<Estimator> MakeLic(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_ICSP_GRAPH_ICSP_GRAPH_H_
