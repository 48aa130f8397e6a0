// Writes Cloud-Optimized GeoTIFFs and reads them back with libtiff and libgeotiff only.

#include "heatmap/geotiff_writer.hpp"

#include <geotiff.h>
#include <geovalues.h>
#include <gtest/gtest.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <vector>

#include "core/error.hpp"
#include "heatmap/tiff_tags.hpp"
#include "support/temp_dir.hpp"

namespace littermap::heatmap {
namespace {

using littermap::test::TempDir;

// 600 x 400 cells of 0.5 m, north-west corner at (500000, 5000200); value = column + 1000 row,
// and a nodata block in the north-west corner.
Raster TestRaster(float nodata) {
  GridGeometry grid;
  grid.min_x_m = 500000.0;
  grid.max_y_m = 5000200.0;
  grid.cell_size_m = 0.5;
  grid.width = 600;
  grid.height = 400;
  Raster raster(grid);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      raster.at(c, r) = (c < 10 && r < 10) ? nodata : static_cast<float>(c + 1000 * r);
    }
  }
  return raster;
}

struct TiffReader {
  explicit TiffReader(const std::filesystem::path& file) {
    RegisterGeoTiffTags();
    tif = XTIFFOpen(file.c_str(), "r");
  }
  ~TiffReader() {
    if (tif) XTIFFClose(tif);
  }
  TIFF* tif = nullptr;
};

float ReadCell(TIFF* tif, std::uint32_t column, std::uint32_t row) {
  std::uint32_t tile_width = 0;
  TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tile_width);
  std::vector<float> tile(static_cast<std::size_t>(TIFFTileSize(tif)) / sizeof(float));
  const std::uint32_t index = TIFFComputeTile(tif, column, row, 0, 0);
  EXPECT_GT(TIFFReadEncodedTile(tif, index, tile.data(), TIFFTileSize(tif)), 0);
  return tile[(row % tile_width) * tile_width + column % tile_width];
}

class GeoTiffWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options_.epsg_code = 32633;
    options_.citation = "littermap test";
    result_ = WriteCloudOptimizedGeoTiff(file_, TestRaster(options_.nodata), options_);
  }
  TempDir dir_;
  std::filesystem::path file_ = dir_ / "density.tif";
  GeoTiffOptions options_;
  GeoTiffResult result_;
};

