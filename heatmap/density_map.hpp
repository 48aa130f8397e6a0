#pragma once
// Effort-normalised litter density: the kernel density of the items divided by the survey
// effort smoothed with the same kernel, in items per 100 m^2 per survey. Smoothing both is a
// kernel ratio estimate: an item near the border between ground surveyed once and ground
// surveyed twice is divided by the effort around it, not by the effort of the cell it spills
// into, so borders of coverage are not biased; where effort is uniform the smoothed effort is
// the effort. Cells surveyed less than min_effort_surveys are nodata: unsurveyed ground is
// unknown, not clean.

#include <cstddef>
#include <span>

#include "db/geometry_blob.hpp"
#include "heatmap/kernel_density.hpp"
#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct DensityMapOptions {
  KernelDensityOptions kernel;
  double min_effort_surveys = 1.0;
  float nodata = -9999.0f;
};

struct DensityMapResult {
  Raster density;  // items per 100 m^2 per survey, or nodata
  std::size_t items_used = 0;
  std::size_t items_outside = 0;
  std::size_t surveyed_cells = 0;
  double surveyed_area_m2 = 0.0;
  float max_density = 0.0f;
};

// `effort` (surveys per cell) fixes the grid. Throws UsageError for bad options.
DensityMapResult EffortNormalisedDensity(const Raster& effort, std::span<const db::PointXY> items,
                                         const DensityMapOptions& options);

}  // namespace littermap::heatmap
