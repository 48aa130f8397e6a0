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
// nearest target point (cut at 3 sigma), and the bound grids of every height beside it.
class LikelihoodGrid {
 public:
  LikelihoodGrid(const Points2& target, const CorrelativeOptions& options, int depth)
      : cell_(options.cell_size_m), pad_((1 << depth) - 1) {
    Eigen::Vector2d low = target.front(), high = target.front();
    for (const Eigen::Vector2d& p : target) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    const double margin = 3 * options.sigma_m + cell_;
    origin_ = low - Eigen::Vector2d::Constant(margin);
    width_ = static_cast<int>(std::ceil((high.x() - origin_.x() + margin) / cell_)) + 1;
    height_ = static_cast<int>(std::ceil((high.y() - origin_.y() + margin) / cell_)) + 1;
    // Stored from -pad_ on: a window that starts left of or below the field still reaches into it.
    stride_ = width_ + pad_;
    std::vector<float>& fine = levels_.emplace_back(
        static_cast<std::size_t>(stride_) * static_cast<std::size_t>(height_ + pad_), 0.0f);
    const int reach = static_cast<int>(std::ceil(3 * options.sigma_m / cell_));
    const double inverse_two_sigma_sq = 1 / (2 * options.sigma_m * options.sigma_m);
    for (const Eigen::Vector2d& p : target) {
      const int cx = CellX(p.x()), cy = CellY(p.y());
      for (int y = std::max(0, cy - reach); y <= std::min(height_ - 1, cy + reach); ++y) {
        for (int x = std::max(0, cx - reach); x <= std::min(width_ - 1, cx + reach); ++x) {
          const Eigen::Vector2d centre = origin_ + cell_ * Eigen::Vector2d(x + 0.5, y + 0.5);
          const auto value =
              static_cast<float>(std::exp(-(centre - p).squaredNorm() * inverse_two_sigma_sq));
          float& cell = fine[Index(x, y)];
          cell = std::max(cell, value);
        }
      }
    }
    // Height h: the maximum over the four windows of height h - 1 that make up its window.
    for (int h = 1; h <= depth; ++h) {
      const std::vector<float>& below = levels_.back();
      std::vector<float> level(below.size(), 0.0f);
      const int half = 1 << (h - 1);
      for (int y = -pad_; y < height_; ++y) {
        for (int x = -pad_; x < width_; ++x) {
          float m = below[Index(x, y)];
          if (x + half < width_) m = std::max(m, below[Index(x + half, y)]);
          if (y + half < height_) {
            m = std::max(m, below[Index(x, y + half)]);
            if (x + half < width_) m = std::max(m, below[Index(x + half, y + half)]);
          }
          level[Index(x, y)] = m;
        }
      }
      levels_.push_back(std::move(level));
    }
  }

  int CellX(double x) const { return static_cast<int>(std::floor((x - origin_.x()) / cell_)); }
  int CellY(double y) const { return static_cast<int>(std::floor((y - origin_.y()) / cell_)); }
  // The maximum of the likelihood over the 2^height x 2^height cells from (x, y) on.
  float Bound(int height, int x, int y) const {
    return Inside(x, y) ? levels_[static_cast<std::size_t>(height)][Index(x, y)] : 0.0f;
  }

 private:
  bool Inside(int x, int y) const { return x >= -pad_ && y >= -pad_ && x < width_ && y < height_; }
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y + pad_) * static_cast<std::size_t>(stride_) +
           static_cast<std::size_t>(x + pad_);
  }

  double cell_;
  int pad_;
  Eigen::Vector2d origin_;
  int width_ = 0, height_ = 0, stride_ = 0;
  std::vector<std::vector<float>> levels_;  // by height; 0 is the likelihood itself
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

// A candidate of the branch and bound: the translations (a, b) + [0, 2^height) cells from the
// initial guess under one rotation, and the bound of its score.
struct Candidate {
  float score;
  int rotation, a, b;
};

// Best first; ties in the window's order, so the search does not depend on the sort.
bool Better(const Candidate& x, const Candidate& y) {
  if (x.score != y.score) return x.score > y.score;
  if (x.rotation != y.rotation) return x.rotation < y.rotation;
  return x.a != y.a ? x.a < y.a : x.b < y.b;
}

