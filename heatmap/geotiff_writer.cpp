#include "heatmap/geotiff_writer.hpp"

#include <geo_normalize.h>
#include <geotiff.h>
#include <geovalues.h>
#include <tiffio.h>
#include <xtiffio.h>
#include <cerrno>

#include <cstdarg>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"
#include "heatmap/tiff_tags.hpp"

namespace littermap::heatmap {
namespace {

// libtiff reports through handlers; collect the first message so the error names it.
int CollectMessage(TIFF*, void* user_data, const char* module, const char* format, va_list args) {
  auto* message = static_cast<std::string*>(user_data);
  if (message->empty()) {
    char text[512];
    std::vsnprintf(text, sizeof(text), format, args);
    *message = std::string(module ? module : "libtiff") + ": " + text;
  }
  return 1;
}

int IgnoreWarning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

class TiffFile {
 public:
  // Writes `path`; failures name `file`, the output `path` becomes.
  TiffFile(const std::filesystem::path& path, const std::filesystem::path& file) : file_(file) {
    RegisterGeoTiffTags();
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, CollectMessage, &message_);
    TIFFOpenOptionsSetWarningHandlerExtR(options, IgnoreWarning, nullptr);
    tif_ = TIFFOpenExt(path.c_str(), "w", options);
    TIFFOpenOptionsFree(options);
    if (tif_ == nullptr) Fail("cannot create the file");
  }
  ~TiffFile() {
    if (tif_) XTIFFClose(tif_);
  }
  TIFF* get() { return tif_; }
  void Check(int ok, const char* action) {
    if (!ok) Fail(action);
  }
  void Close() {
    XTIFFClose(tif_);
    tif_ = nullptr;
    if (!message_.empty()) Fail("closing");
  }
  [[noreturn]] void Fail(const std::string& action) {
    throw FileFailure(
        file_,
        "writing GeoTIFF failed (" + action + (message_.empty() ? "" : ": " + message_) + ")",
        errno);
  }

 private:
  std::filesystem::path file_;
  std::string message_;
  TIFF* tif_ = nullptr;
};

void SetImageTags(TIFF* tif, const GridGeometry& grid, const GeoTiffOptions& options,
                  bool overview) {
  if (overview) TIFFSetField(tif, TIFFTAG_SUBFILETYPE, FILETYPE_REDUCEDIMAGE);
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(grid.width));
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(grid.height));
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 32);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
  TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
  TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_FLOATINGPOINT);
  TIFFSetField(tif, TIFFTAG_TILEWIDTH, static_cast<std::uint32_t>(options.tile_size_px));
  TIFFSetField(tif, TIFFTAG_TILELENGTH, static_cast<std::uint32_t>(options.tile_size_px));
  char nodata[32];
  std::snprintf(nodata, sizeof(nodata), "%.9g", static_cast<double>(options.nodata));
  TIFFSetField(tif, TIFFTAG_GDAL_NODATA, nodata);
}

// GeoTIFF 1.1 keys (OGC 19-008r4): projected model, pixel-is-area, the EPSG code (or a
// user-defined CRS in metres), the tie point of the north-west corner and the cell size.
void SetGeoKeys(TIFF* tif, const GridGeometry& grid, const GeoTiffOptions& options) {
  const double tiepoint[6] = {0, 0, 0, grid.min_x_m, grid.max_y_m, 0};
  const double scale[3] = {grid.cell_size_m, grid.cell_size_m, 0};
  TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, tiepoint);
  TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, scale);
  GTIF* gtif = GTIFNew(tif);
  GTIFKeySet(gtif, GTModelTypeGeoKey, TYPE_SHORT, 1, ModelTypeProjected);
  GTIFKeySet(gtif, GTRasterTypeGeoKey, TYPE_SHORT, 1, RasterPixelIsArea);
  if (!options.citation.empty()) {
    GTIFKeySet(gtif, GTCitationGeoKey, TYPE_ASCII, 0, options.citation.c_str());
  }
  if (options.epsg_code != 0) {
    GTIFKeySet(gtif, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, options.epsg_code);
  } else {
    GTIFKeySet(gtif, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, KvUserDefined);
    GTIFKeySet(gtif, ProjLinearUnitsGeoKey, TYPE_SHORT, 1, Linear_Meter);
    GTIFKeySet(gtif, PCSCitationGeoKey, TYPE_ASCII, 0, options.local_crs_name.c_str());
  }
  GTIFWriteKeys(gtif);
  GTIFFree(gtif);
}

