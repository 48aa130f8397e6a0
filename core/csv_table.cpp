#include "core/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace littermap {

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) {
    while (!field.empty() && (field.back() == '\r' || field.back() == ' ')) field.pop_back();
    while (!field.empty() && field.front() == ' ') field.erase(0, 1);
    fields.push_back(field);
  }
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

const std::string& CsvRow::Text(const std::string& name) const {
  const auto column = columns_.find(name);
  if (column == columns_.end() || column->second >= fields_.size()) {
    throw BadInputError(where_ + ": column '" + name + "' is missing");
  }
  return fields_[column->second];
}

const std::string& CsvRow::NonEmptyText(const std::string& name) const {
  const std::string& text = Text(name);
  if (text.empty()) Fail(name, "is empty");
  return text;
}

void CsvRow::Fail(const std::string& name, const std::string& what) const {
  throw BadInputError(where_ + ": column '" + name + "' " + what);
}

double CsvRow::Number(const std::string& name) const {
  const std::string& text = Text(name);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    throw BadInputError(where_ + ": column '" + name + "' is not a number: '" + text + "'");
  }
  return value;
}

void ReadCsv(const std::filesystem::path& file, const std::vector<std::string>& required_columns,
             const std::function<void(const CsvRow&)>& visit) {
  std::ifstream in(file);
  if (!in) throw BadInputError(file.string() + ": cannot open");
  std::string line;
  if (!std::getline(in, line)) throw BadInputError(file.string() + ":1: the header is missing");
  std::map<std::string, std::size_t> columns;
  const auto header = SplitCsv(line);
  for (std::size_t i = 0; i < header.size(); ++i) columns[header[i]] = i;
  for (const std::string& required : required_columns) {
    if (!columns.count(required)) {
      throw BadInputError(file.string() + ":1: the header has no column '" + required + "'");
    }
  }
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty() || line == "\r" || line[0] == '#') continue;
    const auto fields = SplitCsv(line);
    visit(CsvRow(fields, columns, file.string() + ":" + std::to_string(number)));
  }
}

}  // namespace littermap
