#include "db/sqlite_connection.hpp"

namespace littermap::db {
namespace {

class SqliteSqlStatement : public SqlStatement {
 public:
  explicit SqliteSqlStatement(SqliteStatement statement) : statement_(std::move(statement)) {}

  void Bind(int index, std::int64_t value) override { statement_.Bind(index, value); }
  void BindReal(int index, double value) override { statement_.BindReal(index, value); }
  void BindNull(int index) override { statement_.BindNull(index); }
  void Bind(int index, std::string_view text) override { statement_.Bind(index, text); }
  void BindBlob(int index, std::span<const std::uint8_t> blob) override {
    statement_.BindBlob(index, blob);
  }
  bool Step() override { return statement_.Step(); }
  void Run() override { statement_.Run(); }
  void Reset() override { statement_.Reset(); }
  std::int64_t ColumnInt64(int column) const override { return statement_.ColumnInt64(column); }
  double ColumnDouble(int column) const override { return statement_.ColumnDouble(column); }
  bool ColumnIsNull(int column) const override { return statement_.ColumnIsNull(column); }
  std::string ColumnText(int column) const override { return statement_.ColumnText(column); }
  std::span<const std::uint8_t> ColumnBlob(int column) const override {
    return statement_.ColumnBlob(column);
  }

 private:
  SqliteStatement statement_;
};

}  // namespace

SqliteConnection::SqliteConnection(const std::filesystem::path& file, SqliteDatabase::Mode mode)
    : database_(file, mode), name_(file.string()) {}

std::unique_ptr<SqlStatement> SqliteConnection::Prepare(std::string_view sql) {
  return std::make_unique<SqliteSqlStatement>(database_.Prepare(sql));
}

}  // namespace littermap::db
