#include "heatmap/hotspots.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace littermap::heatmap {
namespace {

bool IsLocalMaximum(const Raster& density, int column, int row, int radius, float nodata) {
  const float value = density.at(column, row);
  const GridGeometry& grid = density.grid;
  for (int r = std::max(0, row - radius); r <= std::min(grid.height - 1, row + radius); ++r) {
    for (int c = std::max(0, column - radius); c <= std::min(grid.width - 1, column + radius);
         ++c) {
      const float other = density.at(c, r);
      if (other == nodata) continue;
      // Ties go to the first cell in row-major order, so a plateau yields one peak.
      if (other > value || (other == value && (r < row || (r == row && c < column)))) return false;
    }
  }
  return true;
}

void Classify(Hotspot& hotspot, std::span<const ClassifiedPoint> items, double radius_m) {
  std::map<std::string, int> counts;
  for (const ClassifiedPoint& item : items) {
    if (std::hypot(item.crs.x - hotspot.crs.x, item.crs.y - hotspot.crs.y) <= radius_m) {
      ++counts[item.class_name];
      ++hotspot.items_nearby;
    }
  }
  int best = 0;
  for (const auto& [name, count] : counts) {
    if (count > best) {
      best = count;
      hotspot.dominant_class = name;
    }
  }
}

}  // namespace

std::vector<Hotspot> FindHotspots(const Raster& density, float nodata,
                                  std::span<const ClassifiedPoint> items,
                                  const HotspotOptions& options) {
  const GridGeometry& grid = density.grid;
  const int radius =
      std::max(1, static_cast<int>(std::ceil(options.separation_m / grid.cell_size_m)));
  std::vector<Hotspot> hotspots;
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      const float value = density.at(c, r);
      if (value == nodata || value <= 0.0f || value < options.min_density_per_100m2) continue;
      if (!IsLocalMaximum(density, c, r, radius, nodata)) continue;
      Hotspot hotspot;
      hotspot.crs = {grid.CellCenterX(c), grid.CellCenterY(r)};
      hotspot.density_per_100m2 = value;
      hotspots.push_back(hotspot);
    }
  }
  std::sort(hotspots.begin(), hotspots.end(), [](const Hotspot& a, const Hotspot& b) {
    return a.density_per_100m2 > b.density_per_100m2;
  });
  if (static_cast<int>(hotspots.size()) > options.max_count) hotspots.resize(options.max_count);
  for (std::size_t i = 0; i < hotspots.size(); ++i) {
    hotspots[i].rank = static_cast<int>(i) + 1;
    Classify(hotspots[i], items, options.separation_m);
  }
  return hotspots;
}

}  // namespace littermap::heatmap
