#pragma once
// CSV files with a header line whose columns are found by name (order free, extra columns
// ignored), as littermap's item, label and truth files are. Blank lines and lines starting with
// '#' are skipped. Errors name FILE:LINE and the column.

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace littermap {

// Splits on commas and trims spaces and a trailing CR; no quoting (littermap never writes any).
std::vector<std::string> SplitCsv(const std::string& line);

class CsvRow {
 public:
  CsvRow(const std::vector<std::string>& fields, const std::map<std::string, std::size_t>& columns,
         std::string where)
      : fields_(fields), columns_(columns), where_(std::move(where)) {}
  bool Has(const std::string& name) const { return columns_.count(name) > 0; }
  // Throws BadInputError "FILE:LINE: column 'name' ..." when absent or not a finite number.
  const std::string& Text(const std::string& name) const;
  double Number(const std::string& name) const;
  // Text that must not be empty ("... column 'name' is empty").
  const std::string& NonEmptyText(const std::string& name) const;
  // Throws BadInputError "FILE:LINE: column 'name' <what>".
  [[noreturn]] void Fail(const std::string& name, const std::string& what) const;
  const std::string& where() const { return where_; }

 private:
  const std::vector<std::string>& fields_;
  const std::map<std::string, std::size_t>& columns_;
  std::string where_;
};

// Calls visit for every data row. Throws BadInputError when the file cannot be opened, the
// header is missing or lacks a required column; visit's own errors pass through.
void ReadCsv(const std::filesystem::path& file, const std::vector<std::string>& required_columns,
             const std::function<void(const CsvRow&)>& visit);

}  // namespace littermap
