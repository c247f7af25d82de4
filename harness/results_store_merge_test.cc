// The results store's tests of merging: MergeFrom into an open store, and
// MergeStores into a new file, with which copy of a run is kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "harness/directory_lock.h"
#include "harness/results_store.h"
#include "harness/results_store_testing.h"

namespace icp {
namespace {

using testing::ExpectSameRun;
using testing::FileBytes;
using testing::FreshDir;
using testing::FreshPath;
using testing::MakeRun;

TEST(ResultsStoreTest, MergeFromCopiesOnlyAbsentRuns) {
  const std::string path_a = FreshPath("merge_a");
  const std::string path_b = FreshPath("merge_b");
  {
    ResultsStore b(path_b);
    for (int i : {2, 3, 4}) b.Insert(MakeRun(i, 6, "bc4"));
    RunRecord overlap = MakeRun(1, 6);
    overlap.reason = "from b";
    b.Insert(overlap);
  }
  ResultsStore a(path_a);
  for (int i : {0, 1}) a.Insert(MakeRun(i, 6));
  EXPECT_EQ(a.MergeFrom(path_b), 3);
  EXPECT_EQ(a.MergeFrom(path_b), 0);  // idempotent

  std::vector<RunRecord> loaded = a.LoadRuns(true);
  ASSERT_EQ(loaded.size(), 5u);
  ExpectSameRun(MakeRun(0, 6), loaded[0], true);
  ExpectSameRun(MakeRun(1, 6), loaded[1], true);  // a's copy kept
  for (int i : {2, 3, 4}) ExpectSameRun(MakeRun(i, 6, "bc4"), loaded[i], true);
  ResultsStore b(path_b);
  EXPECT_EQ(b.RunKeys().size(), 4u);  // the source is left as it was
}

TEST(ResultsStoreTest, MergeFromMissingStoreFailsAndCreatesNothing) {
  const std::string path = FreshPath("merge_missing");
  const std::string missing = FreshPath("does_not_exist");
  ResultsStore store(path);
  try {
    store.MergeFrom(missing);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(missing));
}

// MergeFrom prefers an ok copy over a timeout one, whichever store has it.
TEST(ResultsStoreTest, MergeFromPrefersOkOverTimeout) {
  const std::string path_a = FreshPath("merge_pref_a");
  const std::string path_b = FreshPath("merge_pref_b");
  RunRecord ok = MakeRun(3, 4);
  ok.status = RunStatus::kOk;
  ok.reason = "";
  const RunRecord timeout = MakeRun(3, 4);
  { ResultsStore(path_b).Insert(ok); }
  ResultsStore a(path_a);
  a.Insert(timeout);
  EXPECT_EQ(a.MergeFrom(path_b), 1);
  ASSERT_EQ(a.StoredRuns().size(), 1u);
  EXPECT_EQ(a.StoredRuns()[0].status, RunStatus::kOk);
  ASSERT_EQ(a.Attempts().size(), 1u);
  EXPECT_EQ(a.Attempts()[0].status, RunStatus::kTimeout);
}

TEST(MergeStoresTest, PrefersOkAndSaysWhatItDidAboutConflicts) {
  const std::string a = FreshDir("merge_a");
  const std::string b = FreshDir("merge_b");
  const std::string out = FreshDir("merge_out");
  std::filesystem::remove_all(out);  // OUT need not exist
  RunRecord ok3 = MakeRun(3, 4);     // MakeRun(3) is a timeout; this its ok copy
  ok3.status = RunStatus::kOk;
  ok3.reason = "";
  RunRecord ok7 = MakeRun(7, 4);
  ok7.status = RunStatus::kOk;
  ok7.reason = "";
  {
    ResultsStore sa(StorePath(a));
    sa.Insert(MakeRun(3, 4));  // timeout first: a keep-first merge would keep it
    sa.Insert(ok7);
    sa.Insert(MakeRun(1, 4));
  }
  {
    ResultsStore sb(StorePath(b));
    sb.Insert(ok3);
    sb.Insert(MakeRun(7, 4));  // a timeout that must not replace a's ok
    RunRecord later1 = MakeRun(1, 4);  // equal status, another measurement: a's kept
    later1.provenance.date = "2026-02-02T00:00:00Z";
    sb.Insert(later1);
    sb.Insert(MakeRun(2, 4));
    sb.Insert(MakeRun(5, 4));
  }
  {
    ResultsStore sa(StorePath(a));
    sa.Insert(MakeRun(5, 4));  // the very same run in both: no conflict, no attempt
  }
  const MergeSummary m = MergeStores(out, {a, b});
  EXPECT_EQ(m.runs, 5);
  EXPECT_EQ(m.from_input, (std::vector<int>{3, 2}));
  EXPECT_EQ(m.duplicates, 3);
  EXPECT_EQ(m.equal_kept_first, 1);
  EXPECT_EQ(m.ConflictMessage(),
            "merge: 3 conflicting keys: kept ok over timeout for 2, kept the first of "
            "equal-status copies for 1 (dropped copies are in table attempts)");

  std::map<std::string, RunStatus> status;
  {
    std::unique_ptr<ResultsStore> merged = ResultsStore::OpenReadOnly(StorePath(out));
    for (const StoredRun& r : merged->StoredRuns()) status[r.key] = r.status;
    EXPECT_EQ(merged->Attempts().size(), 3u);  // every dropped copy
    for (const RunRecord& r : merged->LoadRuns(true)) {
      if (r.spec.Key() == ok3.spec.Key()) ExpectSameRun(ok3, r, true);
    }
  }
  EXPECT_EQ(status.size(), 5u);
  EXPECT_EQ(status[ok3.spec.Key()], RunStatus::kOk);
  EXPECT_EQ(status[ok7.spec.Key()], RunStatus::kOk);
  // One complete file: no WAL, no temporary left in OUT (and the emptied lock).
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(out))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{".lock", "results.sqlite"}));

  // Merging again into the existing OUT keeps it as the first input.
  const MergeSummary again = MergeStores(out, {b});
  EXPECT_EQ(again.runs, 5);
  EXPECT_EQ(again.from_input, (std::vector<int>{0}));
  EXPECT_EQ(again.duplicates, 2);  // b's timeout 7 and later 1 differ from OUT's copies
  std::unique_ptr<ResultsStore> merged = ResultsStore::OpenReadOnly(StorePath(out));
  EXPECT_EQ(merged->Attempts().size(), 3u);  // and are in its attempts already: not added
}

