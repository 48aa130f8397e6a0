#pragma once
// Reading an occupancy map back from its ROS map_server files (MAP.yaml + the PGM it names), as
// OccupancyGrid::WritePgmYaml writes them: grey levels 0 occupied .. 254 free, 205 unknown, the
// top image row at the largest y, `origin` the lower-left corner of the lower-left cell.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/occupancy_image.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

// Throws BadInputError naming the file and the field when a file is missing or malformed.
OccupancyImage ReadOccupancyMap(const std::filesystem::path& yaml_path);

// Centres of the occupied cells, in the map frame.
Points2 OccupiedCellCentres(const OccupancyImage& map);

}  // namespace littermap::reconstruct
