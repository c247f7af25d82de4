#include <gtest/gtest.h>
#include <signal.h>

#include <memory>

#include "harness/sweep_recorder.h"

namespace icp {
namespace {

void (*CurrentHandler(int signal))(int) {
  struct sigaction now {};
  sigaction(signal, nullptr, &now);
  return now.sa_handler;
}

TEST(StopSignalsTest, OverlappingSweepsGiveBackTheHandlersBeforeTheFirst) {
  // Two sweeps in threads of one process (icpbench.run): the second saved
  // the first's handler and put it back after the first had ended, so
  // Ctrl-C was caught for good and never reached the program again.
  const auto before = CurrentHandler(SIGINT);
  const auto before_term = CurrentHandler(SIGTERM);
  auto first = std::make_unique<StopSignals>();
  const auto caught = CurrentHandler(SIGINT);
  ASSERT_NE(caught, before);
  auto second = std::make_unique<StopSignals>();
  first.reset();  // the first sweep ends while the second still runs
  EXPECT_EQ(CurrentHandler(SIGINT), caught);
  StopSignals::Request(SIGINT);
  EXPECT_EQ(StopSignals::Caught(), SIGINT);
  second.reset();
  EXPECT_EQ(CurrentHandler(SIGINT), before);
  EXPECT_EQ(CurrentHandler(SIGTERM), before_term);
}

}  // namespace
}  // namespace icp