// A run writing OUT holds its lock: a merge into OUT then refuses, leaving
// OUT as it was (it used to rename a new file over the one the run went on
// writing, and the run's later runs were lost).
TEST(MergeStoresTest, RefusesAnOutThatARunHolds) {
  const std::string in = FreshDir("merge_locked_in");
  const std::string out = FreshDir("merge_locked_out");
  ResultsStore(StorePath(in)).Insert(MakeRun(1, 4));
  ResultsStore(StorePath(out)).Insert(MakeRun(2, 4));
  const std::string before = FileBytes(StorePath(out));
  std::ostringstream messages;
  {
    DirectoryLock held(out, messages);  // as `run` holds it
    EXPECT_THROW(MergeStores(out, {in}), DirectoryLockedError);
    EXPECT_EQ(FileBytes(StorePath(out)), before);
  }
  EXPECT_EQ(MergeStores(out, {in}).runs, 2);  // released: it merges
}

// What a killed merge left in OUT (its temporary store and side files) is
// removed by the next merge, which holds OUT's lock.
TEST(MergeStoresTest, RemovesWhatAKilledMergeLeft) {
  const std::string in = FreshDir("merge_stale_in");
  const std::string out = FreshDir("merge_stale_out");
  ResultsStore(StorePath(in)).Insert(MakeRun(1, 4));
  for (const char* suffix : {"", "-wal", "-shm"})
    std::ofstream(StorePath(out) + ".merge-999999.tmp" + suffix) << "left by a killed merge";
  EXPECT_EQ(MergeStores(out, {in}).runs, 1);
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(out))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{".lock", "results.sqlite"}));
}

TEST(MergeStoresTest, AMissingOrBadInputLeavesOutAsItWas) {
  const std::string a = FreshDir("merge_in_a");
  const std::string missing = FreshDir("merge_in_missing");
  const std::string empty = FreshDir("merge_in_empty");
  const std::string out = FreshDir("merge_out2");
  { ResultsStore(StorePath(a)).Insert(MakeRun(1, 4)); }
  std::ofstream(StorePath(empty)).close();  // zero bytes
  // No OUT store yet: a failed merge creates none.
  EXPECT_THROW(MergeStores(out, {a, missing}), StoreError);
  EXPECT_FALSE(std::filesystem::exists(StorePath(out)));
  EXPECT_THROW(MergeStores(out, {a, empty}), StoreError);
  EXPECT_FALSE(std::filesystem::exists(StorePath(out)));
  EXPECT_EQ(std::filesystem::file_size(StorePath(empty)), 0u);  // not made a store
  const std::string out_missing_dir = ::testing::TempDir() + "/icpbench_store_dir_merge_nodir";
  std::filesystem::remove_all(out_missing_dir);
  EXPECT_THROW(MergeStores(out_missing_dir, {missing}), StoreError);
  EXPECT_FALSE(std::filesystem::exists(out_missing_dir));
  // An OUT store stays byte for byte as it was.
  MergeStores(out, {a});
  const std::string before = FileBytes(StorePath(out));
  ASSERT_FALSE(before.empty());
  try {
    MergeStores(out, {a, missing});
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find(StorePath(missing)), std::string::npos) << e.what();
  }
  EXPECT_EQ(FileBytes(StorePath(out)), before);
}

}  // namespace
}  // namespace icp
