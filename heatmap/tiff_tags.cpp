#include "heatmap/tiff_tags.hpp"

#include <tiffio.h>
#include <xtiffio.h>

#include <mutex>

namespace littermap::heatmap {
namespace {

char kNoDataName[] = "GDALNoDataValue";
const TIFFFieldInfo kGdalFields[] = {
    {TIFFTAG_GDAL_NODATA, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, kNoDataName},
};

TIFFExtendProc g_parent_extender = nullptr;

void GdalTagExtender(TIFF* tif) {
  TIFFMergeFieldInfo(tif, kGdalFields, sizeof(kGdalFields) / sizeof(kGdalFields[0]));
  if (g_parent_extender) g_parent_extender(tif);
}

}  // namespace

void RegisterGeoTiffTags() {
  static std::once_flag once;
  std::call_once(once, [] {
    XTIFFInitialize();
    g_parent_extender = TIFFSetTagExtender(GdalTagExtender);
  });
}

}  // namespace littermap::heatmap
