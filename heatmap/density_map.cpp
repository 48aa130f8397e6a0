#include "heatmap/density_map.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace littermap::heatmap {

DensityMapResult EffortNormalisedDensity(const Raster& effort, std::span<const db::PointXY> items,
                                         const DensityMapOptions& options) {
  if (!(options.min_effort_surveys > 0.0)) {
    throw UsageError("density map: min_effort_surveys must be > 0 (dividing by no effort)");
  }
  KernelDensityResult kde = KernelDensity(effort.grid, items, options.kernel);
  const Raster smoothed_effort = KernelSmooth(effort, options.kernel);
  DensityMapResult result;
  result.items_used = kde.items_used;
  result.items_outside = kde.items_outside;
  result.density = std::move(kde.density);
  constexpr double kPer100SquareMetres = 100.0;
  for (std::size_t i = 0; i < result.density.values.size(); ++i) {
    const double surveys = effort.values[i];
    float& value = result.density.values[i];
    if (surveys < options.min_effort_surveys) {
      value = options.nodata;
      continue;
    }
    value = static_cast<float>(value * kPer100SquareMetres / smoothed_effort.values[i]);
    result.max_density = std::max(result.max_density, value);
    ++result.surveyed_cells;
  }
  result.surveyed_area_m2 = static_cast<double>(result.surveyed_cells) * effort.grid.cell_area_m2();
  return result;
}

}  // namespace littermap::heatmap
