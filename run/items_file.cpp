#include "run/items_file.hpp"

#include <cstdio>

#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"
#include "core/utf8.hpp"

namespace littermap::run {

ItemsWritten WriteItemsCsv(const std::filesystem::path& file,
                           const std::vector<detect::LitterItem>& items,
                           const detect::LitterClassifier& classifier) {
  OutputFile output(file);
  std::ostream& out = output.stream();
  out << "id,class,x,y,z,size_m,confidence,views,missed_views,litter,litter_probability,"
         "first_seen_ns,last_seen_ns\n";
  const std::size_t clutter = classifier.ClassIndex("clutter");
  ItemsWritten written;
  for (const detect::LitterItem& item : items) {
    if (item.best_class == clutter) continue;
    const bool litter = classifier.is_litter(item.best_class);
    (litter ? written.litter : written.natural) += 1;
    double litter_probability = 0;
    for (std::size_t k = 0; k < item.class_probabilities.size(); ++k) {
      if (classifier.is_litter(k)) litter_probability += item.class_probabilities[k];
    }
    char line[320];
    std::snprintf(line, sizeof line, "%d,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,%d,%.3f,%lld,%lld",
                  item.id, classifier.classes()[item.best_class].c_str(), item.position_world_m.x(),
                  item.position_world_m.y(), item.position_world_m.z(), item.size_m,
                  item.confidence, item.views, item.missed_views, litter ? 1 : 0,
                  litter_probability, static_cast<long long>(item.first_seen_ns),
                  static_cast<long long>(item.last_seen_ns));
    out << line << '\n';
  }
  output.Commit();
  return written;
}

std::vector<ItemRow> ReadItemsCsv(const std::filesystem::path& file,
                                  const std::vector<std::string>& required_columns) {
  std::vector<std::string> required = {"id", "class", "x", "y"};
  required.insert(required.end(), required_columns.begin(), required_columns.end());
  std::vector<ItemRow> items;
  ReadCsv(file, required, [&](const CsvRow& row) {
    ItemRow item;
    item.id = row.NonEmptyText("id");
    item.class_name = row.NonEmptyText("class");
    if (!IsUtf8(item.class_name)) row.Fail("class", "is not valid UTF-8");
    item.x_m = row.Number("x");
    item.y_m = row.Number("y");
    if (row.Has("z")) item.z_m = row.Number("z");
    if (row.Has("size_m")) item.size_m = row.Number("size_m");
    if (row.Has("confidence")) {
      item.confidence = row.Number("confidence");
      if (item.confidence < 0 || item.confidence > 1) {
        row.Fail("confidence", "is not in [0, 1]: '" + row.Text("confidence") + "'");
      }
    }
    if (row.Has("litter")) {
      const std::string& flag = row.Text("litter");
      if (flag != "0" && flag != "1") row.Fail("litter", "is not 0 or 1: '" + flag + "'");
      item.litter = flag == "1";
    }
    items.push_back(std::move(item));
  });
  return items;
}

}  // namespace littermap::run
