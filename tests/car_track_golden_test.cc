// Golden boxes: every ICP algorithm gives, step for step, the same newest-state
// box on a fixed 300-step car-track drive (tests/fixtures/car_track_300.csv,
// default parameters: carry=first, digo and lic carry=all) as when the file
// was written. A change of the run loop, the estimators or the problem that moves a single bound by an
// ulp fails here. The drive is a log, not the simulator, so changing the
// simulator's random draws does not move it.
//
// To rewrite the golden file after a deliberate change of the boxes:
//   ICPBENCH_UPDATE_GOLDEN=1 build/tests/car_track_golden_test
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "algorithms/registry.h"
#include "harness/runner.h"
#include "tests/test_names.h"

namespace icp {
namespace {

const std::string kFixtures = ICPBENCH_FIXTURES;
const std::string kLog = kFixtures + "/car_track_300.csv";
const std::string kGolden = kFixtures + "/car_track_golden.txt";
constexpr int kSampleEvery = 25;

std::string Hex(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

// One line per algorithm: name, steps, FNV-1a hash over the bits of every
// reported bound of every step; then every kSampleEvery-th step in full.
std::string Golden(const std::string& algorithm, const RunRecord& r) {
  std::uint64_t hash = 1469598103934665603ull;
  auto mix = [&](double v) {
    std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    for (int i = 0; i < 8; ++i) {
      hash ^= (bits >> (8 * i)) & 0xff;
      hash *= 1099511628211ull;
    }
  };
  std::ostringstream samples;
  for (const StepRecord& s : r.steps) {
    for (const VariableRecord& v : s.vars) {
      mix(v.lo);
      mix(v.hi);
    }
    if (s.step % kSampleEvery == 0) {
      samples << algorithm << " step " << s.step;
      for (const VariableRecord& v : s.vars) samples << " " << v.name << " " << Hex(v.lo) << " " << Hex(v.hi);
      samples << "\n";
    }
  }
  char head[128];
  std::snprintf(head, sizeof head, "%s steps %zu hash %016llx\n", algorithm.c_str(), r.steps.size(),
                static_cast<unsigned long long>(hash));
  return head + samples.str();
}

RunRecord Drive(const std::string& algorithm) {
  return ExecuteRun(RunSpec{algorithm, {}, "car-track", {{"log", kLog}, {"steps", "300"}}, 1, 0});
}

// The golden text of each algorithm, keyed by name.
std::map<std::string, std::string> ReadGolden() {
  std::ifstream in(kGolden);
  std::map<std::string, std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    out[line.substr(0, line.find(' '))] += line + "\n";
  }
  return out;
}

TEST(CarTrackGolden, Update) {
  if (!std::getenv("ICPBENCH_UPDATE_GOLDEN")) GTEST_SKIP() << "set ICPBENCH_UPDATE_GOLDEN=1 to rewrite";
  std::ofstream out(kGolden);
  out << "# tests/car_track_golden_test.cc: newest-state boxes on car_track_300.csv, default "
         "parameters (carry=first; digo and lic: carry=all)\n";
  for (const std::string& a : testing::AlgorithmsNeeding(View::kCsp)) out << Golden(a, Drive(a));
}

class CarTrackGoldenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CarTrackGoldenTest, SameBoxesAsTheGoldenFile) {
  if (std::getenv("ICPBENCH_UPDATE_GOLDEN")) GTEST_SKIP();
  const std::map<std::string, std::string> golden = ReadGolden();
  ASSERT_TRUE(golden.count(GetParam())) << GetParam() << " is not in " << kGolden;
  const RunRecord r = Drive(GetParam());
  ASSERT_EQ(r.status, RunStatus::kOk) << r.reason;
  for (const StepRecord& s : r.steps) ASSERT_EQ(s.contained, 1) << "step " << s.step;
  EXPECT_EQ(Golden(GetParam(), r), golden.at(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(AllAlgorithms, CarTrackGoldenTest, ::testing::ValuesIn(testing::AlgorithmsNeeding(View::kCsp)),
                         testing::RegistryName());

}  // namespace
}  // namespace icp
