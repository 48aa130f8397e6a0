#include "site/run_items.hpp"

#include "run/items_file.hpp"

namespace littermap::site {

std::vector<RunItem> ReadRunItems(const std::filesystem::path& file) {
  std::vector<RunItem> items;
  for (run::ItemRow& row : run::ReadItemsCsv(file, {"z", "size_m"})) {
    if (row.litter == false) continue;  // detect's natural objects
    items.push_back({std::move(row.id),
                     std::move(row.class_name),
                     {row.x_m, row.y_m},
                     row.z_m,
                     row.size_m,
                     row.confidence});
  }
  return items;
}

}  // namespace littermap::site
