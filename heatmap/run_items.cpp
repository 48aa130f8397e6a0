#include "heatmap/run_items.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace littermap::heatmap {
namespace {

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

class Row {
 public:
  Row(const std::vector<std::string>& fields, const std::map<std::string, std::size_t>& columns,
      std::string where)
      : fields_(fields), columns_(columns), where_(std::move(where)) {}
  bool Has(const std::string& name) const { return columns_.count(name) > 0; }
  const std::string& Text(const std::string& name) const {
    const std::size_t index = columns_.at(name);
    if (index >= fields_.size()) throw BadInputError(where_ + ": column '" + name + "' is missing");
    return fields_[index];
  }
  double Number(const std::string& name) const {
    const std::string& text = Text(name);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
      throw BadInputError(where_ + ": column '" + name + "' is not a number: '" + text + "'");
    }
    return value;
  }

 private:
  const std::vector<std::string>& fields_;
  const std::map<std::string, std::size_t>& columns_;
  std::string where_;
};

}  // namespace

std::vector<RunItem> ReadRunItems(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw BadInputError(file.string() + ": cannot open the items file");
  std::string line;
  if (!std::getline(in, line)) throw BadInputError(file.string() + ":1: the header is missing");
  std::map<std::string, std::size_t> columns;
  const auto header = SplitCsv(line);
  for (std::size_t i = 0; i < header.size(); ++i) columns[header[i]] = i;
  for (const char* required : {"id", "class", "x", "y", "z", "size_m"}) {
    if (!columns.count(required)) {
      throw BadInputError(file.string() + ":1: the header has no column '" + required + "'");
    }
  }
  std::vector<RunItem> items;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty() || line == "\r" || line[0] == '#') continue;
    const auto fields = SplitCsv(line);
    const Row row(fields, columns, file.string() + ":" + std::to_string(number));
    RunItem item;
    item.id = row.Text("id");
    item.class_name = row.Text("class");
    item.xy = {row.Number("x"), row.Number("y")};
    item.z_m = row.Number("z");
    item.size_m = row.Number("size_m");
    if (row.Has("confidence")) item.confidence = row.Number("confidence");
    items.push_back(std::move(item));
  }
  return items;
}

}  // namespace littermap::heatmap
