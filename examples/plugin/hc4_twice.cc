// "hc4-twice": HC4 applied twice in sequence, the second pass starting from
// the first one's result. Sound, as HC4 is. With a coarse `ratio` the first
// pass stops early and the second one narrows further; at a fine one the two
// give HC4's box.
#include <memory>
#include <utility>
#include <vector>

#include "algorithms/hc4/hc4.h"
#include "algorithms/registry.h"
#include "core/contractor_algebra.h"
#include "core/plugin.h"

namespace {

// The contractor, from HC4's parameters (`ratio`, `max_revise_calls`): a
// ContractorFactory, as the in-tree algorithms have.
std::unique_ptr<icp::Contractor> MakeHC4Twice(const icp::ParamMap& params,
                                              const icp::ConstraintSystem& csp) {
  icp::SharedContractors passes;
  passes.push_back(icp::MakeHC4(params, csp));
  passes.push_back(icp::MakeHC4(params, csp));
  return std::make_unique<icp::SequenceContractor>(std::move(passes));
}

}  // namespace

// CspAlgorithm runs the contractor over each step's CSP window (with the
// `carry` parameter), as for the in-tree algorithms/registry.cc lines.
extern "C" int icpbench_register_v1(icp::PluginRegistrar* registrar) {
  return registrar->AddAlgorithm(icp::CspAlgorithm<icp::HC4Params, &MakeHC4Twice>(
             "hc4-twice", "HC4 applied twice in sequence (out-of-tree plugin example)",
             {"HC4 twice", 100, "#aec7e8"}))
             ? 0
             : 1;
}
