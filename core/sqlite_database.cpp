#include "core/sqlite_database.hpp"

#include <sqlite3.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <limits>
#include <string>

#include "core/failure.hpp"

namespace littermap {

ErrorKind SqliteErrorKind(int code) {
  switch (code & 0xff) {  // the primary result code of an extended one
    case SQLITE_FULL:
    case SQLITE_IOERR:
    case SQLITE_READONLY:
    case SQLITE_PERM:
    case SQLITE_CANTOPEN:
    case SQLITE_NOMEM:
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
    case SQLITE_NOLFS:
      return ErrorKind::kEnvironment;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      return ErrorKind::kBadInput;
    default:
      return ErrorKind::kInternal;
  }
}

namespace {

constexpr int kBusyTimeoutMs = 5000;

// SQLite's message, and the operating system's when one caused it ("disk I/O error (File too
// large)").
std::string SqliteMessage(sqlite3* db, const std::string& message) {
  const int system_errno = db ? sqlite3_system_errno(db) : 0;
  return system_errno != 0 ? message + " (" + std::strerror(system_errno) + ")" : message;
}

}  // namespace

SqliteStatement::SqliteStatement(sqlite3* db, std::string_view sql,
                                 const std::filesystem::path& file)
    : db_(db), file_(file) {
  const int code =
      sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &statement_, nullptr);
  if (code != SQLITE_OK) Fail(code, "preparing a query");
}

SqliteStatement::SqliteStatement(SqliteStatement&& other) noexcept
    : db_(other.db_), statement_(other.statement_), file_(std::move(other.file_)) {
  other.statement_ = nullptr;
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(statement_); }

void SqliteStatement::Bind(int index, std::int64_t value) {
  const int code = sqlite3_bind_int64(statement_, index, value);
  if (code != SQLITE_OK) Fail(code, "binding an integer");
}

void SqliteStatement::BindReal(int index, double value) {
  const int code = sqlite3_bind_double(statement_, index, value);
  if (code != SQLITE_OK) Fail(code, "binding a real");
}

void SqliteStatement::BindNull(int index) {
  const int code = sqlite3_bind_null(statement_, index);
  if (code != SQLITE_OK) Fail(code, "binding null");
}

void SqliteStatement::Bind(int index, std::string_view text) {
  const int code = sqlite3_bind_text64(statement_, index, text.data(), text.size(),
                                       SQLITE_TRANSIENT, SQLITE_UTF8);
  if (code != SQLITE_OK) Fail(code, "binding text");
}

void SqliteStatement::BindBlob(int index, std::span<const std::uint8_t> blob) {
  // SQLITE_STATIC: the caller keeps the bytes alive until Step(), which saves a copy per message.
  // A null pointer would bind SQL NULL; an empty message is a zero-length blob.
  static const std::uint8_t kEmpty = 0;
  const void* data = blob.empty() ? &kEmpty : blob.data();
  const int code = sqlite3_bind_blob64(statement_, index, data, blob.size(), SQLITE_STATIC);
  if (code != SQLITE_OK) Fail(code, "binding a blob");
}

bool SqliteStatement::Step() {
  const int code = sqlite3_step(statement_);
  if (code == SQLITE_ROW) return true;
  if (code == SQLITE_DONE) return false;
  Fail(code, "running a query");
}

void SqliteStatement::Run() {
  Step();
  Reset();
}

void SqliteStatement::Reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

std::int64_t SqliteStatement::ColumnInt64(int column) const {
  return sqlite3_column_int64(statement_, column);
}

double SqliteStatement::ColumnDouble(int column) const {
  return sqlite3_column_double(statement_, column);
}

bool SqliteStatement::ColumnIsNull(int column) const {
  return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

std::string SqliteStatement::ColumnText(int column) const {
  const auto* text = sqlite3_column_text(statement_, column);
  if (text == nullptr) return {};
  const auto size = static_cast<std::size_t>(sqlite3_column_bytes(statement_, column));
  return std::string(reinterpret_cast<const char*>(text), size);
}

std::span<const std::uint8_t> SqliteStatement::ColumnBlob(int column) const {
  const void* blob = sqlite3_column_blob(statement_, column);
  const auto size = static_cast<std::size_t>(sqlite3_column_bytes(statement_, column));
  if (blob == nullptr) return {};
  return {static_cast<const std::uint8_t*>(blob), size};
}

void SqliteStatement::Fail(int code, const char* action) const {
  throw SqliteError(
      file_.string() + ": SQLite error " + action + ": " + SqliteMessage(db_, sqlite3_errmsg(db_)),
      code);
}

namespace {

// A file: URI for the path, every byte outside RFC 3986's unreserved set and '/' escaped.
std::string FileUri(const std::filesystem::path& file) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string uri = "file:";
  for (const char c : std::filesystem::absolute(file).string()) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || std::strchr("-._~/", c) != nullptr) {
      uri += c;
    } else {
      uri += '%';
      uri += kHex[byte >> 4];
      uri += kHex[byte & 15];
    }
  }
  return uri;
}

