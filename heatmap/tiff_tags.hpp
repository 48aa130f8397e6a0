#pragma once
// Makes libtiff know the GeoTIFF tags (via libgeotiff) and GDAL's nodata tag (42113, an ASCII
// number), for writing and reading. Safe to call any number of times, from any thread.

namespace littermap::heatmap {

void RegisterGeoTiffTags();

}  // namespace littermap::heatmap