class BranchAndBound {
 public:
  // A pose is found when it scores above min_score (a sum over the scan's points).
  BranchAndBound(float min_score, const LikelihoodGrid& grid,
                 const std::vector<std::vector<std::array<int, 2>>>& cells, int half,
                 CorrelativeResult* result)
      : grid_(grid), cells_(cells), half_(half), result_(result), best_{min_score, -1, 0, 0} {}

  // Scores the candidates at `height` and searches them best first.
  void Search(std::vector<Candidate> candidates, int height) {
    for (Candidate& c : candidates) c.score = Score(c, height);
    std::sort(candidates.begin(), candidates.end(), Better);
    for (const Candidate& c : candidates) {
      if (c.score <= best_.score) return;  // nor can any later one beat the best
      if (height == 0) {
        best_ = c;
        continue;
      }
      const int step = 1 << (height - 1);
      std::vector<Candidate> children;
      for (int i = 0; i <= step && c.a + i <= half_; i += step) {
        for (int j = 0; j <= step && c.b + j <= half_; j += step) {
          children.push_back({0, c.rotation, c.a + i, c.b + j});
        }
      }
      Search(std::move(children), height - 1);
    }
  }

  const Candidate& best() const { return best_; }

 private:
  float Score(const Candidate& c, int height) {
    ++(height == 0 ? result_->fine_evaluations : result_->bound_evaluations);
    float score = 0;
    for (const auto& q : cells_[static_cast<std::size_t>(c.rotation)]) {
      score += grid_.Bound(height, q[0] + c.a, q[1] + c.b);
    }
    return score;
  }

  const LikelihoodGrid& grid_;
  const std::vector<std::vector<std::array<int, 2>>>& cells_;
  int half_;
  CorrelativeResult* result_;
  Candidate best_;  // rotation -1 until a pose beats the minimum score
};

}  // namespace

void CorrelativeOptions::Validate() const {
  if (!(cell_size_m > 0) || !(sigma_m > 0) || !(source_voxel_m >= 0) || !(max_source_range_m > 0) ||
      max_source_points < 3 || max_branch_and_bound_depth < 0 || max_branch_and_bound_depth > 12 ||
      !(min_score >= 0 && min_score <= 1)) {
    throw UsageError(
        "correlative matcher: sizes must be > 0, max_source_points >= 3, "
        "max_branch_and_bound_depth from 0 to 12 and min_score in [0, 1]");
  }
}

CorrelativeResult MatchCorrelative(const Points2& source_base, const Points2& target,
                                   const PlanarPose& initial, double window_m, double window_rad,
                                   const CorrelativeOptions& options) {
  CorrelativeResult result;
  const Points2 source = ThinSource(source_base, options);
  if (source.size() < 3 || target.empty()) return result;
  // Rotation step: the farthest point moves by at most one cell (Hess et al. 2016, eq. 7).
  double farthest = 0;
  for (const Eigen::Vector2d& p : source) farthest = std::max(farthest, p.norm());
  const double cell = options.cell_size_m;
  const double angular_step =
      std::max(1e-3, std::acos(std::clamp(1 - cell * cell / (2 * farthest * farthest), -1.0, 1.0)));
  const int rotations = static_cast<int>(std::ceil(window_rad / angular_step));
  const int half = static_cast<int>(std::ceil(window_m / cell));
  // The lowest height whose candidates span the window, at most the options' depth.
  int depth = 0;
  while (depth < options.max_branch_and_bound_depth && (1 << depth) < 2 * half + 1) ++depth;
  const LikelihoodGrid grid(target, options, depth);

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
  const auto side = static_cast<std::size_t>(2 * half + 1);
  result.window_poses = cells.size() * side * side;
  std::vector<Candidate> top;
  for (int r = 0; r < static_cast<int>(cells.size()); ++r) {
    for (int a = -half; a <= half; a += 1 << depth) {
      for (int b = -half; b <= half; b += 1 << depth) top.push_back({0, r, a, b});
    }
  }
  const auto points = static_cast<float>(source.size());
  BranchAndBound search(static_cast<float>(options.min_score) * points, grid, cells, half, &result);
  search.Search(std::move(top), depth);
  const Candidate& best = search.best();
  if (best.rotation >= 0) {
    result.found = true;
    result.score = best.score / points;
    result.T_target_source = {
        initial.x_m + best.a * cell, initial.y_m + best.b * cell,
        WrapAngle(initial.theta_rad + (best.rotation - rotations) * angular_step)};
  }
  return result;
}

}  // namespace littermap::reconstruct
