#pragma once
// RUN_DIR/items.csv, the fused items of a run, one row each:
//   id,class,x,y,z,size_m,confidence,views,litter,litter_probability,first_seen_ns,last_seen_ns
// metres in the run's map frame; `class` the classifier's final decision over the item's mean
// class probabilities, `confidence` its probability, `litter` 1 for litter classes and 0 for
// natural objects. Items decided as clutter are left out.

#include <cstddef>
#include <filesystem>
#include <vector>

#include "detect/item_fusion.hpp"
#include "detect/litter_classifier.hpp"

namespace littermap::run {

struct ItemsWritten {
  std::size_t litter = 0;
  std::size_t natural = 0;
};

// Throws UsageError if the file cannot be created, InternalError if writing fails.
ItemsWritten WriteItemsCsv(const std::filesystem::path& file,
                           const std::vector<detect::LitterItem>& items,
                           const detect::LitterClassifier& classifier);

}  // namespace littermap::run
