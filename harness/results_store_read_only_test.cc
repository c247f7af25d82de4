// The results store's tests of read-only opens: nothing written, a live
// writer's runs seen, old versions read as they are, bad files refused.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "harness/results_store.h"
#include "harness/results_store_testing.h"

namespace icp {
namespace {

using testing::ExpectSameRun;
using testing::FileBytes;
using testing::FreshDir;
using testing::FreshPath;
using testing::MakeRun;
using testing::WriteVersionOneStore;

// A read-only open writes nothing: not the file, no -wal/-shm (tests may
// run as root, where permissions do not stop writes, so the bytes and the
// directory listing are checked too).
TEST(ResultsStoreReadOnlyTest, ReadsAReadOnlyStoreWithoutWritingIt) {
  namespace fs = std::filesystem;
  const std::string dir = FreshDir("readonly");
  const std::string path = StorePath(dir);
  {
    ResultsStore store(path);
    store.Insert(MakeRun(1, 6));
    store.Insert(MakeRun(2, 6, "bc4"));
  }
  ASSERT_FALSE(fs::exists(path + "-wal"));
  const std::string before = FileBytes(path);
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                           fs::perms::group_exec);
  {
    std::unique_ptr<ResultsStore> store = ResultsStore::OpenReadOnly(path);
    EXPECT_EQ(store->schema_version(), 3);
    const std::vector<RunRecord> runs = store->LoadRuns(true);
    ASSERT_EQ(runs.size(), 2u);
    ExpectSameRun(MakeRun(2, 6, "bc4"), runs[1], true);
    EXPECT_THROW(store->Insert(MakeRun(3, 6)), StoreError);
  }
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"results.sqlite"}));
  EXPECT_EQ(FileBytes(path), before);
  fs::permissions(dir, fs::perms::owner_all);
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
}

// While a writer has the store open (a -wal exists) a reader sees its
// committed runs.
TEST(ResultsStoreReadOnlyTest, SeesTheRunsOfAnOpenWriter) {
  const std::string path = FreshPath("readonly_live");
  ResultsStore writer(path);
  writer.Insert(MakeRun(1, 3));
  ASSERT_TRUE(std::filesystem::exists(path + "-wal"));
  EXPECT_EQ(ResultsStore::OpenReadOnly(path)->LoadRuns(false).size(), 1u);
  writer.Insert(MakeRun(2, 3));
  EXPECT_EQ(ResultsStore::OpenReadOnly(path)->LoadRuns(false).size(), 2u);
}

// Old versions are read as they are, not migrated.
TEST(ResultsStoreReadOnlyTest, ReadsAVersionOneStoreWithoutMigratingIt) {
  const std::string path = FreshPath("readonly_v1");
  WriteVersionOneStore(path);
  const std::string before = FileBytes(path);
  {
    std::unique_ptr<ResultsStore> store = ResultsStore::OpenReadOnly(path);
    EXPECT_EQ(store->schema_version(), 1);
    const std::vector<RunRecord> runs = store->LoadRuns(true);
    ASSERT_EQ(runs.size(), 1u);
    ASSERT_EQ(runs[0].steps.size(), 1u);
    EXPECT_EQ(runs[0].steps[0].estimate, "box");
    EXPECT_TRUE(store->Attempts().empty());
  }
  EXPECT_EQ(FileBytes(path), before);
}

TEST(ResultsStoreReadOnlyTest, AMissingEmptyOrForeignFileIsAnError) {
  const std::string missing = FreshPath("readonly_missing");
  const std::string empty = FreshPath("readonly_empty");
  std::ofstream(empty).close();
  for (const auto& [path, what] : {std::pair{missing, "no such file"},
                                   std::pair{empty, "empty file (0 bytes)"}}) {
    try {
      ResultsStore::OpenReadOnly(path);
      FAIL() << "expected StoreError for " << path;
    } catch (const StoreError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(missing));
  EXPECT_EQ(std::filesystem::file_size(empty), 0u);
  const std::string foreign = FreshPath("readonly_foreign");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(foreign.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "CREATE TABLE t(a)", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  EXPECT_THROW(ResultsStore::OpenReadOnly(foreign), StoreError);
}

}  // namespace
}  // namespace icp
