#include "reconstruct/correlative_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

// Likelihood field over the target's bounding box: exp(-d^2 / 2 sigma^2) of the distance to the
// nearest target point (cut at 3 sigma), and the coarse upper-bound grid beside it.
class LikelihoodGrid {
 public:
  LikelihoodGrid(const Points2& target, const CorrelativeOptions& options)
      : cell_(options.cell_size_m) {
    Eigen::Vector2d low = target.front(), high = target.front();
    for (const Eigen::Vector2d& p : target) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    const double margin = 3 * options.sigma_m + cell_;
    origin_ = low - Eigen::Vector2d::Constant(margin);
    width_ = static_cast<int>(std::ceil((high.x() - origin_.x() + margin) / cell_)) + 1;
    height_ = static_cast<int>(std::ceil((high.y() - origin_.y() + margin) / cell_)) + 1;
    fine_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0.0f);
    const int reach = static_cast<int>(std::ceil(3 * options.sigma_m / cell_));
    const double inverse_two_sigma_sq = 1 / (2 * options.sigma_m * options.sigma_m);
    for (const Eigen::Vector2d& p : target) {
      const int cx = CellX(p.x()), cy = CellY(p.y());
      for (int y = std::max(0, cy - reach); y <= std::min(height_ - 1, cy + reach); ++y) {
        for (int x = std::max(0, cx - reach); x <= std::min(width_ - 1, cx + reach); ++x) {
          const Eigen::Vector2d centre = origin_ + cell_ * Eigen::Vector2d(x + 0.5, y + 0.5);
          const auto value =
              static_cast<float>(std::exp(-(centre - p).squaredNorm() * inverse_two_sigma_sq));
          float& cell = fine_[Index(x, y)];
          cell = std::max(cell, value);
        }
      }
    }
    coarse_ = ForwardMax(fine_, options.coarse_cells);
  }

  int CellX(double x) const { return static_cast<int>(std::floor((x - origin_.x()) / cell_)); }
  int CellY(double y) const { return static_cast<int>(std::floor((y - origin_.y()) / cell_)); }
  float Fine(int x, int y) const { return Inside(x, y) ? fine_[Index(x, y)] : 0.0f; }
  float Coarse(int x, int y) const { return Inside(x, y) ? coarse_[Index(x, y)] : 0.0f; }

 private:
  bool Inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }
  // max over the window [x, x + n) x [y, y + n), separably: rows, then columns.
  std::vector<float> ForwardMax(const std::vector<float>& grid, int n) const {
    std::vector<float> rows(grid.size(), 0.0f), out(grid.size(), 0.0f);
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        float m = 0;
        for (int i = 0; i < n && x + i < width_; ++i) m = std::max(m, grid[Index(x + i, y)]);
        rows[Index(x, y)] = m;
      }
    }
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        float m = 0;
        for (int j = 0; j < n && y + j < height_; ++j) m = std::max(m, rows[Index(x, y + j)]);
        out[Index(x, y)] = m;
      }
    }
    return out;
  }

  double cell_;
  Eigen::Vector2d origin_;
  int width_ = 0, height_ = 0;
  std::vector<float> fine_, coarse_;
};

Points2 ThinSource(const Points2& source, const CorrelativeOptions& options) {
  Points2 near;
  for (const Eigen::Vector2d& p : source) {
    if (p.norm() <= options.max_source_range_m) near.push_back(p);
  }
  Points2 thinned = VoxelDownsample(near, options.source_voxel_m);
  if (thinned.size() <= options.max_source_points) return thinned;
  Points2 kept;
  const double step =
      static_cast<double>(thinned.size()) / static_cast<double>(options.max_source_points);
  for (std::size_t k = 0; k < options.max_source_points; ++k) {
    kept.push_back(thinned[static_cast<std::size_t>(static_cast<double>(k) * step)]);
  }
  return kept;
}

struct Coarse {
  float bound;
  int rotation, a, b;
};

}  // namespace

void CorrelativeOptions::Validate() const {
  if (!(cell_size_m > 0) || !(sigma_m > 0) || coarse_cells < 1 || !(source_voxel_m >= 0) ||
      !(max_source_range_m > 0) || max_source_points < 3) {
    throw UsageError("correlative matcher: sizes must be > 0 and max_source_points >= 3");
  }
}

CorrelativeResult MatchCorrelative(const Points2& source_base, const Points2& target,
                                   const PlanarPose& initial, double window_m, double window_rad,
                                   const CorrelativeOptions& options) {
  CorrelativeResult result;
  const Points2 source = ThinSource(source_base, options);
  if (source.size() < 3 || target.empty()) return result;
  const LikelihoodGrid grid(target, options);
  // Rotation step: the farthest point moves by at most one cell (Hess et al. 2016, eq. 7).
  double farthest = 0;
  for (const Eigen::Vector2d& p : source) farthest = std::max(farthest, p.norm());
  const double cell = options.cell_size_m;
  const double angular_step =
      std::max(1e-3, std::acos(std::clamp(1 - cell * cell / (2 * farthest * farthest), -1.0, 1.0)));
  const int rotations = static_cast<int>(std::ceil(window_rad / angular_step));
  const int half = static_cast<int>(std::ceil(window_m / cell));
  const int step = options.coarse_cells;

  // The scan's cells under every rotation, with the initial translation applied.
  std::vector<std::vector<std::array<int, 2>>> cells;
  for (int k = -rotations; k <= rotations; ++k) {
    const double theta = initial.theta_rad + k * angular_step;
    const double c = std::cos(theta), s = std::sin(theta);
    std::vector<std::array<int, 2>>& rotated = cells.emplace_back();
    for (const Eigen::Vector2d& p : source) {
      rotated.push_back({grid.CellX(initial.x_m + c * p.x() - s * p.y()),
                         grid.CellY(initial.y_m + s * p.x() + c * p.y())});
    }
  }
  std::vector<Coarse> coarse;
  for (int r = 0; r < static_cast<int>(cells.size()); ++r) {
    for (int a = -half; a <= half; a += step) {
      for (int b = -half; b <= half; b += step) {
        float bound = 0;
        for (const auto& q : cells[static_cast<std::size_t>(r)])
          bound += grid.Coarse(q[0] + a, q[1] + b);
        coarse.push_back({bound, r, a, b});
      }
    }
  }
  result.coarse_candidates = coarse.size();
  std::sort(coarse.begin(), coarse.end(),
            [](const Coarse& x, const Coarse& y) { return x.bound > y.bound; });
  float best = 0;
  for (const Coarse& candidate : coarse) {
    if (candidate.bound <= best) break;
    const auto& rotated = cells[static_cast<std::size_t>(candidate.rotation)];
    for (int i = 0; i < step && candidate.a + i <= half; ++i) {
      for (int j = 0; j < step && candidate.b + j <= half; ++j) {
        float score = 0;
        for (const auto& q : rotated)
          score += grid.Fine(q[0] + candidate.a + i, q[1] + candidate.b + j);
        ++result.fine_evaluations;
        if (score > best) {
          best = score;
          result.found = true;
          result.T_target_source = {
              initial.x_m + (candidate.a + i) * cell, initial.y_m + (candidate.b + j) * cell,
              WrapAngle(initial.theta_rad + (candidate.rotation - rotations) * angular_step)};
        }
      }
    }
  }
  result.score = best / static_cast<float>(source.size());
  return result;
}

}  // namespace littermap::reconstruct
