#include "problems/minibex_file/minibex_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "problems/measurement_checks.h"
#include "problems/registry.h"

namespace icp {
namespace {

// Writes text to a fresh file under the test's temporary directory.
std::string WriteTemp(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / name;
  std::ofstream(path) << text;
  return path.string();
}

// Three constraints, two of them from a loop; (1, 2, 3) solves them all.
constexpr char kThreeConstraints[] = R"(
Variables
  x[2] in [-5, 5];
  z in [0, 10];
Constraints
  for i = 1:2;
    x(i) >= i - 1.5;
  end;
  z = x(1) + x(2);
end
)";

TEST(MinibexFileTest, OffersOneMeasurementPerExpandedConstraint) {
  const std::string path = WriteTemp("three.bch", kThreeConstraints);
  auto problem = FindProblem("minibex-file").make({{"file", path}}, 1);
  EXPECT_EQ(problem->NumSteps(), 1);
  Step step;
  ASSERT_TRUE(problem->Next(&step));
  ASSERT_TRUE(step.views.Offers(View::kMeasurementSet));
  ASSERT_TRUE(step.views.Offers(View::kCsp));
  const MeasurementSetView& set = *step.views.measurement_set;
  EXPECT_EQ(set.measurements.size(), 3u);
  EXPECT_EQ(set.prior, step.views.csp->csp.domains());
  EXPECT_EQ(set.prior, Box({Interval(-5, 5), Interval(-5, 5), Interval(0, 10)}));
  EXPECT_TRUE(set.outliers.empty());
  EXPECT_TRUE(set.sources.empty());
  EXPECT_FALSE(set.predict);
  EXPECT_FALSE(problem->Next(&step));

  // Measurement i is constraint i: (1, 2, 3) keeps all three; a point
  // below the second bound (x(2) >= 0.5) fails exactly the second.
  for (const auto& m : set.measurements) EXPECT_TRUE(KeepsTruth(*m, {1, 2, 3}));
  const std::vector<double> bad = {1, 0, 1};
  EXPECT_FALSE(RejectsTruth(*set.measurements[0], bad));
  EXPECT_TRUE(RejectsTruth(*set.measurements[1], bad));
  EXPECT_FALSE(RejectsTruth(*set.measurements[2], bad));
}

TEST(MinibexFileTest, RegistryListsBothViews) {
  const ProblemInfo& info = FindProblem("minibex-file");
  EXPECT_EQ(info.offers, (std::vector<View>{View::kCsp, View::kMeasurementSet}));
  EXPECT_THROW(info.make({}, 1), ParamError);
}

}  // namespace
}  // namespace icp
