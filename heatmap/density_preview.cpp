#include "heatmap/density_preview.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "bag/image_codec.hpp"
#include "core/error.hpp"

namespace littermap::heatmap {
namespace {

const cv::Scalar kUnsurveyed(215, 215, 215);
const cv::Scalar kInk(30, 30, 30);
constexpr int kLegendWidthPx = 190;
constexpr int kTitleHeightPx = 36;

float PeakOf(const Raster& density, float nodata) {
  float peak = 0.0f;
  for (float v : density.values) {
    if (v != nodata) peak = std::max(peak, v);
  }
  return peak > 0.0f ? peak : 1.0f;
}

cv::Mat ColourMap(const Raster& density, float nodata, float peak) {
  cv::Mat levels(density.grid.height, density.grid.width, CV_8UC1);
  cv::Mat valid(density.grid.height, density.grid.width, CV_8UC1);
  for (int r = 0; r < density.grid.height; ++r) {
    for (int c = 0; c < density.grid.width; ++c) {
      const float v = density.at(c, r);
      valid.at<std::uint8_t>(r, c) = v != nodata;
      levels.at<std::uint8_t>(r, c) =
          static_cast<std::uint8_t>(std::clamp(v / peak, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
  }
  cv::Mat colour;
  cv::applyColorMap(levels, colour, cv::COLORMAP_VIRIDIS);
  colour.setTo(kUnsurveyed, valid == 0);
  return colour;
}

const cv::Scalar kMapInk(45, 45, 45);
const cv::Scalar kMappedUnsurveyed(238, 238, 238);

// Occupied map cells as dark ink over the colours; free but unsurveyed ground lighter than
// ground the robot never mapped. Each pixel takes the darkest map cell it covers.
void DrawOccupancy(cv::Mat& map, const GridGeometry& grid, double scale,
                   const DensityPreviewOptions& options) {
  const double pixel_m = grid.cell_size_m / scale;
  const int samples =
      std::clamp(static_cast<int>(std::ceil(pixel_m / options.occupancy_cell_size_m)), 1, 8);
  const auto pixel_of = [](const cv::Scalar& colour) {
    return cv::Vec3b(static_cast<std::uint8_t>(colour[0]), static_cast<std::uint8_t>(colour[1]),
                     static_cast<std::uint8_t>(colour[2]));
  };
  const cv::Vec3b unsurveyed = pixel_of(kUnsurveyed);
  const cv::Vec3b ink = pixel_of(kMapInk);
  const cv::Vec3b mapped_unsurveyed = pixel_of(kMappedUnsurveyed);
  for (int r = 0; r < map.rows; ++r) {
    for (int c = 0; c < map.cols; ++c) {
      int darkest = 256;
      for (int i = 0; i < samples; ++i) {
        for (int j = 0; j < samples; ++j) {
          const double x = grid.min_x_m + (c + (i + 0.5) / samples) * pixel_m;
          const double y = grid.max_y_m - (r + (j + 0.5) / samples) * pixel_m;
          if (const auto grey = options.occupancy(x, y)) darkest = std::min<int>(darkest, *grey);
        }
      }
      cv::Vec3b& pixel = map.at<cv::Vec3b>(r, c);
      if (darkest < 100) {
        // Dark ink, or white ink where the density's colour is dark itself.
        const int luminance = (pixel[0] + 6 * pixel[1] + 3 * pixel[2]) / 10;
        pixel = luminance < 110 ? cv::Vec3b(255, 255, 255) : ink;
      } else if (darkest > 250 && darkest <= 255 && pixel == unsurveyed) {
        pixel = mapped_unsurveyed;
      }
    }
  }
}

void DrawLegend(cv::Mat& canvas, int x0, int map_height, float peak, const std::string& unit,
                bool with_map) {
  const int bar_top = kTitleHeightPx + 10;
  const int bar_height = std::max(60, std::min(300, map_height - 60));
  for (int y = 0; y < bar_height; ++y) {
    cv::Mat level(1, 1, CV_8UC1, cv::Scalar(255.0 * (bar_height - 1 - y) / (bar_height - 1)));
    cv::Mat colour;
    cv::applyColorMap(level, colour, cv::COLORMAP_VIRIDIS);
    cv::line(canvas, {x0 + 10, bar_top + y}, {x0 + 30, bar_top + y},
             cv::Scalar(colour.at<cv::Vec3b>(0, 0)));
  }
  for (int tick = 0; tick <= 4; ++tick) {
    const int y = bar_top + (bar_height - 1) * (4 - tick) / 4;
    char label[32];
    std::snprintf(label, sizeof(label), "%.2f", static_cast<double>(peak) * tick / 4.0);
    cv::putText(canvas, label, {x0 + 36, y + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kInk, 1,
                cv::LINE_AA);
  }
  cv::putText(canvas, unit, {x0 + 4, bar_top + bar_height + 22}, cv::FONT_HERSHEY_SIMPLEX, 0.4,
              kInk, 1, cv::LINE_AA);
  const int key_y = bar_top + bar_height + 40;
  cv::rectangle(canvas, {x0 + 10, key_y}, {x0 + 30, key_y + 14}, kUnsurveyed, cv::FILLED);
  cv::putText(canvas, "not surveyed", {x0 + 36, key_y + 12}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kInk,
              1, cv::LINE_AA);
  if (!with_map) return;
  cv::rectangle(canvas, {x0 + 10, key_y + 22}, {x0 + 30, key_y + 36}, kMappedUnsurveyed,
                cv::FILLED);
  cv::putText(canvas, "mapped, not surveyed", {x0 + 36, key_y + 34}, cv::FONT_HERSHEY_SIMPLEX, 0.4,
              kInk, 1, cv::LINE_AA);
  cv::rectangle(canvas, {x0 + 10, key_y + 44}, {x0 + 30, key_y + 58}, kMapInk, cv::FILLED);
  cv::putText(canvas, "trees, walls (map)", {x0 + 36, key_y + 56}, cv::FONT_HERSHEY_SIMPLEX, 0.4,
              kInk, 1, cv::LINE_AA);
}

}  // namespace

DensityImage RenderDensityImage(const Raster& density, float nodata,
                                const DensityPreviewOptions& options) {
  if (density.grid.width <= 0 || density.grid.height <= 0) {
    throw UsageError("density map: nothing to draw (empty raster)");
  }
  DensityImage image;
  image.peak = PeakOf(density, nodata);
  image.pixels_per_cell =
      std::max(1, options.max_size_px / std::max(density.grid.width, density.grid.height));
  const double scale = image.pixels_per_cell;
  cv::resize(ColourMap(density, nodata, image.peak), image.bgr, {}, scale, scale,
             cv::INTER_NEAREST);
  if (options.occupancy) DrawOccupancy(image.bgr, density.grid, scale, options);
  return image;
}

void WriteDensityPreview(const std::filesystem::path& file, const Raster& density, float nodata,
                         const DensityPreviewOptions& options) {
  if (density.grid.width <= 0 || density.grid.height <= 0) {
    throw UsageError(file.string() + ": nothing to draw (empty raster)");
  }
  const DensityImage image = RenderDensityImage(density, nodata, options);
  const cv::Mat& map = image.bgr;
  const float peak = image.peak;
  const int height = std::max(map.rows, 420) + kTitleHeightPx;
  cv::Mat canvas(height, map.cols + kLegendWidthPx, CV_8UC3, cv::Scalar(255, 255, 255));
  map.copyTo(canvas(cv::Rect(0, kTitleHeightPx, map.cols, map.rows)));
  cv::putText(canvas, options.title, {8, 25}, cv::FONT_HERSHEY_SIMPLEX, 0.6, kInk, 1, cv::LINE_AA);
  DrawLegend(canvas, map.cols, map.rows, peak, options.unit, static_cast<bool>(options.occupancy));
  bag::WriteImageFile(file, canvas);
}

}  // namespace littermap::heatmap