std::filesystem::path FolderOf(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

// A database that can only be read as immutable: its folder cannot take a -shm file, and no
// -wal file holds changes that reading without it would miss.
bool ReadableOnlyAsImmutable(const std::filesystem::path& file) {
  const std::filesystem::path folder = FolderOf(file);
  std::error_code error;
  const std::filesystem::path wal = file.string() + "-wal";
  const bool pending_wal =
      std::filesystem::exists(wal, error) && std::filesystem::file_size(wal, error) > 0;
  return access(folder.c_str(), W_OK) != 0 && !pending_wal;
}

}  // namespace

SqliteDatabase::SqliteDatabase(const std::filesystem::path& file, Mode mode) : file_(file) {
  int flags = SQLITE_OPEN_NOMUTEX;
  std::string name = file.string();
  switch (mode) {
    case Mode::kReadOnly:
      flags |= SQLITE_OPEN_READONLY;
      if (ReadableOnlyAsImmutable(file)) {
        flags |= SQLITE_OPEN_URI;
        name = FileUri(file) + "?immutable=1";
      }
      break;
    case Mode::kReadWrite:
      flags |= SQLITE_OPEN_READWRITE;
      break;
    case Mode::kCreate:
      flags |= SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
      break;
  }
  const int code = sqlite3_open_v2(name.c_str(), &db_, flags, nullptr);
  if (code != SQLITE_OK) {
    std::string message = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(code);
    // Why the file could not be opened (no such folder: the path; no permission: the machine).
    int system_errno = db_ ? sqlite3_system_errno(db_) : 0;
    // Refused a new file, SQLite retries read-only and reports that attempt's ENOENT: the
    // folder's own answer (a read-only file system, no permission) is the cause.
    std::error_code ignored;
    if (mode == Mode::kCreate && !std::filesystem::exists(file, ignored) &&
        access(FolderOf(file).c_str(), W_OK) != 0) {
      system_errno = errno;
    }
    sqlite3_close(db_);
    db_ = nullptr;
    if (system_errno != 0) message += std::string(" (") + std::strerror(system_errno) + ")";
    throw SqliteError(file.string() + ": cannot open database: " + message, code,
                      system_errno != 0 ? KindOfErrno(system_errno) : SqliteErrorKind(code));
  }
  sqlite3_extended_result_codes(db_, 0);
  sqlite3_busy_timeout(db_, kBusyTimeoutMs);
}

SqliteDatabase::~SqliteDatabase() { sqlite3_close(db_); }

SqliteDatabase::SqliteDatabase(SqliteDatabase&& other) noexcept
    : db_(other.db_), file_(std::move(other.file_)) {
  other.db_ = nullptr;
}

void SqliteDatabase::Execute(std::string_view sql) {
  char* error = nullptr;
  const std::string statement(sql);
  const int code = sqlite3_exec(db_, statement.c_str(), nullptr, nullptr, &error);
  if (code != SQLITE_OK) {
    const std::string message = error ? error : sqlite3_errstr(code);
    sqlite3_free(error);
    throw SqliteError(file_.string() + ": SQLite error: " + SqliteMessage(db_, message), code);
  }
}

SqliteStatement SqliteDatabase::Prepare(std::string_view sql) const {
  return SqliteStatement(db_, sql, file_);
}

std::int64_t SqliteDatabase::LastInsertId() const { return sqlite3_last_insert_rowid(db_); }

int SqliteDatabase::Changes() const { return sqlite3_changes(db_); }

bool SqliteDatabase::HasTable(std::string_view table) const {
  SqliteStatement query(db_, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?",
                        file_);
  query.Bind(1, table);
  return query.Step();
}

bool SqliteDatabase::HasColumn(std::string_view table, std::string_view column) const {
  SqliteStatement query(db_, "SELECT 1 FROM pragma_table_info(?) WHERE name = ?", file_);
  query.Bind(1, table);
  query.Bind(2, column);
  return query.Step();
}

}  // namespace littermap
