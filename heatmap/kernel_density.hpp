#pragma once
// Kernel density of point items on a grid with the quartic (biweight) kernel
//   K(d) = 3 / (pi h^2) (1 - d^2/h^2)^2  for d < h, 0 beyond,
// which integrates to 1 over the plane. Each item's kernel, sampled at cell centres, is scaled
// to sum to exactly one item over the cells it reaches, so the raster integrates to the item
// count (an item near the grid edge keeps only the part inside the grid).

#include <cstddef>
#include <span>

#include "db/geometry_blob.hpp"
#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct KernelDensityOptions {
  double bandwidth_m = 3.0;  // kernel radius h
};

struct KernelDensityResult {
  Raster density;  // items per m^2
  std::size_t items_used = 0;
  std::size_t items_outside = 0;  // farther than the bandwidth from every cell
};

// The raster convolved with the same kernel, sampled at cell centres and normalised to sum to
// one: a weighted mean of the values within the bandwidth. Cells outside the grid count as 0.
// Throws UsageError when the bandwidth is not positive.
Raster KernelSmooth(const Raster& raster, const KernelDensityOptions& options);

// Throws UsageError when the bandwidth is not positive.
KernelDensityResult KernelDensity(const GridGeometry& grid, std::span<const db::PointXY> items,
                                  const KernelDensityOptions& options);

}  // namespace littermap::heatmap
