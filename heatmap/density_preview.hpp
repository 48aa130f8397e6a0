#pragma once
// density.png: a colour preview of a density raster for people without a GIS: viridis colours
// from 0 to the peak, grey where the site was not surveyed, a legend with the scale, north up.

#include <filesystem>
#include <string>

#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct DensityPreviewOptions {
  int max_size_px = 1200;  // the longer side of the map part
  std::string title;
  std::string unit = "items / 100 m2 / survey";
};

// Throws UsageError when the file cannot be written.
void WriteDensityPreview(const std::filesystem::path& file, const Raster& density, float nodata,
                         const DensityPreviewOptions& options);

}  // namespace littermap::heatmap
