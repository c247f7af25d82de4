// A plugin algorithm "faulty" whose contractor misbehaves as its `fault`
// parameter says (tests/plugin_test.cc: what `icpbench solve` does with a
// broken result). With ICPBENCH_TEST_PLUGIN_PARAM set, it also declares a
// parameter of that name: `fault` again, `carry` (which the window adapter
// adds) or a name that cannot be written; loading must refuse each.
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "algorithms/hc4/hc4.h"
#include "algorithms/registry.h"
#include "core/plugin.h"

namespace {

struct FaultyParams {
  std::string fault = "none";
};

void Describe(FaultyParams& p, icp::ParamSet& set) {
  set.Add("fault", &p.fault, "what the contraction does wrong",
          {"none", "chatty", "nan", "outside", "extra", "throw", "throw-int", "hang", "null"});
  static std::string extra;
  if (const char* name = std::getenv("ICPBENCH_TEST_PLUGIN_PARAM")) set.Add(name, &extra, "an extra parameter");
}

class FaultyContractor : public icp::Contractor {
 public:
  FaultyContractor(std::string fault, std::unique_ptr<icp::Contractor> hc4)
      : fault_(std::move(fault)), hc4_(std::move(hc4)) {}
  std::string_view Name() const override { return "faulty"; }
  icp::ContractSummary Contract(icp::Box& box, icp::ContractContext& context) override {
    if (fault_ == "throw") throw std::runtime_error("faulty: deliberate failure");
    if (fault_ == "throw-int") throw 42;
    if (fault_ == "hang")
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // never checks its stop condition
    if (fault_ == "chatty") {  // a debug print, on both streams
      std::fputs("faulty: contracting\n", stderr);
      std::fputs("faulty: contracting\n", stdout);
      std::fflush(nullptr);
    }
    icp::ContractSummary summary = hc4_->Contract(box, context);
    if (fault_ == "nan")
      box[0] = icp::Interval(box[0].lo(), std::numeric_limits<double>::quiet_NaN(), icp::Interval::kOrdered);
    if (fault_ == "outside") box[0] = icp::Interval(box[0].lo() - 1e6, box[0].hi() + 1e6);
    if (fault_ == "extra") box = icp::Box(std::vector<icp::Interval>(box.size() + 1, icp::Interval(0, 1)));
    return summary;
  }

 private:
  std::string fault_;
  std::unique_ptr<icp::Contractor> hc4_;
};

std::unique_ptr<icp::Contractor> MakeFaulty(const icp::ParamMap& params, const icp::ConstraintSystem& csp) {
  const FaultyParams p = icp::ParseParams<FaultyParams>("faulty", params);
  if (p.fault == "null") return nullptr;
  return std::make_unique<FaultyContractor>(p.fault, icp::MakeHC4({}, csp));
}

}  // namespace

extern "C" int icpbench_register_v1(icp::PluginRegistrar* registrar) {
  return registrar->AddAlgorithm(icp::CspAlgorithm<FaultyParams, &MakeFaulty>(
             "faulty", "a contractor that misbehaves on purpose (plugin tests)", {"faulty", 990, "#000000"}))
             ? 0
             : 1;
}
