#pragma once
// Occupancy grid in log-odds (thesis 2.1): every cell starts at 0 (p = 0.5); a scan taken at a
// known pose adds l_hit to the cell of each echo and l_miss to every cell the beam crossed
// before it, L(cell | all data) = L(cell | this scan) + L(cell | earlier data) - L(prior), with
// L(prior) = 0, clamped so that cells stay able to change (moving obstacles fade out).
// The grid grows to fit what is inserted. Rays are traversed with Amanatides & Woo (1987), which
// visits every cell a segment passes through, unlike sampling or plain Bresenham.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/planar_pose.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct OccupancyGridOptions {
  double cell_size_m = 0.05;
  double log_odds_hit = 0.85;   // ln(0.7 / 0.3)
  double log_odds_miss = -0.4;  // ln(0.4 / 0.6)
  double log_odds_min = -2.0;
  double log_odds_max = 3.5;
  void Validate() const;
};

struct CellIndex {
  std::int64_t x = 0;
  std::int64_t y = 0;
  bool operator==(const CellIndex&) const = default;
};

// Calls visit for every cell the segment from a to b passes through, in order, a's cell first and
// b's cell last (Amanatides & Woo). Coordinates in metres, cells of size cell_size_m at integer
// multiples of it.
inline std::int64_t CellCoordinate(double v, double cell_size_m) {
  return static_cast<std::int64_t>(std::floor(v / cell_size_m));
}

template <typename Visit>
void TraverseRay(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double cell_size_m,
                 Visit&& visit) {
  CellIndex cell{CellCoordinate(a.x(), cell_size_m), CellCoordinate(a.y(), cell_size_m)};
  const CellIndex last{CellCoordinate(b.x(), cell_size_m), CellCoordinate(b.y(), cell_size_m)};
  const Eigen::Vector2d d = b - a;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int step_x = d.x() > 0 ? 1 : (d.x() < 0 ? -1 : 0);
  const int step_y = d.y() > 0 ? 1 : (d.y() < 0 ? -1 : 0);
  // t (0..1 along the segment) at the next vertical / horizontal cell border, and per cell.
  const double next_x = static_cast<double>(cell.x + (step_x > 0 ? 1 : 0)) * cell_size_m;
  const double next_y = static_cast<double>(cell.y + (step_y > 0 ? 1 : 0)) * cell_size_m;
  double t_max_x = step_x != 0 ? (next_x - a.x()) / d.x() : kInf;
  double t_max_y = step_y != 0 ? (next_y - a.y()) / d.y() : kInf;
  const double t_delta_x = step_x != 0 ? cell_size_m / std::abs(d.x()) : kInf;
  const double t_delta_y = step_y != 0 ? cell_size_m / std::abs(d.y()) : kInf;
  const std::int64_t steps = std::abs(last.x - cell.x) + std::abs(last.y - cell.y);
  visit(cell);
  for (std::int64_t i = 0; i < steps; ++i) {
    // Step along the axis whose border comes first; the step count is fixed by the end cell so
    // rounding can never run past b or stop short of it.
    const bool x_first = (t_max_x < t_max_y && cell.x != last.x) || cell.y == last.y;
    if (x_first) {
      cell.x += step_x;
      t_max_x += t_delta_x;
    } else {
      cell.y += step_y;
      t_max_y += t_delta_y;
    }
    visit(cell);
  }
}

class OccupancyGrid {
 public:
  explicit OccupancyGrid(const OccupancyGridOptions& options);

  // Adds one scan: origin = laser position in the world, hits = echo points in the world.
  void InsertScan(const Eigen::Vector2d& origin, const Points2& hits);
  // Makes the grid cover the box [low, high] (world, metres) at once: growing scan by scan
  // copies a large map each time the robot drives past its edge.
  void Cover(const Eigen::Vector2d& low, const Eigen::Vector2d& high);

  CellIndex CellOf(const Eigen::Vector2d& p) const;
  float LogOdds(CellIndex cell) const;  // 0 outside the grid
  bool empty() const { return width_ == 0; }
  std::int64_t width() const { return width_; }
  std::int64_t height() const { return height_; }
  CellIndex min_cell() const { return min_; }
  const OccupancyGridOptions& options() const { return options_; }

  // ROS map_server convention: PATH.pgm (P5, 0 occupied .. 254 free, 205 unknown, top row =
  // largest y) and PATH.yaml (image, resolution, origin of the lower-left cell, thresholds).
  void WritePgmYaml(const std::filesystem::path& pgm_path,
                    const std::filesystem::path& yaml_path) const;
  // A PNG preview with the same grey levels, for people.
  void WritePng(const std::filesystem::path& png_path) const;

 private:
  void Grow(CellIndex low, CellIndex high);
  float& At(CellIndex cell) {
    return cells_[static_cast<std::size_t>((cell.y - min_.y) * width_ + (cell.x - min_.x))];
  }
  std::vector<std::uint8_t> Image() const;  // row-major, top row first

  OccupancyGridOptions options_;
  CellIndex min_;
  std::int64_t width_ = 0;
  std::int64_t height_ = 0;
  std::vector<float> cells_;
};

}  // namespace littermap::reconstruct
