#pragma once
// Cloud-Optimized GeoTIFF writer (libtiff + libgeotiff, no GDAL): float32, square tiles,
// deflate with the floating-point predictor, internal overviews (reduced-resolution subfiles,
// 2x2 means of the valid cells), GDAL_NODATA, and the EPSG code, tie point and pixel scale as
// GeoTIFF keys. Layout as the COG definition asks: all IFDs first, then tile data from the
// smallest overview to full resolution.

#include <cstdint>
#include <filesystem>
#include <string>

#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct GeoTiffOptions {
  int tile_size_px = 256;   // 256 or 512 for COG readers; any multiple of 16 works
  int deflate_level = 6;    // 1 fast ... 9 small
  float nodata = -9999.0f;  // cells with this value are "no data"
  int epsg_code = 0;        // projected CRS of the grid; 0: a local metric frame
  std::string citation;     // GTCitationGeoKey, e.g. "littermap density, items per 100 m2"
  std::string local_crs_name = "littermap site frame";  // the local frame's PCSCitationGeoKey
};

struct GeoTiffResult {
  int overview_count = 0;
  std::uint64_t file_size_bytes = 0;
};

// Throws UsageError for an empty raster or bad options, InternalError when writing fails
// (both naming the file).
GeoTiffResult WriteCloudOptimizedGeoTiff(const std::filesystem::path& file, const Raster& raster,
                                         const GeoTiffOptions& options);

// One level of the overview pyramid: each cell the mean of the valid cells of a 2x2 block.
Raster Downsample2x(const Raster& raster, float nodata);

}  // namespace littermap::heatmap
