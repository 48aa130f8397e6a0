#include "reconstruct/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <opencv2/core.hpp>

#include "bag/image_codec.hpp"
#include "core/error.hpp"
#include "core/map_server_grey.hpp"
#include "core/output_file.hpp"

namespace littermap::reconstruct {
namespace {

using map_grey::kFree;
using map_grey::kOccupied;
using map_grey::kUnknown;
constexpr std::int64_t kGrowMarginCells = 64;

}  // namespace

void OccupancyGridOptions::Validate() const {
  if (!(cell_size_m > 0)) throw UsageError("grid: cell_size_m must be > 0");
  if (!(log_odds_hit > 0) || !(log_odds_miss < 0)) {
    throw UsageError("grid: need log_odds_hit > 0 and log_odds_miss < 0");
  }
  if (!(log_odds_min < 0) || !(log_odds_max > 0)) {
    throw UsageError("grid: need log_odds_min < 0 < log_odds_max");
  }
}

OccupancyGrid::OccupancyGrid(const OccupancyGridOptions& options) : options_(options) {
  options_.Validate();
}

CellIndex OccupancyGrid::CellOf(const Eigen::Vector2d& p) const {
  return {CellCoordinate(p.x(), options_.cell_size_m), CellCoordinate(p.y(), options_.cell_size_m)};
}

float OccupancyGrid::LogOdds(CellIndex cell) const {
  if (cell.x < min_.x || cell.y < min_.y || cell.x >= min_.x + width_ ||
      cell.y >= min_.y + height_) {
    return 0.0f;
  }
  return cells_[static_cast<std::size_t>((cell.y - min_.y) * width_ + (cell.x - min_.x))];
}

void OccupancyGrid::Grow(CellIndex low, CellIndex high) {
  if (width_ > 0 && low.x >= min_.x && low.y >= min_.y && high.x < min_.x + width_ &&
      high.y < min_.y + height_) {
    return;
  }
  CellIndex new_min = low, new_max = high;
  if (width_ > 0) {
    new_min = {std::min(low.x, min_.x), std::min(low.y, min_.y)};
    new_max = {std::max(high.x, min_.x + width_ - 1), std::max(high.y, min_.y + height_ - 1)};
  }
  // A margin so that a robot driving on does not reallocate for every scan.
  new_min = {new_min.x - kGrowMarginCells, new_min.y - kGrowMarginCells};
  new_max = {new_max.x + kGrowMarginCells, new_max.y + kGrowMarginCells};
  const std::int64_t new_width = new_max.x - new_min.x + 1;
  const std::int64_t new_height = new_max.y - new_min.y + 1;
  std::vector<float> cells(static_cast<std::size_t>(new_width * new_height), 0.0f);
  for (std::int64_t y = 0; y < height_; ++y) {
    std::copy_n(cells_.begin() + y * width_, width_,
                cells.begin() + ((y + min_.y - new_min.y) * new_width + (min_.x - new_min.x)));
  }
  cells_ = std::move(cells);
  min_ = new_min;
  width_ = new_width;
  height_ = new_height;
}

void OccupancyGrid::Cover(const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
  if (low.x() <= high.x() && low.y() <= high.y()) Grow(CellOf(low), CellOf(high));
}

void OccupancyGrid::InsertScan(const Eigen::Vector2d& origin, const Points2& hits) {
  if (hits.empty()) return;
  CellIndex low = CellOf(origin), high = low;
  for (const Eigen::Vector2d& p : hits) {
    const CellIndex c = CellOf(p);
    low = {std::min(low.x, c.x), std::min(low.y, c.y)};
    high = {std::max(high.x, c.x), std::max(high.y, c.y)};
  }
  Grow(low, high);
  const auto miss = static_cast<float>(options_.log_odds_miss);
  const auto hit = static_cast<float>(options_.log_odds_hit);
  const auto lo = static_cast<float>(options_.log_odds_min);
  const auto hi = static_cast<float>(options_.log_odds_max);
  for (const Eigen::Vector2d& p : hits) {
    const CellIndex end = CellOf(p);
    TraverseRay(origin, p, options_.cell_size_m, [&](CellIndex cell) {
      if (cell == end) return;
      float& value = At(cell);
      value = std::max(lo, value + miss);
    });
  }
  // Hits after misses, so that a cell crossed by one beam and hit by another ends occupied.
  for (const Eigen::Vector2d& p : hits) {
    float& value = At(CellOf(p));
    value = std::min(hi, value + hit);
  }
}

std::vector<std::uint8_t> OccupancyGrid::Image() const {
  std::vector<std::uint8_t> image(static_cast<std::size_t>(width_ * height_), kUnknown);
  // map_server thresholds: occupied above p = 0.65, free below p = 0.196.
  const float occupied = std::log(0.65f / 0.35f);
  const float free = std::log(0.196f / 0.804f);
  for (std::int64_t row = 0; row < height_; ++row) {
    const std::int64_t y = height_ - 1 - row;
    for (std::int64_t x = 0; x < width_; ++x) {
      const float value = cells_[static_cast<std::size_t>(y * width_ + x)];
      std::uint8_t& pixel = image[static_cast<std::size_t>(row * width_ + x)];
      if (value > occupied) {
        pixel = kOccupied;
      } else if (value < free) {
        pixel = kFree;
      }
    }
  }
  return image;
}

void OccupancyGrid::WritePgmYaml(const std::filesystem::path& pgm_path,
                                 const std::filesystem::path& yaml_path) const {
  const std::vector<std::uint8_t> image = Image();
  OutputFile pgm_file(pgm_path);
  std::ostream& pgm = pgm_file.stream();
  pgm << "P5\n# littermap occupancy grid\n" << width_ << " " << height_ << "\n255\n";
  pgm.write(reinterpret_cast<const char*>(image.data()),
            static_cast<std::streamsize>(image.size()));
  OutputFile yaml_file(yaml_path);
  std::ostream& yaml = yaml_file.stream();
  const double cell = options_.cell_size_m;
  yaml << "image: " << pgm_path.filename().string() << "\n"
       << "mode: trinary\n"
       << "resolution: " << cell << "\n"
       << "origin: [" << static_cast<double>(min_.x) * cell << ", "
       << static_cast<double>(min_.y) * cell << ", 0.0]\n"
       << "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  pgm_file.Commit();
  yaml_file.Commit();
}

void OccupancyGrid::WritePng(const std::filesystem::path& png_path) const {
  std::vector<std::uint8_t> image = Image();
  if (image.empty()) image.assign(1, kUnknown);
  const cv::Mat mat(std::max<int>(1, static_cast<int>(height_)),
                    std::max<int>(1, static_cast<int>(width_)), CV_8UC1, image.data());
  bag::WriteImageFile(png_path, mat);
}

}  // namespace littermap::reconstruct
