#include "harness/map_command.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "harness/results_store.h"
#include "harness/runner.h"

namespace icp {
namespace {

namespace fs = std::filesystem;

StepRecord WithProperties(int step, Properties properties) {
  StepRecord s;
  s.step = step;
  s.properties = std::move(properties);
  return s;
}

TEST(MapCommandTest, EachLandmarksLastBox) {
  const std::vector<StepRecord> steps = {
      WithProperties(0, {{"L0_x_lo", 0.0}, {"L0_x_hi", 4.0}, {"L0_y_lo", 0.0}, {"L0_y_hi", 4.0},
                         {"L0_z_lo", 0.0}, {"L0_z_hi", 4.0}, {"L0_held", std::int64_t{1}}}),
      WithProperties(1, {{"L0_x_lo", 1.0}, {"L0_x_hi", 2.0}, {"L0_y_lo", 1.5}, {"L0_y_hi", 2.5},
                         {"L0_z_lo", 0.5}, {"L0_z_hi", 0.75}, {"L7_x_lo", -1.0}, {"L7_x_hi", 1.0},
                         {"L7_y_lo", -1.0}, {"L7_y_hi", 1.0}, {"L7_z_lo", 0.0}, {"L7_z_hi", 2.0},
                         {"landmarks", std::int64_t{2}}})};
  std::vector<int> left_out;
  const LandmarkMap map = MapOfSteps(steps, "k", &left_out);
  EXPECT_TRUE(left_out.empty());
  ASSERT_EQ(map.size(), 2u);
  EXPECT_EQ(map.at(0)[0], Interval(1, 2));
  EXPECT_EQ(map.at(0)[2], Interval(0.5, 0.75));
  EXPECT_EQ(map.at(7)[1], Interval(-1, 1));
  EXPECT_THROW(MapOfSteps({WithProperties(0, {{"landmarks", std::int64_t{0}}})}, "k", &left_out),
               std::invalid_argument);
  // Unbounded: left out of the map; nothing bounded: no map.
  const StepRecord unbounded = WithProperties(
      0, {{"L3_x_lo", 0.0}, {"L3_x_hi", kInf}, {"L3_y_lo", 0.0}, {"L3_y_hi", 1.0},
          {"L3_z_lo", 0.0}, {"L3_z_hi", 1.0}});
  EXPECT_THROW(MapOfSteps({unbounded}, "k", &left_out), std::invalid_argument);
  left_out.clear();
  EXPECT_EQ(MapOfSteps({steps[1], unbounded}, "k", &left_out).size(), 2u);
  EXPECT_EQ(left_out, (std::vector<int>{3}));
}

// From a store: the one run the terms single out; none or several say so.
TEST(MapCommandTest, TheRunTheTermsSingleOut) {
  const fs::path dir = fs::path(::testing::TempDir()) / "map_command";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    ResultsStore store(StorePath(dir.string()));
    for (const char* w : {"2", "4", "20"})
      store.Insert(ExecuteRun(RunSpec{"digo", {}, "visual-landmarks", {{"w", w}, {"steps", "30"}}, 1, 0}));
  }
  std::string key;
  std::vector<int> left_out;
  const LandmarkMap map = MapOfStoredRun(dir.string(), {"digo", "w=4"}, &key, &left_out);
  EXPECT_NE(key.find("w=4"), std::string::npos);
  EXPECT_FALSE(map.empty());
  EXPECT_EQ(left_out, (std::vector<int>{4}));  // 30 steps: no parallax on the far one
  try {
    MapOfStoredRun(dir.string(), {"digo"}, &key, &left_out);
    ADD_FAILURE() << "two runs match";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("3 runs"), std::string::npos) << e.what();
  }
  // A number in a term ends where the key's does: w=2 is not w=20.
  MapOfStoredRun(dir.string(), {"digo", "w=2"}, &key, &left_out);
  EXPECT_NE(key.find("w=2}"), std::string::npos) << key;
  MapOfStoredRun(dir.string(), {"w=20", "|seed=1"}, &key, &left_out);
  EXPECT_NE(key.find("w=20"), std::string::npos) << key;
  EXPECT_THROW(MapOfStoredRun(dir.string(), {"lic"}, &key, &left_out), std::invalid_argument);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace icp
