#include "site/run_items.hpp"

#include "core/csv_table.hpp"

namespace littermap::site {

std::vector<RunItem> ReadRunItems(const std::filesystem::path& file) {
  std::vector<RunItem> items;
  ReadCsv(file, {"id", "class", "x", "y", "z", "size_m"}, [&](const CsvRow& row) {
    if (row.Has("litter") && row.Number("litter") == 0) return;  // detect's natural objects
    RunItem item;
    item.id = row.Text("id");
    item.class_name = row.Text("class");
    item.xy = {row.Number("x"), row.Number("y")};
    item.z_m = row.Number("z");
    item.size_m = row.Number("size_m");
    if (row.Has("confidence")) item.confidence = row.Number("confidence");
    items.push_back(std::move(item));
  });
  return items;
}

}  // namespace littermap::site
