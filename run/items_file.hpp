#pragma once
// RUN_DIR/items.csv, the fused items of a run, one row each:
//   id,class,x,y,z,size_m,confidence,views,missed_views,litter,litter_probability,first_seen_ns,
//   last_seen_ns
// metres in the run's map frame; `class` the classifier's final decision over the item's mean
// class probabilities, `confidence` its probability, `missed_views` the frames after its first
// sighting that could have seen it and did not, `litter` 1 for litter classes and 0 for
// natural objects. Items decided as clutter are left out. The simulator's truth litter.csv
// (id,class,x,y,z,size_m) reads the same way.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "detect/item_fusion.hpp"
#include "detect/litter_classifier.hpp"

namespace littermap::run {

struct ItemsWritten {
  std::size_t litter = 0;
  std::size_t natural = 0;
};

// Writes the items as decided (best_class; clutter is left out). Throws UsageError if the file
// cannot be created, InternalError if writing fails.
ItemsWritten WriteItemsCsv(const std::filesystem::path& file,
                           const std::vector<detect::LitterItem>& items,
                           const detect::LitterClassifier& classifier);

struct ItemRow {
  std::string id;
  std::string class_name;
  double x_m = 0;  // the run's map frame
  double y_m = 0;
  double z_m = 0;              // 0 when the file has no z column
  double size_m = 0;           // 0 when the file has no size_m column
  double confidence = 1.0;     // 1 when the file has no confidence column
  std::optional<bool> litter;  // the litter column, when the file has one
};

// Columns by header name, in any order (core/csv_table.hpp): id, class, x, y and
// `required_columns` required; z, size_m, confidence (0..1) and litter (0/1) optional. Throws
// BadInputError naming FILE:LINE and the column (LINE 1: the header).
std::vector<ItemRow> ReadItemsCsv(const std::filesystem::path& file,
                                  const std::vector<std::string>& required_columns = {});

}  // namespace littermap::run