TEST_F(GeoTiffWriterTest, MainImageIsTiledDeflatedFloat32) {
  TiffReader reader(file_);
  ASSERT_NE(reader.tif, nullptr);
  std::uint32_t width = 0, height = 0, tile_width = 0, tile_height = 0;
  std::uint16_t bits = 0, format = 0, compression = 0;
  TIFFGetField(reader.tif, TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(reader.tif, TIFFTAG_IMAGELENGTH, &height);
  TIFFGetField(reader.tif, TIFFTAG_TILEWIDTH, &tile_width);
  TIFFGetField(reader.tif, TIFFTAG_TILELENGTH, &tile_height);
  TIFFGetField(reader.tif, TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetField(reader.tif, TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetField(reader.tif, TIFFTAG_COMPRESSION, &compression);
  EXPECT_EQ(width, 600u);
  EXPECT_EQ(height, 400u);
  EXPECT_TRUE(TIFFIsTiled(reader.tif));
  EXPECT_EQ(tile_width, 256u);
  EXPECT_EQ(tile_height, 256u);
  EXPECT_EQ(bits, 32);
  EXPECT_EQ(format, SAMPLEFORMAT_IEEEFP);
  EXPECT_EQ(compression, COMPRESSION_ADOBE_DEFLATE);
  EXPECT_EQ(ReadCell(reader.tif, 599, 399), 599.0f + 1000.0f * 399);
  EXPECT_EQ(ReadCell(reader.tif, 300, 5), 300.0f + 5000.0f);
  EXPECT_EQ(ReadCell(reader.tif, 3, 3), -9999.0f);
}

TEST_F(GeoTiffWriterTest, NodataTagIsGdalCompatible) {
  TiffReader reader(file_);
  const char* nodata = nullptr;
  ASSERT_EQ(TIFFGetField(reader.tif, TIFFTAG_GDAL_NODATA, &nodata), 1);
  EXPECT_STREQ(nodata, "-9999");
}

TEST_F(GeoTiffWriterTest, GeoreferenceIsEpsgWithTiePointAndScale) {
  TiffReader reader(file_);
  std::uint16_t count = 0;
  double* values = nullptr;
  ASSERT_EQ(TIFFGetField(reader.tif, TIFFTAG_GEOTIEPOINTS, &count, &values), 1);
  ASSERT_EQ(count, 6);
  EXPECT_EQ(values[0], 0.0);
  EXPECT_EQ(values[1], 0.0);
  EXPECT_EQ(values[3], 500000.0);
  EXPECT_EQ(values[4], 5000200.0);
  ASSERT_EQ(TIFFGetField(reader.tif, TIFFTAG_GEOPIXELSCALE, &count, &values), 1);
  ASSERT_EQ(count, 3);
  EXPECT_EQ(values[0], 0.5);
  EXPECT_EQ(values[1], 0.5);
  GTIF* gtif = GTIFNew(reader.tif);
  ASSERT_NE(gtif, nullptr);
  unsigned short model = 0, raster_type = 0, pcs = 0;
  EXPECT_EQ(GTIFKeyGetSHORT(gtif, GTModelTypeGeoKey, &model, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(gtif, GTRasterTypeGeoKey, &raster_type, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(gtif, ProjectedCSTypeGeoKey, &pcs, 0, 1), 1);
  EXPECT_EQ(model, ModelTypeProjected);
  EXPECT_EQ(raster_type, RasterPixelIsArea);
  EXPECT_EQ(pcs, 32633);
  GTIFFree(gtif);
}

TEST_F(GeoTiffWriterTest, OverviewsAreReducedResolutionSubfiles) {
  // 600x400 -> 300x200 -> 150x100: the smallest fits one 256 tile.
  EXPECT_EQ(result_.overview_count, 2);
  TiffReader reader(file_);
  const std::uint32_t expected_width[] = {600, 300, 150};
  std::vector<std::uint64_t> ifd_offsets;
  std::uint64_t first_data = UINT64_MAX;
  int directory = 0;
  do {
    std::uint32_t width = 0, subfile = 0;
    TIFFGetField(reader.tif, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetFieldDefaulted(reader.tif, TIFFTAG_SUBFILETYPE, &subfile);
    ASSERT_LT(directory, 3);
    EXPECT_EQ(width, expected_width[directory]);
    EXPECT_EQ(subfile, directory == 0 ? 0u : static_cast<std::uint32_t>(FILETYPE_REDUCEDIMAGE));
    EXPECT_TRUE(TIFFIsTiled(reader.tif));
    ifd_offsets.push_back(TIFFCurrentDirOffset(reader.tif));
    for (std::uint32_t t = 0; t < TIFFNumberOfTiles(reader.tif); ++t) {
      first_data = std::min(first_data, TIFFGetStrileOffset(reader.tif, t));
    }
    ++directory;
  } while (TIFFReadDirectory(reader.tif));
  EXPECT_EQ(directory, 3);
  // Cloud-optimized layout: every IFD precedes all tile data.
  for (std::uint64_t offset : ifd_offsets) EXPECT_LT(offset, first_data);
  // The first overview cell is the mean of the valid cells of its 2x2 block.
  ASSERT_TRUE(TIFFSetDirectory(reader.tif, 1));
  EXPECT_EQ(ReadCell(reader.tif, 10, 10), (20 + 21 + 20 + 21 + 4 * 20000 + 2 * 1000) / 4.0f);
  EXPECT_EQ(ReadCell(reader.tif, 0, 0), -9999.0f);
}

TEST(GeoTiffWriter, LocalFrameIsAUserDefinedMetricCrs) {
  TempDir dir;
  GeoTiffOptions options;  // epsg_code 0
  WriteCloudOptimizedGeoTiff(dir / "local.tif", TestRaster(options.nodata), options);
  TiffReader reader(dir / "local.tif");
  GTIF* gtif = GTIFNew(reader.tif);
  unsigned short pcs = 0, units = 0;
  EXPECT_EQ(GTIFKeyGetSHORT(gtif, ProjectedCSTypeGeoKey, &pcs, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(gtif, ProjLinearUnitsGeoKey, &units, 0, 1), 1);
  EXPECT_EQ(pcs, KvUserDefined);
  EXPECT_EQ(units, Linear_Meter);
  GTIFFree(gtif);
}

TEST(GeoTiffWriter, RefusesEmptyRastersAndBadTiles) {
  TempDir dir;
  EXPECT_THROW(WriteCloudOptimizedGeoTiff(dir / "e.tif", Raster(), {}), UsageError);
  GeoTiffOptions options;
  options.tile_size_px = 100;
  EXPECT_THROW(WriteCloudOptimizedGeoTiff(dir / "t.tif", TestRaster(-9999.0f), options),
               UsageError);
}

}  // namespace
}  // namespace littermap::heatmap