void WriteTiles(TiffFile& file, const Raster& raster, const GeoTiffOptions& options) {
  const int tile = options.tile_size_px;
  std::vector<float> buffer(static_cast<std::size_t>(tile) * tile);
  const int tiles_x = (raster.grid.width + tile - 1) / tile;
  const int tiles_y = (raster.grid.height + tile - 1) / tile;
  for (int ty = 0; ty < tiles_y; ++ty) {
    for (int tx = 0; tx < tiles_x; ++tx) {
      std::fill(buffer.begin(), buffer.end(), options.nodata);
      for (int r = 0; r < tile && ty * tile + r < raster.grid.height; ++r) {
        for (int c = 0; c < tile && tx * tile + c < raster.grid.width; ++c) {
          buffer[static_cast<std::size_t>(r) * tile + c] = raster.at(tx * tile + c, ty * tile + r);
        }
      }
      const auto index = static_cast<std::uint32_t>(ty * tiles_x + tx);
      file.Check(TIFFWriteEncodedTile(file.get(), index, buffer.data(),
                                      static_cast<tmsize_t>(buffer.size() * sizeof(float))) >= 0,
                 "writing a tile");
    }
  }
}

void ValidateOptions(const std::filesystem::path& file, const Raster& raster,
                     const GeoTiffOptions& options) {
  if (raster.grid.width <= 0 || raster.grid.height <= 0 ||
      raster.values.size() != raster.grid.size()) {
    throw UsageError(file.string() + ": the raster to write is empty or inconsistent");
  }
  if (options.tile_size_px < 16 || options.tile_size_px % 16 != 0) {
    throw UsageError(file.string() + ": tile_size_px must be a positive multiple of 16");
  }
  if (options.epsg_code < 0 || options.epsg_code > 65535) {
    throw UsageError(file.string() + ": EPSG code " + std::to_string(options.epsg_code) +
                     " does not fit a GeoTIFF key");
  }
}

}  // namespace

Raster Downsample2x(const Raster& raster, float nodata) {
  GridGeometry grid = raster.grid;
  grid.width = (raster.grid.width + 1) / 2;
  grid.height = (raster.grid.height + 1) / 2;
  grid.cell_size_m *= 2.0;
  Raster out(grid, nodata);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      double sum = 0.0;
      int count = 0;
      for (int dr = 0; dr < 2; ++dr) {
        for (int dc = 0; dc < 2; ++dc) {
          const int sc = 2 * c + dc;
          const int sr = 2 * r + dr;
          if (sc >= raster.grid.width || sr >= raster.grid.height) continue;
          const float v = raster.at(sc, sr);
          if (v == nodata || std::isnan(v)) continue;
          sum += v;
          ++count;
        }
      }
      if (count > 0) out.at(c, r) = static_cast<float>(sum / count);
    }
  }
  return out;
}

GeoTiffResult WriteCloudOptimizedGeoTiff(const std::filesystem::path& file, const Raster& raster,
                                         const GeoTiffOptions& options) {
  ValidateOptions(file, raster, options);
  std::vector<Raster> overviews;
  const Raster* level = &raster;
  while (level->grid.width > options.tile_size_px || level->grid.height > options.tile_size_px) {
    overviews.push_back(Downsample2x(*level, options.nodata));
    level = &overviews.back();
  }
  OutputFile output = OutputFile::ByName(file);
  TiffFile tiff(output.temporary(), file);
  // All IFDs first, with their tile arrays deferred (libtiff's COG support).
  for (std::size_t i = 0; i <= overviews.size(); ++i) {
    const Raster& image = i == 0 ? raster : overviews[i - 1];
    SetImageTags(tiff.get(), image.grid, options, i > 0);
    TIFFSetField(tiff.get(), TIFFTAG_ZIPQUALITY, options.deflate_level);
    if (i == 0) SetGeoKeys(tiff.get(), raster.grid, options);
    TIFFDeferStrileArrayWriting(tiff.get());
    tiff.Check(TIFFWriteCheck(tiff.get(), 1, "littermap"), "checking the directory");
    tiff.Check(TIFFWriteDirectory(tiff.get()), "writing a directory");
  }
  // Then the data, smallest overview first, so a reader of the overview needs the fewest bytes.
  for (std::size_t i = overviews.size() + 1; i-- > 0;) {
    tiff.Check(TIFFSetDirectory(tiff.get(), static_cast<tdir_t>(i)), "selecting a directory");
    TIFFSetField(tiff.get(), TIFFTAG_ZIPQUALITY, options.deflate_level);
    WriteTiles(tiff, i == 0 ? raster : overviews[i - 1], options);
    tiff.Check(TIFFForceStrileArrayWriting(tiff.get()), "writing the tile index");
  }
  tiff.Close();
  output.Commit();
  GeoTiffResult result;
  result.overview_count = static_cast<int>(overviews.size());
  result.file_size_bytes = std::filesystem::file_size(file);
  return result;
}

}  // namespace littermap::heatmap
