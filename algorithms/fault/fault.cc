#include "algorithms/fault/fault.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <thread>

#include "algorithms/hc4/hc4.h"

namespace icp {

void Describe(FaultParams& p, ParamSet& set) {
  set.Add("mode", &p.mode, "the fault to inject",
          {"none", "segfault", "abort", "hang", "throw", "garbage"});
  set.Add("after_calls", &p.after_calls, "good contractions before the fault",
          Range::AtLeast(0));
}

namespace {
// Counts contractions across the steps of a run (a process runs one run).
std::atomic<int> calls_in_process{0};

class FaultContractor : public Contractor {
 public:
  FaultContractor(const ConstraintSystem& csp, FaultParams params)
      : params_(std::move(params)),
        hc4_(std::make_shared<CompiledSystem>(csp), HC4Params()) {}
  std::string_view Name() const override { return "fault"; }
  ContractSummary Contract(Box& box, ContractContext& context) override {
    if (calls_in_process++ < params_.after_calls || params_.mode == "none")
      return hc4_.Contract(box, context);
    if (params_.mode == "segfault") std::raise(SIGSEGV);
    if (params_.mode == "abort") std::abort();
    if (params_.mode == "throw") throw std::runtime_error("injected fault");
    if (params_.mode == "hang") {
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    // garbage: a box that is not inside the initial one.
    for (std::size_t i = 0; i < box.size(); ++i)
      box[i] = Interval(box[i].lo() - 1, std::numeric_limits<double>::infinity());
    return {};
  }

 private:
  FaultParams params_;
  HC4Contractor hc4_;
};
}  // namespace

std::unique_ptr<Contractor> MakeFault(const ParamMap& params, const ConstraintSystem& csp) {
  return std::make_unique<FaultContractor>(csp, ParseParams<FaultParams>("fault", params));
}

}  // namespace icp
