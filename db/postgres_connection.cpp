#include "db/postgres_connection.hpp"

#include <libpq-fe.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace littermap::db {
namespace {

constexpr Oid kByteaOid = 17;

ErrorKind KindOf(const char* sqlstate) {
  if (sqlstate == nullptr) return ErrorKind::kEnvironment;  // no result: the connection broke
  const std::string_view state(sqlstate);
  const std::string_view cls = state.substr(0, 2);
  // 08 connection, 53 resources, 57 operator intervention, 58 system, 28 login, 40 transaction
  // conflicts (serialization failure, deadlock), 55 lock not available, 25 read-only transaction.
  for (const char* environment : {"08", "53", "57", "58", "28", "40", "55", "25"}) {
    if (cls == environment) return ErrorKind::kEnvironment;
  }
  if (cls == "22" || cls == "23") return ErrorKind::kBadInput;  // data, integrity constraints
  return ErrorKind::kInternal;
}

std::string Trimmed(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return message;
}

// Throws unless the result has one of the wanted statuses; frees it when throwing.
void Check(PGresult* result, pg_conn* connection, const std::string& name, std::string_view sql) {
  const ExecStatusType status = result ? PQresultStatus(result) : PGRES_FATAL_ERROR;
  if (status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK) return;
  const char* sqlstate = result ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  const std::string state = sqlstate ? sqlstate : "";
  std::string message = Trimmed(result ? PQresultErrorMessage(result) : PQerrorMessage(connection));
  if (message.empty()) message = Trimmed(PQerrorMessage(connection));
  const ErrorKind kind = KindOf(sqlstate);
  PQclear(result);
  std::string statement(sql.substr(0, 80));
  if (sql.size() > 80) statement += "...";
  throw PostgresError(
      kind, name + ": " + message + (kind == ErrorKind::kInternal ? " [" + statement + "]" : ""),
      state);
}

std::string RealText(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

class PostgresStatement : public SqlStatement {
 public:
  PostgresStatement(pg_conn* connection, const std::string& name, std::string sql)
      : connection_(connection), name_(name), sql_(std::move(sql)) {}
  ~PostgresStatement() override { PQclear(result_); }
  PostgresStatement(const PostgresStatement&) = delete;
  PostgresStatement& operator=(const PostgresStatement&) = delete;

  void Bind(int index, std::int64_t value) override { Set(index, std::to_string(value), 0); }
  void BindReal(int index, double value) override { Set(index, RealText(value), 0); }
  void BindNull(int index) override { Slot(index).value.reset(); }
  void Bind(int index, std::string_view text) override { Set(index, std::string(text), 0); }
  void BindBlob(int index, std::span<const std::uint8_t> blob) override {
    Set(index, std::string(blob.begin(), blob.end()), 1);
  }

  bool Step() override {
    if (!result_) Execute();
    ++row_;
    return row_ < PQntuples(result_);
  }
  void Run() override {
    Execute();
    Reset();
  }
  void Reset() override {
    PQclear(result_);
    result_ = nullptr;
    row_ = -1;
  }

  std::int64_t ColumnInt64(int column) const override {
    const char* text = Value(column);
    std::int64_t value = 0;
    std::from_chars(text, text + std::char_traits<char>::length(text), value);
    return value;
  }
  double ColumnDouble(int column) const override {
    if (ColumnIsNull(column)) return 0.0;
    // from_chars, not strtod: the text is PostgreSQL's ("0.5", "Infinity", "NaN") whatever the
    // process's locale says a decimal point is.
    const char* text = Value(column);
    double value = 0.0;
    std::from_chars(text, text + std::char_traits<char>::length(text), value);
    return value;
  }
  bool ColumnIsNull(int column) const override { return PQgetisnull(result_, row_, column) != 0; }
  std::string ColumnText(int column) const override { return Value(column); }
  std::span<const std::uint8_t> ColumnBlob(int column) const override {
    if (PQftype(result_, column) != kByteaOid || ColumnIsNull(column)) {
      const char* text = Value(column);
      return {reinterpret_cast<const std::uint8_t*>(text), std::char_traits<char>::length(text)};
    }
    std::size_t length = 0;
    unsigned char* bytes =
        PQunescapeBytea(reinterpret_cast<const unsigned char*>(Value(column)), &length);
    if (bytes == nullptr) throw EnvironmentError(name_ + ": out of memory reading a bytea value");
    blob_.assign(bytes, bytes + length);
    PQfreemem(bytes);
    return blob_;
  }

 private:
  struct Parameter {
    std::optional<std::string> value;
    int format = 0;
  };

  Parameter& Slot(int index) {
    if (index < 1 || index > 1000) {
      throw InternalError(name_ + ": parameter " + std::to_string(index) + " out of range");
    }
    if (parameters_.size() < static_cast<std::size_t>(index)) parameters_.resize(index);
    return parameters_[index - 1];
  }
  void Set(int index, std::string value, int format) {
    Parameter& slot = Slot(index);
    slot.value = std::move(value);
    slot.format = format;
  }
  const char* Value(int column) const {
    if (!result_ || row_ < 0 || row_ >= PQntuples(result_) || column >= PQnfields(result_)) {
      throw InternalError(name_ + ": column " + std::to_string(column) + " read outside a row");
    }
    return PQgetvalue(result_, row_, column);
  }
  void Execute() {
    PQclear(result_);
    result_ = nullptr;
    std::vector<const char*> values;
    std::vector<int> lengths, formats;
    for (const Parameter& p : parameters_) {
      values.push_back(p.value ? p.value->data() : nullptr);
      lengths.push_back(p.value ? static_cast<int>(p.value->size()) : 0);
      formats.push_back(p.format);
    }
    PGresult* result = PQexecParams(connection_, sql_.c_str(), static_cast<int>(values.size()),
                                    nullptr, values.data(), lengths.data(), formats.data(), 0);
    Check(result, connection_, name_, sql_);
    result_ = result;
    row_ = -1;
  }

  pg_conn* connection_;
  const std::string& name_;
  std::string sql_;
  std::vector<Parameter> parameters_;
  PGresult* result_ = nullptr;
  int row_ = -1;
  mutable std::vector<std::uint8_t> blob_;
};

void IgnoreNotice(void*, const char*) {}

}  // namespace

std::string ToPostgresParameters(std::string_view sql) {
  std::string out;
  out.reserve(sql.size() + 16);
  int next = 0;
  char quote = 0;
  for (std::size_t i = 0; i < sql.size(); ++i) {
    const char c = sql[i];
    if (quote) {
      if (c == quote) quote = 0;
      out += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      out += c;
    } else if (c == '?') {
      std::size_t j = i + 1;
      while (j < sql.size() && sql[j] >= '0' && sql[j] <= '9') ++j;
      out += '$';
      if (j > i + 1) {
        out.append(sql.substr(i + 1, j - i - 1));
        i = j - 1;
      } else {
        out += std::to_string(++next);
      }
    } else {
      out += c;
    }
  }
  return out;
}

PostgresConnection::PostgresConnection(const std::string& conninfo, std::string schema,
                                       std::string name)
    : schema_(std::move(schema)), name_(std::move(name)) {
  connection_ = PQconnectdb(conninfo.c_str());
  if (connection_ == nullptr) throw EnvironmentError(name_ + ": out of memory connecting");
  if (PQstatus(connection_) != CONNECTION_OK) {
    const std::string message = Trimmed(PQerrorMessage(connection_));
    PQfinish(connection_);
    connection_ = nullptr;
    throw PostgresError(ErrorKind::kEnvironment, name_ + ": cannot connect: " + message, "08000");
  }
  // A library does not print: the server's notices ("schema already exists, skipping") go.
  PQsetNoticeProcessor(connection_, IgnoreNotice, nullptr);
  try {
    Execute("SET search_path TO " + QuotedSchema() + ", public; SET client_min_messages = warning");
  } catch (...) {
    PQfinish(connection_);
    throw;
  }
}

PostgresConnection::~PostgresConnection() { PQfinish(connection_); }

std::string PostgresConnection::QuotedSchema() const {
  std::string quoted = "\"";
  for (char c : schema_) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void PostgresConnection::Execute(std::string_view sql) {
  const std::string text(sql);
  PGresult* result = PQexec(connection_, text.c_str());
  Check(result, connection_, name_, sql);  // frees the result when it throws
  PQclear(result);
}

std::unique_ptr<SqlStatement> PostgresConnection::Prepare(std::string_view sql) {
  return std::make_unique<PostgresStatement>(connection_, name_, ToPostgresParameters(sql));
}

void PostgresConnection::BeginWrite() {
  if (write_serialisation_ == PostgresWriteSerialisation::kSerializableTransactions) {
    Execute("BEGIN ISOLATION LEVEL SERIALIZABLE");
    return;
  }
  Execute("BEGIN");
  const std::unique_ptr<SqlStatement> lock =
      Prepare("SELECT pg_advisory_xact_lock(hashtext('littermap site ' || ?))");
  lock->Bind(1, schema_);
  lock->Step();
}

bool PostgresConnection::IsConflict(const std::exception& error) const {
  const auto* postgres = dynamic_cast<const PostgresError*>(&error);
  return postgres && (postgres->sqlstate() == "40001" || postgres->sqlstate() == "40P01");
}

bool PostgresConnection::HasTable(std::string_view table) {
  const std::unique_ptr<SqlStatement> query =
      Prepare("SELECT 1 FROM information_schema.tables WHERE table_schema = ? AND table_name = ?");
  query->Bind(1, schema_);
  query->Bind(2, table);
  return query->Step();
}

bool PostgresConnection::HasColumn(std::string_view table, std::string_view column) {
  const std::unique_ptr<SqlStatement> query = Prepare(
      "SELECT 1 FROM information_schema.columns WHERE table_schema = ? AND table_name = ? "
      "AND column_name = ?");
  query->Bind(1, schema_);
  query->Bind(2, table);
  query->Bind(3, column);
  return query->Step();
}

}  // namespace littermap::db
