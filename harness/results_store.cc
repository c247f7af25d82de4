// Opening and closing a results store: for writing (WAL mode, schema created
// or migrated) or read-only (nothing written, no -wal/-shm files created).
// Writing, reading, the schema and merging are in results_store_*.cc.
#include "harness/results_store.h"

#include <sqlite3.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include "harness/environment_error.h"
#include "harness/results_store_internal.h"

namespace icp {

namespace {

using detail::CheckOrCreateSchema;
using detail::Exec;
using detail::Statement;

constexpr int kBusyTimeoutMs = 30000;
constexpr int kCloseCheckpointMs = 5000;  // a reader's query takes milliseconds

sqlite3* Open(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    std::string message = "cannot open: ";
    message += db != nullptr ? sqlite3_errmsg(db) : "out of memory";
    // The OS's reason: descriptors, permissions or memory are the environment.
    const int os_error = db != nullptr ? sqlite3_system_errno(db) : ENOMEM;
    sqlite3_close_v2(db);
    if (IsEnvironmentErrno(os_error))
      throw EnvironmentError("results store '" + path + "': " + message + ": " +
                             std::strerror(os_error) + " (" + EnvironmentAdvice(os_error) + ")");
    std::error_code ec;
    std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
      message += " (directory '" + parent.string() + "' does not exist)";
    } else if (std::filesystem::is_directory(path, ec)) {
      message += " (it is a directory)";
    }
    throw StoreError("results store '" + path + "': " + message);
  }
  sqlite3_extended_result_codes(db, 1);
  sqlite3_busy_timeout(db, kBusyTimeoutMs);
  return db;
}

}  // namespace

namespace detail {

// Opens an existing store file for reading only. Without a -wal file no
// writer has the store open, so it is opened immutable: SQLite then creates
// no -wal/-shm files (a plain read-only open of a WAL file does, and cannot
// on a read-only directory). With one, a sweep may be writing: a plain
// read-only open shares its WAL index.
sqlite3* OpenExistingReadOnly(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw StoreError("results store '" + path + "': no such file");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw StoreError("results store '" + path + "': not a regular file");
  }
  if (std::filesystem::file_size(path, ec) == 0) {
    throw StoreError("results store '" + path + "': empty file (0 bytes), not a results store");
  }
  if (std::filesystem::exists(path + "-wal", ec)) {
    // SQLite reads a write-ahead log through its index (-shm), which it must
    // create when a killed sweep left none: impossible in a read-only place.
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (!std::filesystem::exists(path + "-shm", ec) && access(dir.empty() ? "." : dir.c_str(), W_OK) != 0)
      throw EnvironmentError("results store '" + path + "': a sweep that did not finish left its write-ahead log (" +
                             path + "-wal) without the index SQLite needs to read it, and this directory is "
                             "read-only: copy the directory somewhere writable and read it there");
    return Open(path, SQLITE_OPEN_READONLY);
  }
  std::string uri = "file:";
  for (char c : std::filesystem::absolute(path, ec).string()) {
    // Percent-encode what a URI path cannot hold literally.
    if (c == '%' || c == '?' || c == '#') {
      static const char kHex[] = "0123456789ABCDEF";
      uri += '%';
      uri += kHex[(static_cast<unsigned char>(c) >> 4) & 15];
      uri += kHex[static_cast<unsigned char>(c) & 15];
    } else {
      uri += c;
    }
  }
  uri += "?immutable=1";
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(uri.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) !=
      SQLITE_OK) {
    std::string message = db != nullptr ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close_v2(db);
    throw StoreError("results store '" + path + "': cannot open read-only: " + message);
  }
  sqlite3_extended_result_codes(db, 1);
  sqlite3_busy_timeout(db, kBusyTimeoutMs);
  return db;
}

}  // namespace detail

ResultsStore::ResultsStore(const std::string& path) : path_(path) {
  db_ = Open(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  try {
    // SQLite opens a file it may not write read-only without a word, and an
    // empty transaction below writes nothing: asked now, before any run.
    if (sqlite3_db_readonly(db_, "main") == 1)
      throw EnvironmentError("results store '" + path_ +
                             "': the file cannot be written (check the permissions of the store)");
    Exec(db_, path_, "PRAGMA foreign_keys=ON");
    // The schema first: a database that is not a store is refused before
    // anything in it changes (switching to WAL rewrites its header).
    version_ = CheckOrCreateSchema(db_, path_, /*may_create=*/true);
    // Each run commits on its own; WAL lets reports read while a sweep writes.
    std::string mode;
    {
      Statement wal(db_, path_, "PRAGMA journal_mode=WAL");
      if (wal.Step()) mode = wal.ColumnText(0);
    }
    if (mode != "wal") {
      throw StoreError("results store '" + path_ + "': cannot use WAL journal mode (got '" + mode +
                       "')");
    }
    // The WAL's files open at the first write: a store that cannot be
    // written (no descriptor left, say) fails here, before any run starts.
    Exec(db_, path_, "BEGIN IMMEDIATE; COMMIT");
  } catch (...) {
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw;
  }
}

ResultsStore::ResultsStore(const std::string& path, ReadOnlyTag) : path_(path), read_only_(true) {
  db_ = detail::OpenExistingReadOnly(path);
  try {
    version_ = CheckOrCreateSchema(db_, path_, /*may_create=*/false);
  } catch (...) {
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw;
  }
}

std::unique_ptr<ResultsStore> ResultsStore::OpenReadOnly(const std::string& path) {
  return std::unique_ptr<ResultsStore>(new ResultsStore(path, ReadOnlyTag{}));
}

ResultsStore::~ResultsStore() {
  // SQLite folds the WAL into the store and removes it when the last
  // connection closes; a reader still open then (a page of `icpbench serve`)
  // left the runs in -wal, and results.sqlite copied alone was malformed.
  // So the writer folds it in first, waiting a little for readers between
  // their queries; the WAL left is empty.
  if (db_ != nullptr && !read_only_) {
    sqlite3_busy_timeout(db_, kCloseCheckpointMs);
    sqlite3_wal_checkpoint_v2(db_, nullptr, SQLITE_CHECKPOINT_TRUNCATE, nullptr, nullptr);
  }
  sqlite3_close_v2(db_);
}

std::string StorePath(const std::string& out_dir) { return out_dir + "/results.sqlite"; }

}  // namespace icp
