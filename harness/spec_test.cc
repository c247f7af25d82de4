#include "harness/spec.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "problems/car_track/car_track.h"

namespace icp {
namespace {

std::string ErrorOf(const std::string& text) {
  try {
    ParseSpec(text, "spec.yaml");
  } catch (const SpecError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpecTest, ExpandsGridsAndSeedsIntoTheMatrix) {
  Spec spec = ParseSpec(R"(
timeout_s: 30
seeds: [1, 2]
algorithms:
  - hc4
  - {name: bc4, params: {ratio: [0.001, 0.01], epsilon: 1e-8}}
problems:
  - {name: chain, params: {w: [5, 10, 20]}}
)", "spec.yaml");
  // (1 + 2 algorithm points) x 3 problem points x 2 seeds.
  ASSERT_EQ(spec.runs.size(), 18u);
  EXPECT_EQ(spec.runs[0].spec.algorithm, "hc4");
  EXPECT_EQ(spec.runs[0].spec.problem_params.at("w"), "5");
  EXPECT_EQ(spec.runs[0].spec.seed, 1u);
  EXPECT_EQ(spec.runs[0].spec.timeout_s, 30);
  int bc4 = 0;
  for (const PlannedRun& r : spec.runs) {
    if (r.spec.algorithm != "bc4") continue;
    ++bc4;
    EXPECT_EQ(r.spec.algorithm_params.at("epsilon"), "1e-08");  // canonical spelling
    EXPECT_TRUE(r.skip_reason.empty());
  }
  EXPECT_EQ(bc4, 12);
}

TEST(SpecTest, RunsAreKeyedOnEffectiveParameters) {
  // The same computation spelled three ways is one run; its key names every
  // parameter with its default, so a changed default makes a new key.
  Spec spec = ParseSpec(R"(
algorithms:
  - hc4
  - {name: hc4, params: {ratio: 0.001}}
  - {name: hc4, params: {ratio: 1e-3, carry: first, max_revise_calls: 1000000}}
  - {name: hc4, params: {ratio: 0.01}}
problems:
  - chain
  - {name: chain, params: {w: 20, gps_error: 2.50}}
)", "spec.yaml");
  ASSERT_EQ(spec.runs.size(), 2u);
  const RunSpec& a = spec.runs[0].spec;
  EXPECT_EQ(a.algorithm_params,
            (ParamMap{{"carry", "first"}, {"max_revise_calls", "1000000"}, {"ratio", "0.001"}}));
  EXPECT_EQ(a.problem_params.at("w"), "20");
  EXPECT_EQ(a.problem_params.at("heading_known"), "false");
  EXPECT_NE(a.Key().find("ratio=0.001"), std::string::npos) << a.Key();
  EXPECT_NE(a.Key(), spec.runs[1].spec.Key());
  EXPECT_EQ(spec.runs[1].spec.algorithm_params.at("ratio"), "0.01");
}

TEST(SpecTest, CarTracksLegacyCarryMovesToTheAlgorithms) {
  Spec spec = ParseSpec(R"(
algorithms: [hc4, bc4]
problems:
  - {name: car-track, params: {steps: 5, carry: all}}
)", "spec.yaml");
  ASSERT_EQ(spec.runs.size(), 2u);
  for (const PlannedRun& r : spec.runs) {
    EXPECT_EQ(r.spec.algorithm_params.at("carry"), "all");
    EXPECT_EQ(r.spec.problem_params.count("carry"), 0u);
  }
  EXPECT_NE(ErrorOf(R"(
algorithms: [hc4]
problems:
  - {name: car-track, params: {carry: [first, all]}}
)").find("car-track.carry moved to the algorithms"), std::string::npos);
}

TEST(SpecTest, ExperimentsOverrideSeedsAndTimeoutAndDuplicatesAreRemoved) {
  Spec spec = ParseSpec(R"(
repetitions: 3
experiments:
  - name: a
    algorithms: [hc4]
    problems: [chain]
  - name: b
    seeds: [1]
    timeout_s: 5
    algorithms: [hc4, bc3]
    problems: [chain]
)", "spec.yaml");
  // a: hc4 x seeds 1..3; b: hc4 seed 1 (a duplicate of a's) + bc3 seed 1.
  ASSERT_EQ(spec.runs.size(), 4u);
  EXPECT_EQ(spec.runs[0].experiment, "a");
  EXPECT_EQ(spec.runs[3].spec.algorithm, "bc3");
  EXPECT_EQ(spec.runs[3].experiment, "b");
  EXPECT_EQ(spec.runs[3].spec.timeout_s, 5);
  EXPECT_EQ(spec.runs[0].spec.timeout_s, 600);
}

TEST(SpecTest, ErrorsNameTheFileLineAndKey) {
  EXPECT_EQ(ErrorOf("algorithms: [hc4]\nproblems: [chain]\nspeed: 3\n"),
            "spec.yaml:3:1: key 'speed': unknown key (expected one of: algorithms, description, "
            "experiments, memory_limit_mb, name, problems, record, repetitions, seeds, timeout_s)");
  EXPECT_EQ(ErrorOf("algorithms: [hc5]\nproblems: [chain]\n").substr(0, 60),
            "spec.yaml:1:14: key 'algorithms[0]': unknown algorithm 'hc5'");
  std::string e = ErrorOf("algorithms:\n  - {name: hc4, params: {ratio: 2}}\nproblems: [chain]\n");
  EXPECT_NE(e.find("spec.yaml:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("hc4.ratio = 2: must be in [0, 1)"), std::string::npos) << e;
  e = ErrorOf("algorithms: [hc4]\nproblems:\n  - {name: chain, params: {window: 3}}\n");
  EXPECT_NE(e.find("spec.yaml:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown parameter 'window' for chain"), std::string::npos) << e;
  e = ErrorOf("algorithms: [hc4]\nproblems: [chain]\nseeds: [1, x]\n");
  EXPECT_NE(e.find("spec.yaml:3:12: key 'seeds[1]'"), std::string::npos) << e;
  e = ErrorOf("algorithms: [hc4]\nproblems: [chain]\ntimeout_s: -1\n");
  EXPECT_NE(e.find("key 'timeout_s'"), std::string::npos) << e;
  e = ErrorOf("algorithms: [hc4\nproblems: [chain]\n");
  EXPECT_NE(e.find("spec.yaml:"), std::string::npos) << e;  // YAML syntax error with position
  EXPECT_NE(ErrorOf("algorithms: []\nproblems: [chain]\n").find("non-empty list"), std::string::npos);
  EXPECT_NE(ErrorOf("problems: [chain]\n").find("key 'algorithms'"), std::string::npos);
  EXPECT_NE(ErrorOf("").find("empty spec"), std::string::npos);
  // A problem's file that cannot be read: the spec's line and key, then the file's.
  e = ErrorOf("algorithms: [hc4]\nproblems:\n  - {name: minibex-file, params: {file: /nonexistent.bch}}\n");
  EXPECT_NE(e.find("spec.yaml:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("key 'problems[0]"), std::string::npos) << e;
  EXPECT_NE(e.find("cannot open '/nonexistent.bch'"), std::string::npos) << e;
  EXPECT_NE(ErrorOf("experiments:\n  - algorithms: [hc4]\n    problem: [chain]\n").find(
                "key 'experiments[0].problem': unknown key"),
            std::string::npos);
}

TEST(SpecTest, NonScalarKeysNameTheFileLineAndKey) {
  EXPECT_EQ(ErrorOf("? [a, b]\n: 1\nalgorithms: [hc4]\nproblems: [chain]\n"),
            "spec.yaml:1:3: a key must be a single value, not a list");
  EXPECT_EQ(ErrorOf("algorithms: [hc4]\nproblems:\n  - {name: chain, params: {[x]: 1}}\n"),
            "spec.yaml:3:28: key 'problems[0].params': a key must be a single value, not a list");
  EXPECT_EQ(ErrorOf("experiments:\n  - {{a: 1}: 2, algorithms: [hc4], problems: [chain]}\n"),
            "spec.yaml:2:6: key 'experiments[0]': a key must be a single value, not a mapping");
}

TEST(SpecTest, DuplicateKeysAndExperimentNamesAreRejected) {
  EXPECT_EQ(ErrorOf("algorithms: [hc4]\nproblems: [chain]\nalgorithms: [bc4]\n"),
            "spec.yaml:3:1: key 'algorithms': duplicated key (first at line 1:1)");
  EXPECT_EQ(ErrorOf("algorithms: [hc4]\nproblems:\n  - {name: chain, params: {w: 3, w: 4}}\n"),
            "spec.yaml:3:34: key 'problems[0].params.w': duplicated key (first at line 3:28)");
  EXPECT_EQ(ErrorOf("experiments:\n"
                    "  - {name: a, algorithms: [hc4], problems: [chain]}\n"
                    "  - {name: a, algorithms: [bc4], problems: [chain]}\n"),
            "spec.yaml:3:12: key 'experiments[1].name': experiment 'a' is already the name of "
            "experiments[0]");
  // A default name counts too.
  EXPECT_NE(ErrorOf("experiments:\n"
                    "  - {name: experiment2, algorithms: [hc4], problems: [chain]}\n"
                    "  - {algorithms: [bc4], problems: [chain]}\n")
                .find("spec.yaml:3:5: key 'experiments[1].name': experiment 'experiment2'"),
            std::string::npos);
}

TEST(SpecTest, MissingFileIsASpecError) {
  EXPECT_THROW(LoadSpec("/nonexistent/spec.yaml"), SpecError);
  try {
    LoadSpec("/tmp");
    ADD_FAILURE() << "a directory was read as a spec";
  } catch (const SpecError& e) {
    EXPECT_EQ(std::string(e.what()), "/tmp: is a directory");
  }
  // /dev/zero never ends: read, it would fill memory.
  try {
    LoadSpec("/dev/zero");
    ADD_FAILURE() << "a device was read as a spec";
  } catch (const SpecError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: is a device or a socket, not a spec file");
  }
}

}  // namespace
}  // namespace icp

namespace icp {
namespace {

TEST(SpecTest, MemoryLimitHasADefaultAnOverrideAndARange) {
  const Spec spec = ParseSpec(R"(
memory_limit_mb: 1024
experiments:
  - {name: a, algorithms: [hc4], problems: [chain]}
  - {name: b, memory_limit_mb: 0, algorithms: [bc4], problems: [chain]}
)", "spec.yaml");
  ASSERT_EQ(spec.runs.size(), 2u);
  EXPECT_EQ(spec.runs[0].spec.memory_limit_mb, 1024);
  EXPECT_EQ(spec.runs[1].spec.memory_limit_mb, 0);  // no limit
  EXPECT_EQ(ParseSpec("algorithms: [hc4]\nproblems: [chain]\n", "s").runs[0].spec.memory_limit_mb,
            kDefaultMemoryLimitMb);
  // Not part of a run's identity, like the timeout.
  EXPECT_EQ(spec.runs[0].spec.Key().find("memory"), std::string::npos);
  EXPECT_NE(ErrorOf("memory_limit_mb: 8\nalgorithms: [hc4]\nproblems: [chain]\n")
                .find("spec.yaml:1:18: key 'memory_limit_mb': '8' is below the least a worker needs"),
            std::string::npos)
      << ErrorOf("memory_limit_mb: 8\nalgorithms: [hc4]\nproblems: [chain]\n");
  EXPECT_NE(ErrorOf("memory_limit_mb: lots\nalgorithms: [hc4]\nproblems: [chain]\n").find("not a positive number"),
            std::string::npos);
}

}  // namespace
}  // namespace icp

namespace icp {
namespace {

// A second YAML document would be dropped by a one-document load: it is
// refused at its line. An empty one (a trailing '---') is harmless.
TEST(SpecTest, ASecondDocumentIsRefused) {
  EXPECT_NE(ErrorOf("algorithms: [hc4]\nproblems: [chain]\n---\nalgorithms: [bc4]\nproblems: [chain]\n")
                .find("spec.yaml:4:1: a second YAML document"),
            std::string::npos)
      << ErrorOf("algorithms: [hc4]\nproblems: [chain]\n---\nalgorithms: [bc4]\nproblems: [chain]\n");
  EXPECT_EQ(ParseSpec("---\nalgorithms: [hc4]\nproblems: [chain]\n---\n", "s").runs.size(), 1u);
}

// A log longer than `steps` is cut, and the spec says so once (it was cut
// without a word).
TEST(SpecTest, ALogLongerThanStepsIsNoted) {
  const std::string log =
      (std::filesystem::temp_directory_path() / ("spec_test_log_" + std::to_string(::getpid()) + ".csv"))
          .string();
  CarTrackParams p;
  p.steps = 40;
  {
    std::ofstream out(log);
    WriteCarTrackLog(SimulateCarTrack(p, 1), out);
  }
  const Spec cut = ParseSpec("algorithms: [hc4, bc4]\nproblems:\n  - {name: car-track, params: "
                             "{log: " + log + ", steps: 30, w: [5, 10]}}\n",
                             "s");
  EXPECT_EQ(cut.notes, (std::vector<std::string>{"car-track: the log " + log +
                                                 " has 40 rows; steps = 30 uses the first 30 "
                                                 "(give steps: 40 to use them all)"}));
  const Spec whole = ParseSpec(
      "algorithms: [hc4]\nproblems:\n  - {name: car-track, params: {log: " + log + ", steps: 40}}\n",
      "s");
  EXPECT_TRUE(whole.notes.empty());
  std::filesystem::remove(log);
}

// A spec with neither experiments nor algorithms says what it needs (it
// named 'algorithms' only).
TEST(SpecTest, ASpecWithoutExperimentsOrAlgorithmsSaysWhatItNeeds) {
  EXPECT_NE(ErrorOf("{}\n").find("a spec needs 'experiments'"), std::string::npos) << ErrorOf("{}\n");
  EXPECT_NE(ErrorOf("name: x\n").find("or 'algorithms' and 'problems'"), std::string::npos);
}

// A misspelt key or name is answered with the likely one.
TEST(SpecTest, AMisspeltNameIsSuggested) {
  EXPECT_NE(ErrorOf("seed: [1]\nalgorithms: [hc4]\nproblems: [chain]\n")
                .find("key 'seed': unknown key; did you mean 'seeds'? (expected one of:"),
            std::string::npos);
  EXPECT_NE(ErrorOf("algorithms: [hc44]\nproblems: [chain]\n").find("did you mean 'hc4'?"),
            std::string::npos);
  EXPECT_NE(ErrorOf("algorithms: [hc4]\nproblems: [chian]\n").find("did you mean 'chain'?"),
            std::string::npos);
  EXPECT_NE(ErrorOf("algorithms: [{name: 3b-bc4, params: {inner: {epsilon: 1e-8}}}]\n"
                    "problems: [chain]\n")
                .find("written with a dot: 'inner.epsilon: VALUE'"),
            std::string::npos);
}

// A stray ',' made yaml-cpp's LoadAll loop forever (found by the fuzzer):
// such text is an empty or bad spec, answered at once.
TEST(SpecTest, AStrayCommaIsAnsweredNotLoopedOn) {
  EXPECT_THROW(ParseSpec(",", "s"), SpecError);
  EXPECT_THROW(ParseSpec("algorithms: [hc4]\nproblems: [chain]\n,\n", "s"), SpecError);
  EXPECT_THROW(ParseSpec("- a\n,\n", "s"), SpecError);
}

// -0 is 0: one spelling, so one run key.
TEST(SpecTest, MinusZeroIsZero) {
  const Spec spec = ParseSpec("algorithms: [{name: hc4, params: {ratio: [0, -0, -0.0, 0e5]}}]\nproblems: [chain]\n", "s");
  ASSERT_EQ(spec.runs.size(), 1u);
  EXPECT_EQ(spec.runs[0].spec.algorithm_params.at("ratio"), "0");
}

// Numbers are decimal: hexadecimal text (strtod's 0x10) is refused, and a
// seed may be spelt as integer parameters are (1.0, 1e3).
TEST(SpecTest, NumbersAreDecimalAndSeedsTakeIntegerSpellings) {
  EXPECT_NE(ErrorOf("timeout_s: 0x10\nalgorithms: [hc4]\nproblems: [chain]\n")
                .find("'0x10' is not a positive number"),
            std::string::npos);
  EXPECT_NE(ErrorOf("algorithms: [{name: hc4, params: {ratio: 0x0.1p0}}]\nproblems: [chain]\n")
                .find("not a number"),
            std::string::npos);
  const Spec spec = ParseSpec("seeds: [1.0, 1, 1e3, 2]\nalgorithms: [hc4]\nproblems: [chain]\n", "s");
  ASSERT_EQ(spec.runs.size(), 3u);  // 1.0 and 1 are one seed
  EXPECT_EQ(spec.runs[1].spec.seed, 1000u);
  // 2^53 + 1 has no double: spelt as a decimal it would read as 2^53.
  EXPECT_EQ(ParseSpec("seeds: [9007199254740992.0, 9007199254740993]\nalgorithms: [hc4]\nproblems: [chain]\n", "s")
                .runs.size(),
            2u);
  for (const char* bad : {"1.5", "-1", "1e300", "x", "9007199254740993.0", "9007199254740994.0"})
    EXPECT_NE(ErrorOf(std::string("seeds: [") + bad + "]\nalgorithms: [hc4]\nproblems: [chain]\n")
                  .find("is not a non-negative integer"),
              std::string::npos)
        << bad;
}

// Aliases nest cheaply in YAML (each level naming the one before twice):
// the duplicate-key check visits each node once, and grids are counted
// against the run limit before they are resolved, so neither a deep nest
// nor many aliased large grids costs more than its text.
TEST(SpecTest, NestedAliasesCostTheirTextNotTheirExpansion) {
  std::string laughs = "anchors: {l0: &l0 [a, a]";
  for (int i = 1; i <= 40; ++i)
    laughs += ", l" + std::to_string(i) + ": &l" + std::to_string(i) + " [*l" + std::to_string(i - 1) +
              ", *l" + std::to_string(i - 1) + "]";
  laughs += "}\nalgorithms: [hc4]\nproblems: [chain]\n";
  // 2^40 leaves, which would never end if walked: the unknown key is seen.
  EXPECT_NE(ErrorOf(laughs).find("key 'anchors': unknown key"), std::string::npos) << ErrorOf(laughs);

  std::string values = "[";
  for (int i = 0; i < 100; ++i) values += (i ? ", " : "") + std::to_string(i + 1) + "e-9";
  values += "]";
  std::string seeds = "seeds: [";
  for (int i = 1; i <= 100; ++i) seeds += (i > 1 ? ", " : "") + std::to_string(i);
  std::string grids = seeds + "]\nalgorithms:\n  - &big {name: hc4, params: {ratio: " + values +
                      ", max_revise_calls: " + values + "}}\n";
  for (int i = 0; i < 200; ++i) grids += "  - *big\n";
  grids += "problems: [chain]\n";
  // 201 grids of 10^4 points, 100 seeds: the second grid passes the limit.
  const std::string error = ErrorOf(grids);
  EXPECT_NE(error.find("key 'algorithms[1]': the run matrix has at least 2000000 runs, more than the limit of 1000000"), std::string::npos)
      << error;
}

// A description is free text: one value, not a list or a mapping.
TEST(SpecTest, ADescriptionIsText) {
  EXPECT_NE(ErrorOf("description: [a, b]\nalgorithms: [hc4]\nproblems: [chain]\n")
                .find("key 'description': expected a single value"),
            std::string::npos);
  EXPECT_NE(ErrorOf("experiments:\n  - {description: {a: 1}, algorithms: [hc4], problems: [chain]}\n")
                .find("key 'experiments[0].description'"),
            std::string::npos);
}

// Runs are stored under SPEC#NAME and read back after the last '#'.
TEST(SpecTest, AnExperimentNameCannotHoldAHash) {
  EXPECT_NE(ErrorOf("experiments:\n  - {name: 'a#b', algorithms: [hc4], problems: [chain]}\n")
                .find("cannot hold '#'"),
            std::string::npos);
}

// What an outside probe of specs found, each refused with its reason.
TEST(SpecTest, AnExperimentNameIsNotEmptyAndTheSpecsNameIsCheckedToo) {
  // Empty, it was stored without its '#' and read back from the spec's path.
  EXPECT_NE(ErrorOf("experiments:\n  - {name: '', algorithms: [hc4], problems: [chain]}\n")
                .find("cannot be empty"),
            std::string::npos);
  EXPECT_NE(ErrorOf("experiments:\n  - {name: \"a\\0b\", algorithms: [hc4], problems: [chain]}\n")
                .find("control character"),
            std::string::npos);
  EXPECT_NE(ErrorOf("name: [1, 2]\nexperiments:\n  - {name: a, algorithms: [hc4], problems: [chain]}\n")
                .find("key 'name'"),
            std::string::npos);
  EXPECT_NE(ErrorOf("name: x#y\nexperiments:\n  - {name: a, algorithms: [hc4], problems: [chain]}\n")
                .find("cannot hold '#'"),
            std::string::npos);
}

TEST(SpecTest, AMergeKeyIsSaidToBeUnsupported) {
  const std::string error = ErrorOf(
      "algorithms: [hc4]\nproblems:\n  - {name: car-track, params: &d {steps: 10, w: 3}}\n"
      "  - {name: car-track, params: {<<: *d, w: 4}}\n");
  EXPECT_NE(error.find("merge keys (<<) are not supported"), std::string::npos) << error;
}

TEST(SpecTest, SeedsAreDecimalDigitsAndLimitsTakeEverySpellingOfZeroAndInfinity) {
  for (const char* bad : {"0x10", " 5"})
    EXPECT_NE(ErrorOf(std::string("seeds: ['") + bad + "']\nalgorithms: [hc4]\nproblems: [chain]\n")
                  .find("is not a non-negative integer"),
              std::string::npos)
        << bad;
  EXPECT_NE(ErrorOf("repetitions: 0x10\nalgorithms: [hc4]\nproblems: [chain]\n").find("not a non-negative"),
            std::string::npos);
  for (const char* zero : {"0", "0.0", "-0"})
    EXPECT_EQ(ParseSpec(std::string("memory_limit_mb: ") + zero + "\nalgorithms: [hc4]\nproblems: [chain]\n", "s")
                  .runs[0].spec.memory_limit_mb,
              0)
        << zero;
  EXPECT_EQ(ParseSpec("memory_limit_mb: .inf\nalgorithms: [hc4]\nproblems: [chain]\n", "s").runs[0].spec.memory_limit_mb,
            kInf);
}

TEST(SpecTest, ATabInTheIndentationIsNamed) {
  const std::string error = ErrorOf("algorithms:\n\t- hc4\nproblems: [chain]\n");
  EXPECT_NE(error.find("line 2 is indented with a tab"), std::string::npos) << error;
}

TEST(SpecTest, AValueThatUnderflowsIsRefusedNotReadAsZero) {
  // ratio: 1e-400 ran, and was stored, as ratio=0.
  EXPECT_NE(ErrorOf("algorithms: [{name: hc4, params: {ratio: 1e-400}}]\nproblems: [chain]\n").find("ratio"),
            std::string::npos);
  EXPECT_EQ(ErrorOf("algorithms: [{name: hc4, params: {ratio: 1e-310}}]\nproblems: [chain]\n"), "no error");
}

}  // namespace
}  // namespace icp
