#pragma once
// The litter items of one run: RUN_DIR/items.csv from the detect stage
// (id,class,x,y,z,size_m,confidence,litter,...; metres in the run's map frame; rows with
// litter = 0 are natural objects and are skipped), or the simulator's truth litter.csv
// (id,class,x,y,z,size_m), which stands in for it with confidence 1.

#include <filesystem>
#include <string>
#include <vector>

#include "db/geometry_blob.hpp"

namespace littermap::site {

struct RunItem {
  std::string id;
  std::string class_name;
  db::PointXY xy;
  double z_m = 0.0;
  double size_m = 0.0;
  double confidence = 1.0;
};

// Columns are found by their header names (order free); confidence and litter are optional. Throws
// BadInputError "FILE:LINE: ..." naming the column for a missing column or a bad number.
std::vector<RunItem> ReadRunItems(const std::filesystem::path& file);

}  // namespace littermap::site
