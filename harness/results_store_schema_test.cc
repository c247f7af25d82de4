// The results store's tests of opening a file: schema versions and their
// migration, and the errors for bad paths, foreign files and no descriptors.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "harness/environment_error.h"
#include "harness/results_store.h"
#include "harness/results_store_internal.h"
#include "harness/results_store_testing.h"

namespace icp {
namespace {

using testing::ExpectSameRun;
using testing::FreshPath;
using testing::MakeRun;
using testing::RawQuery;
using testing::WriteVersionOneStore;

// A store written by schema version 1 (no estimate kind, no properties) is
// migrated when opened: its runs load, new runs with properties go in.
TEST(ResultsStoreTest, MigratesAVersionOneStore) {
  const std::string path = FreshPath("v1");
  WriteVersionOneStore(path);
  {
    ResultsStore store(path);
    const std::vector<RunRecord> runs = store.LoadRuns(true);
    ASSERT_EQ(runs.size(), 1u);
    ASSERT_EQ(runs[0].steps.size(), 1u);
    EXPECT_EQ(runs[0].steps[0].estimate, "box");
    EXPECT_TRUE(runs[0].steps[0].properties.empty());
    EXPECT_EQ(runs[0].steps[0].vars[0].hi, 1);
    store.Insert(MakeRun(1, 5));
    ASSERT_EQ(store.LoadRuns(true).size(), 2u);
    ExpectSameRun(MakeRun(1, 5), store.LoadRuns(true)[1], true);
    EXPECT_TRUE(store.Attempts().empty());
  }
  EXPECT_EQ(RawQuery(path, "SELECT value FROM meta WHERE key='schema_version'"), "3");
  EXPECT_EQ(RawQuery(path, "SELECT count(*) FROM attempts"), "0");
}

// A version-2 store (no attempts table) is migrated to version 3.
TEST(ResultsStoreTest, MigratesAVersionTwoStore) {
  const std::string path = FreshPath("v2");
  {
    ResultsStore store(path);
    store.Insert(MakeRun(3, 4));
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db,
                         "DROP TABLE attempts; UPDATE meta SET value='2' WHERE key='schema_version'",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  {
    ResultsStore store(path);
    EXPECT_EQ(store.schema_version(), 3);
    RunRecord retry = MakeRun(3, 4);
    retry.status = RunStatus::kOk;
    store.Insert(retry);
    ASSERT_EQ(store.Attempts().size(), 1u);
    EXPECT_EQ(store.Attempts()[0].status, RunStatus::kTimeout);
  }
  EXPECT_EQ(RawQuery(path, "SELECT value FROM meta WHERE key='schema_version'"), "3");
}

TEST(ResultsStoreTest, RejectsAnotherSchemaVersion) {
  const std::string path = FreshPath("version");
  { ResultsStore store(path); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE meta SET value='99' WHERE key='schema_version'", nullptr,
                         nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  try {
    ResultsStore store(path);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("schema version '99'"), std::string::npos) << e.what();
  }
}

// Out of file descriptors when the store is opened: the environment (exit
// code 3 in the CLI), not bad input. Run in a child, whose limit is lowered
// to the descriptors it already has.
TEST(ResultsStoreTest, NoDescriptorLeftToOpenIsTheEnvironment) {
#if defined(ICPBENCH_SANITIZED)
  // UBSan's vptr check tests memory with a pipe; without descriptors it
  // reports a virtual call on a valid object (e.what() here) as invalid.
  GTEST_SKIP() << "the sanitizers' runtime needs descriptors of its own";
#endif
  const std::string path = FreshPath("no_fd");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // Less one: the listing's own descriptor, closed once it is read.
    const auto open_now = std::distance(std::filesystem::directory_iterator("/proc/self/fd"),
                                        std::filesystem::directory_iterator{}) - 1;
    const rlimit limit{static_cast<rlim_t>(open_now), static_cast<rlim_t>(open_now)};
    setrlimit(RLIMIT_NOFILE, &limit);
    try {
      ResultsStore store(path);
    } catch (const EnvironmentError& e) {
      _exit(std::string(e.what()).find("ulimit -n") != std::string::npos ? 0 : 2);
    } catch (...) {
      _exit(3);
    }
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "2: no advice, 3: another error, 4: opened";
}

TEST(ResultsStoreTest, BadPathsSayWhatAndWhere) {
  const std::string dir_missing = ::testing::TempDir() + "/icpbench_no_such_dir/sub/results.sqlite";
  try {
    ResultsStore store(dir_missing);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir_missing), std::string::npos) << what;
    EXPECT_NE(what.find("unable to open database file"), std::string::npos) << what;
    EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
  }

  const std::string not_db = FreshPath("not_a_database");
  {
    std::ofstream out(not_db);
    for (int i = 0; i < 100; ++i) out << "this is a text file, not a database\n";
  }
  try {
    ResultsStore store(not_db);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(not_db), std::string::npos) << what;
    EXPECT_NE(what.find("file is not a database"), std::string::npos) << what;
  }

  const std::string foreign = FreshPath("foreign");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(foreign.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "CREATE TABLE t(a)", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string before = bytes(foreign);
  try {
    ResultsStore store(foreign);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("not an icpbench results store"), std::string::npos)
        << e.what();
  }
  // Refused as it was: not switched to WAL, not a byte changed.
  EXPECT_EQ(RawQuery(foreign, "PRAGMA journal_mode"), "delete");
  EXPECT_EQ(bytes(foreign), before);
}

// A full disk is the environment's failure (exit 3, with what to do), also
// where it is met at a plain statement such as COMMIT. (max_page_count makes
// SQLite report a full database.)
TEST(ResultsStoreSchemaTest, AFullDiskIsTheEnvironment) {
  const std::string path = FreshPath("full");
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  detail::Exec(db, path, "CREATE TABLE t(a)");
  detail::Exec(db, path, "PRAGMA max_page_count = 2");
  try {
    detail::Exec(db, path, "BEGIN; INSERT INTO t VALUES (randomblob(100000)); COMMIT;");
    ADD_FAILURE() << "expected EnvironmentError";
  } catch (const EnvironmentError& e) {
    EXPECT_NE(std::string(e.what()).find("free disk space"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  sqlite3_close(db);
}

}  // namespace
}  // namespace icp
