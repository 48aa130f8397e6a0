#pragma once
// Reading an occupancy map back from its ROS map_server files (MAP.yaml + the PGM it names), as
// OccupancyGrid::WritePgmYaml writes them: grey levels 0 occupied .. 254 free, 205 unknown, the
// top image row at the largest y, `origin` the lower-left corner of the lower-left cell.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct OccupancyMapImage {
  double resolution_m = 0;
  double origin_x_m = 0;  // lower-left corner of the lower-left cell, map frame
  double origin_y_m = 0;
  int width = 0;
  int height = 0;
  double occupied_threshold = 0.65;  // occupancy probability (255 - grey) / 255 above: occupied
  std::vector<std::uint8_t> pixels;  // row-major, top row first
};

// Throws BadInputError naming the file and the field when a file is missing or malformed.
OccupancyMapImage ReadOccupancyMap(const std::filesystem::path& yaml_path);

// Centres of the occupied cells, in the map frame.
Points2 OccupiedCellCentres(const OccupancyMapImage& map);

}  // namespace littermap::reconstruct
