#pragma once
// An occupancy map as the ROS map_server stores it: grey levels 0 occupied .. 254 free, 205
// unknown, row-major with the top row (largest y) first, `origin` the lower-left corner of the
// lower-left cell. A run's map.pgm/map.yaml read back, and the site map a site database keeps.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace littermap {

struct OccupancyImage {
  double resolution_m = 0;
  double origin_x_m = 0;  // lower-left corner of the lower-left cell, map frame
  double origin_y_m = 0;
  int width = 0;
  int height = 0;
  double occupied_threshold = 0.65;  // occupancy probability (255 - grey) / 255 above: occupied
  std::vector<std::uint8_t> pixels;  // row-major, top row first

  // The grey level of the cell under (x, y) of the map frame; none outside the map.
  std::optional<std::uint8_t> GreyAt(double x_m, double y_m) const {
    const double column = std::floor((x_m - origin_x_m) / resolution_m);
    const double from_bottom = std::floor((y_m - origin_y_m) / resolution_m);
    if (!(column >= 0 && from_bottom >= 0 && column < width && from_bottom < height)) {
      return std::nullopt;
    }
    const auto row = static_cast<std::size_t>(height - 1 - static_cast<int>(from_bottom));
    return pixels[row * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)];
  }
};

}  // namespace littermap
