#pragma once
// A north-up float raster in the site CRS: row 0 is the northern edge (as in GeoTIFF), cell
// (column c, row r) covers x in [min_x_m + c s, min_x_m + (c+1) s) and
// y in (max_y_m - (r+1) s, max_y_m - r s] for cell size s.

#include <cmath>
#include <cstddef>
#include <vector>

namespace littermap::heatmap {

struct GridGeometry {
  double min_x_m = 0.0;  // western edge
  double max_y_m = 0.0;  // northern edge
  double cell_size_m = 0.5;
  int width = 0;
  int height = 0;

  double max_x_m() const { return min_x_m + width * cell_size_m; }
  double min_y_m() const { return max_y_m - height * cell_size_m; }
  double CellCenterX(int column) const { return min_x_m + (column + 0.5) * cell_size_m; }
  double CellCenterY(int row) const { return max_y_m - (row + 0.5) * cell_size_m; }
  double cell_area_m2() const { return cell_size_m * cell_size_m; }
  std::size_t size() const { return static_cast<std::size_t>(width) * height; }

  // A grid covering [min_x, max_x] x [min_y, max_y] plus margin_m on every side.
  static GridGeometry Covering(double min_x, double min_y, double max_x, double max_y,
                               double cell_size_m, double margin_m) {
    GridGeometry grid;
    grid.cell_size_m = cell_size_m;
    grid.min_x_m = std::floor((min_x - margin_m) / cell_size_m) * cell_size_m;
    grid.max_y_m = std::ceil((max_y + margin_m) / cell_size_m) * cell_size_m;
    grid.width = static_cast<int>(std::ceil((max_x + margin_m - grid.min_x_m) / cell_size_m));
    grid.height = static_cast<int>(std::ceil((grid.max_y_m - (min_y - margin_m)) / cell_size_m));
    return grid;
  }
};

struct Raster {
  GridGeometry grid;
  std::vector<float> values;  // row-major, grid.size() values

  explicit Raster(const GridGeometry& geometry = {}, float fill = 0.0f)
      : grid(geometry), values(geometry.size(), fill) {}
  float& at(int column, int row) {
    return values[static_cast<std::size_t>(row) * grid.width + column];
  }
  float at(int column, int row) const {
    return values[static_cast<std::size_t>(row) * grid.width + column];
  }
};

}  // namespace littermap::heatmap
