#include "algorithms/fault/fault.h"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "algorithms/hc4/hc4.h"
#include "algorithms/window/window_estimator.h"

namespace icp {

void Describe(FaultParams& p, ParamSet& set) {
  set.Add("mode", &p.mode, "the fault to inject",
          {"none", "segfault", "abort", "hang", "spin", "throw", "allocate", "garbage", "nan", "paving-nan",
           "particles-nan", "exit", "slow"});
  set.Add("after_calls", &p.after_calls, "good steps before the fault", Range::AtLeast(0));
  set.Add("slow_ms", &p.slow_ms, "mode slow: milliseconds added to every step", Range::AtLeast(0));
}

namespace {
// Busy forever; the process is killed.
void Spin() {
  volatile bool stop = false;  // read every time: the loop is not elided
  while (!stop) {
  }
}

class FaultEstimator : public Estimator {
 public:
  explicit FaultEstimator(FaultParams params)
      : params_(std::move(params)), hc4_(&MakeHC4, {}, Carry::kFirst) {}

  StepResult Step(const Views& views, const StopCondition& stop) override {
    if (params_.mode == "slow")
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(params_.slow_ms));
    if (steps_++ < params_.after_calls || params_.mode == "none" || params_.mode == "slow")
      return hc4_.Step(views, stop);
    if (params_.mode == "segfault") std::raise(SIGSEGV);
    if (params_.mode == "abort") std::abort();
    if (params_.mode == "throw") throw std::runtime_error("injected fault");
    if (params_.mode == "exit") std::exit(0);  // a library that ends the process, successfully
    if (params_.mode == "allocate") {
      // Blocks touched once cost little memory but count whole against
      // RLIMIT_DATA: under a limit the allocation fails long before the
      // machine notices.
      constexpr std::size_t kBlock = std::size_t{64} << 20;
      std::vector<std::unique_ptr<char[]>> blocks;
      for (int i = 0; i < 1024; ++i) {
        blocks.emplace_back(new char[kBlock]);
        *static_cast<volatile char*>(blocks.back().get()) = 1;  // kept, not elided
      }
      throw std::runtime_error("allocated 64 GiB without reaching a memory limit");
    }
    if (params_.mode == "hang") {
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    if (params_.mode == "spin") {
      const unsigned threads = 2 * std::max(1u, std::thread::hardware_concurrency());
      for (unsigned i = 1; i < threads; ++i) std::thread(Spin).detach();
      Spin();
    }
    // garbage: a box reaching outside the step's domains; nan: one NaN
    // bound (a box that reads as empty); paving-nan, particles-nan: a
    // paving or a cloud whose one part has one (the hull would drop it).
    StepResult result = hc4_.Step(views, stop);
    if (params_.mode == "paving-nan" || params_.mode == "particles-nan") {
      const Box hull = result.estimate->Hull();
      Box broken = hull;
      broken[0] = Interval(hull[0].lo(), std::numeric_limits<double>::quiet_NaN(), Interval::kOrdered);
      if (params_.mode == "paving-nan") {
        result.estimate = std::make_unique<PavingEstimate>(hull.size(), std::vector<Box>{hull},
                                                           std::vector<Box>{broken});
      } else {
        cv::Mat particles(2, static_cast<int>(hull.size()), CV_64F);
        for (int c = 0; c < particles.cols; ++c) particles.at<double>(0, c) = particles.at<double>(1, c) = hull[c].Mid();
        particles.at<double>(1, 0) = std::numeric_limits<double>::quiet_NaN();
        result.estimate = std::make_unique<ParticleEstimate>(particles, std::vector<double>{1, 1});
      }
      return result;
    }
    Box box = result.estimate->Hull();
    for (std::size_t i = 0; i < box.size(); ++i)
      box[i] = Interval(box[i].lo() - 1, std::numeric_limits<double>::infinity());
    if (params_.mode == "nan") {
      box = result.estimate->Hull();
      box[0] = Interval(box[0].lo(), std::numeric_limits<double>::quiet_NaN(), Interval::kOrdered);
    }
    result.estimate = std::make_unique<BoxEstimate>(box);
    return result;
  }

 private:
  FaultParams params_;
  WindowEstimator hc4_;
  int steps_ = 0;
};
}  // namespace

std::unique_ptr<Estimator> MakeFault(const ParamMap& params, std::uint64_t) {
  return std::make_unique<FaultEstimator>(ParseParams<FaultParams>("fault", params));
}

}  // namespace icp
