#pragma once
// density.png: a colour preview of a density raster for people without a GIS: viridis colours
// from 0 to the peak, grey where the site was not surveyed, the site map's walls, trunks and
// fences drawn over it so people can tell where they are, a legend with the scale, north up.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct DensityPreviewOptions {
  int max_size_px = 1200;  // the longer side of the map part
  std::string title;
  std::string unit = "items / 100 m2 / survey";
  // The site's occupancy map: its grey level (map_server: 0 occupied .. 254 free, 205 unknown)
  // at a point of the raster's CRS, none outside the map. Unset: no map drawn.
  std::function<std::optional<std::uint8_t>(double x_m, double y_m)> occupancy;
  double occupancy_cell_size_m = 0.05;  // the map's resolution: thin walls are not skipped
};

// The map part of the preview, north up: `pixels_per_cell` pixels a raster cell, the colour
// scale running from 0 to `peak`.
struct DensityImage {
  cv::Mat bgr;
  int pixels_per_cell = 1;
  float peak = 1.0f;
};

// Throws UsageError for an empty raster.
DensityImage RenderDensityImage(const Raster& density, float nodata,
                                const DensityPreviewOptions& options);

// Throws UsageError when the file cannot be written.
void WriteDensityPreview(const std::filesystem::path& file, const Raster& density, float nodata,
                         const DensityPreviewOptions& options);

}  // namespace littermap::heatmap
