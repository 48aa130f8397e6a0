#include "heatmap/kernel_density.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/error.hpp"

namespace littermap::heatmap {
namespace {

struct Window {
  int c0, c1, r0, r1;
};

Window KernelWindow(const GridGeometry& grid, const db::PointXY& p, double h) {
  const double s = grid.cell_size_m;
  // Cells whose centre may lie within h: centre x = min_x + (c + 0.5) s.
  return {
      std::max(0, static_cast<int>(std::ceil((p.x - h - grid.min_x_m) / s - 0.5))),
      std::min(grid.width - 1, static_cast<int>(std::floor((p.x + h - grid.min_x_m) / s - 0.5))),
      std::max(0, static_cast<int>(std::ceil((grid.max_y_m - p.y - h) / s - 0.5))),
      std::min(grid.height - 1, static_cast<int>(std::floor((grid.max_y_m - p.y + h) / s - 0.5)))};
}

// The kernel weights (1 - d^2/h^2)^2 of one item at cell centres, kept in a small buffer so the
// stamp can be normalised before it is added. Returns the sum of the weights.
struct Stamp {
  std::vector<float> dx2;      // per column of the window: (x_c - x)^2 / h^2
  std::vector<float> weights;  // window cells, row-major
  double Fill(const GridGeometry& grid, const db::PointXY& p, double h, const Window& w) {
    const int columns = w.c1 - w.c0 + 1;
    const double inv_h2 = 1.0 / (h * h);
    dx2.resize(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c) {
      const double dx = grid.CellCenterX(w.c0 + c) - p.x;
      dx2[static_cast<std::size_t>(c)] = static_cast<float>(dx * dx * inv_h2);
    }
    weights.assign(static_cast<std::size_t>(columns) * (w.r1 - w.r0 + 1), 0.0f);
    double sum = 0.0;
    for (int r = w.r0; r <= w.r1; ++r) {
      const double dy = grid.CellCenterY(r) - p.y;
      const float ry = static_cast<float>(1.0 - dy * dy * inv_h2);
      if (ry <= 0.0f) continue;
      float* row = weights.data() + static_cast<std::size_t>(r - w.r0) * columns;
      float row_sum = 0.0f;
      for (int c = 0; c < columns; ++c) {
        const float u = std::max(ry - dx2[static_cast<std::size_t>(c)], 0.0f);
        row[c] = u * u;
        row_sum += row[c];
      }
      sum += row_sum;
    }
    return sum;
  }
};

// Items sorted by row, then column, so consecutive stamps touch neighbouring memory.
std::vector<db::PointXY> SortedForLocality(const GridGeometry& grid,
                                           std::span<const db::PointXY> items) {
  std::vector<db::PointXY> sorted(items.begin(), items.end());
  const double block = 16.0 * grid.cell_size_m;
  std::sort(sorted.begin(), sorted.end(), [&](const db::PointXY& a, const db::PointXY& b) {
    const double ra = std::floor((grid.max_y_m - a.y) / block);
    const double rb = std::floor((grid.max_y_m - b.y) / block);
    return ra != rb ? ra < rb : a.x < b.x;
  });
  return sorted;
}

}  // namespace

Raster KernelSmooth(const Raster& raster, const KernelDensityOptions& options) {
  if (!(options.bandwidth_m > 0.0)) throw UsageError("kernel smoothing: bandwidth_m must be > 0");
  const GridGeometry& grid = raster.grid;
  const double h_cells = options.bandwidth_m / grid.cell_size_m;
  // Each cell of the kernel's reach is one pass over the raster: beyond this the smoothing takes
  // hours, and the reach would not fit an int.
  constexpr double kMaxReachCells = 200;
  if (!(h_cells <= kMaxReachCells)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "kernel smoothing: a bandwidth of %g m is %g cells of %g m; at most %g (choose "
                  "a larger cell size)",
                  options.bandwidth_m, h_cells, grid.cell_size_m, kMaxReachCells);
    throw UsageError(text);
  }
  const int reach = static_cast<int>(std::floor(h_cells));
  struct Tap {
    int dx, dy;
    float weight;
  };
  std::vector<Tap> taps;
  double sum = 0.0;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const double u = 1.0 - (dx * dx + dy * dy) / (h_cells * h_cells);
      if (u <= 0.0) continue;
      taps.push_back({dx, dy, static_cast<float>(u * u)});
      sum += u * u;
    }
  }
  Raster out(grid, 0.0f);
  // One shifted, weighted add of the whole raster per kernel tap: contiguous rows, vectorised.
  for (const Tap& tap : taps) {
    const auto weight = static_cast<float>(tap.weight / sum);
    const int c0 = std::max(0, -tap.dx);
    const int c1 = std::min(grid.width, grid.width - tap.dx);
    for (int r = std::max(0, -tap.dy); r < std::min(grid.height, grid.height - tap.dy); ++r) {
      float* target = &out.at(0, r);
      const float* source =
          raster.values.data() + static_cast<std::size_t>(r + tap.dy) * grid.width;
      for (int c = c0; c < c1; ++c) target[c] += weight * source[c + tap.dx];
    }
  }
  return out;
}

KernelDensityResult KernelDensity(const GridGeometry& grid, std::span<const db::PointXY> items,
                                  const KernelDensityOptions& options) {
  if (!(options.bandwidth_m > 0.0)) throw UsageError("kernel density: bandwidth_m must be > 0");
  const double h = options.bandwidth_m;
  // The continuous kernel's integral over the grid, used when an item's stamp is clipped by the
  // grid edge: then the sampled sum is scaled by the full stamp's expected sum.
  // The integral of (1 - d^2/h^2)^2 over the disc is pi h^2 / 3: in cells, what an unclipped
  // stamp sums to (near enough), used for an item whose stamp the grid edge cuts off.
  const double full_sum = std::numbers::pi * h * h / 3.0 / grid.cell_area_m2();
  KernelDensityResult result{Raster(grid, 0.0f), 0, 0};
  float* density = result.density.values.data();
  const double inv_area = 1.0 / grid.cell_area_m2();
  Stamp stamp;
  for (const db::PointXY& p : SortedForLocality(grid, items)) {
    const Window window = KernelWindow(grid, p, h);
    const double sum =
        window.c0 <= window.c1 && window.r0 <= window.r1 ? stamp.Fill(grid, p, h, window) : 0.0;
    if (sum <= 0.0) {
      ++result.items_outside;
      continue;
    }
    ++result.items_used;
    const bool clipped = p.x - h < grid.min_x_m || p.x + h > grid.max_x_m() ||
                         p.y - h < grid.min_y_m() || p.y + h > grid.max_y_m;
    const auto scale = static_cast<float>(inv_area / (clipped ? std::max(sum, full_sum) : sum));
    const int columns = window.c1 - window.c0 + 1;
    for (int r = window.r0; r <= window.r1; ++r) {
      float* out = density + static_cast<std::size_t>(r) * grid.width + window.c0;
      const float* w = stamp.weights.data() + static_cast<std::size_t>(r - window.r0) * columns;
      for (int c = 0; c < columns; ++c) out[c] += w[c] * scale;
    }
  }
  return result;
}

}  // namespace littermap::heatmap
