#include "reconstruct/scan_alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include <ceres/ceres.h>
#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/pose_problem.hpp"
#include "reconstruct/scan_normals.hpp"

namespace littermap::reconstruct {
namespace {

using Matrix5d = Eigen::Matrix<double, 5, 5>;
using Vector5d = Eigen::Matrix<double, 5, 1>;

// A key frame as the alignment uses it: a KD-tree over all its points with line normals that
// face the sensor (a thin wall's two sides then do not pair; ScanNormals), and the sparser
// points it pairs.
struct Frame {
  std::unique_ptr<IcpTarget> target;
  std::vector<bool> matchable;  // per target point (ScanNormals)
  Points2 source;
  Points2 source_normals;
};

// as_target: with the search tree (a frame only paired as source needs none).
Frame MakeFrame(const KeyFrame& key_frame, const ScanAlignmentOptions& options,
                bool as_target = true) {
  Frame frame;
  ScanNormals normals = EstimateScanNormals(key_frame.points_base, options.normals);
  for (std::size_t i : VoxelIndices(key_frame.points_base, options.source_voxel_size_m)) {
    frame.source.push_back(key_frame.points_base[i]);
    frame.source_normals.push_back(normals.normals[i]);
  }
  if (as_target) {
    frame.matchable = std::move(normals.matchable);
    frame.target = std::make_unique<IcpTarget>(key_frame.points_base, std::move(normals.normals));
  }
  return frame;
}

double Distance(const PlanarPose& a, const PlanarPose& b) {
  return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m);
}

struct Pair {
  std::size_t source = 0;  // the later key frame, whose points are paired
  std::size_t target = 0;
};

// Visits: runs of consecutive frames within the pair radius, offered one by one in path order
// (either direction), each remembered by its nearest frame.
class Visits {
 public:
  explicit Visits(double radius_m) : radius_m_(radius_m) {}
  void Offer(double distance_m, std::size_t frame) {
    if (distance_m > radius_m_) {
      Break();
      return;
    }
    if (!in_visit_) visits_.emplace_back(distance_m, frame);
    if (distance_m < visits_.back().first) visits_.back() = {distance_m, frame};
    in_visit_ = true;
  }
  void Break() { in_visit_ = false; }  // the next frame offered starts another visit
  // Pairs `source` with the nearest frame of each of up to `count` visits, the nearest first.
  void PairNearest(std::size_t source, std::size_t count, std::vector<Pair>* pairs) {
    std::sort(visits_.begin(), visits_.end());
    visits_.resize(std::min(visits_.size(), count));
    for (const auto& visit : visits_) pairs->push_back({source, visit.second});
  }

 private:
  double radius_m_;
  bool in_visit_ = false;
  std::vector<std::pair<double, std::size_t>> visits_;  // (distance, nearest frame)
};

// Each key frame with its nearest predecessors, and with the nearest key frame of each earlier
// visit (a run of consecutive key frames within the radius), the nearest visits first.
std::vector<Pair> SelectPairs(const std::vector<PlanarPose>& poses,
                              const ScanAlignmentOptions& options) {
  std::vector<Pair> pairs;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const std::size_t first_revisit =
        i > options.sequential_pairs ? i - options.sequential_pairs : 0;
    for (std::size_t j = i; j-- > first_revisit;) {
      if (Distance(poses[i], poses[j]) <= options.pair_radius_m) pairs.push_back({i, j});
    }
    Visits visits(options.pair_radius_m);
    for (std::size_t j = first_revisit; j-- > 0;) visits.Offer(Distance(poses[i], poses[j]), j);
    visits.PairNearest(i, options.max_revisit_pairs, &pairs);
  }
  return pairs;
}

// Each free frame with the held frames next to it along the path (the last one before it and the
// first one after it) and with the nearest held frame of each other visit, the nearest first.
std::vector<Pair> SelectPairsToHeld(const std::vector<PlanarPose>& poses,
                                    const std::vector<bool>& fixed,
                                    const ScanAlignmentOptions& options) {
  std::vector<std::size_t> held;
  for (std::size_t j = 0; j < poses.size(); ++j) {
    if (fixed[j]) held.push_back(j);
  }
  std::vector<Pair> pairs;
  std::size_t next = 0;  // the first held frame after i
  for (std::size_t i = 0; i < poses.size(); ++i) {
    while (next < held.size() && held[next] <= i) ++next;
    if (fixed[i]) continue;
    // held[next - 1] and held[next] bracket i: paired directly, and they split i's own visit.
    Visits visits(options.pair_radius_m);
    for (std::size_t h = 0; h < held.size(); ++h) {
      const double distance = Distance(poses[i], poses[held[h]]);
      if (h + 1 == next || h == next) {
        if (distance <= options.pair_radius_m) pairs.push_back({i, held[h]});
        visits.Break();
      } else {
        visits.Offer(distance, held[h]);
      }
    }
    visits.PairNearest(i, options.max_revisit_pairs, &pairs);
  }
  return pairs;
}

// The squared, weighted point-to-line errors of a pair for fixed associations, as a quadratic
// form z^T M z in z = (cos, sin, x, y, 1) of the source's pose in the target's frame: with
// r = n . (R p + t - q) = cos (n . p) + sin (n_y p_x - n_x p_y) + n . t - n . q.
struct PairForm {
  Matrix5d M = Matrix5d::Zero();
  std::size_t correspondences = 0;
};

void AddRow(const Eigen::Vector2d& n, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
            double weight, Matrix5d* M) {
  Vector5d phi;
  phi << n.dot(p), n.y() * p.x() - n.x() * p.y(), n.x(), n.y(), -n.dot(q);
  *M += weight * phi * phi.transpose();
}

PairForm Associate(const Frame& source, const Frame& target, const PlanarPose& T_target_source,
                   double max_distance_m, const ScanAlignmentOptions& options) {
  PairForm form;
  const double max_sq = max_distance_m * max_distance_m;
  const double c = std::cos(T_target_source.theta_rad), s = std::sin(T_target_source.theta_rad);
  const double inverse_variance = 1 / (options.point_sigma_m * options.point_sigma_m);
  const double scale_sq = options.cauchy_scale_m * options.cauchy_scale_m;
  for (std::size_t k = 0; k < source.source.size(); ++k) {
    const Eigen::Vector2d& p = source.source[k];
    const Eigen::Vector2d moved(c * p.x() - s * p.y() + T_target_source.x_m,
                                s * p.x() + c * p.y() + T_target_source.y_m);
    std::size_t index = 0;
    double distance_sq = 0;
    if (!target.target->NearestWithin(moved, max_sq, &index, &distance_sq)) continue;
    const Eigen::Vector2d& q = target.target->points()[index];
    const Eigen::Vector2d& n = target.target->normal(index);
    if (n.squaredNorm() > 0.5) {
      const Eigen::Vector2d& m = source.source_normals[k];
      if (m.squaredNorm() > 0.5 &&
          n.dot(Eigen::Vector2d(c * m.x() - s * m.y(), s * m.x() + c * m.y())) <= 0) {
        continue;  // the other side of a wall
      }
      const double r = n.dot(moved - q);
      AddRow(n, p, q, inverse_variance / (1 + r * r / scale_sq), &form.M);
    } else if (target.matchable[index]) {
      // No line through the target's neighbourhood (a post, a corner): point to point.
      const double weight = inverse_variance / (1 + distance_sq / scale_sq);
      AddRow(Eigen::Vector2d::UnitX(), p, q, weight, &form.M);
      AddRow(Eigen::Vector2d::UnitY(), p, q, weight, &form.M);
    } else {
      continue;
    }
    ++form.correspondences;
  }
  return form;
}

// One pair's quadratic form as residuals: r = A z with A^T A = M.
class PairError {
 public:
  explicit PairError(const Matrix5d& A) : A_(A) {}

  template <typename T>
  bool operator()(const T* const target, const T* const source, T* residual) const {
    const T ct = ceres::cos(target[2]), st = ceres::sin(target[2]);
    const T dx = source[0] - target[0], dy = source[1] - target[1];
    Eigen::Matrix<T, 5, 1> z;
    z << ceres::cos(source[2] - target[2]), ceres::sin(source[2] - target[2]), ct * dx + st * dy,
        -st * dx + ct * dy, T(1);
    Eigen::Map<Eigen::Matrix<T, 5, 1>> r(residual);
    r = A_.cast<T>() * z;
    return true;
  }

  static ceres::CostFunction* Create(const Matrix5d& M) {
    const Eigen::SelfAdjointEigenSolver<Matrix5d> eigen(M);
    const Vector5d root = eigen.eigenvalues().cwiseMax(0).cwiseSqrt();
    const Matrix5d A = root.asDiagonal() * eigen.eigenvectors().transpose();
    return new ceres::AutoDiffCostFunction<PairError, 5, 3, 3>(new PairError(A));
  }

 private:
  Matrix5d A_;
};

}  // namespace

void ScanAlignmentOptions::Validate() const {
  if (max_correspondence_distances_m.empty()) {
    throw UsageError("scan alignment: max_correspondence_distances_m must not be empty");
  }
  if (!(pair_radius_m > 0) || !(source_voxel_size_m > 0) || !(point_sigma_m > 0) ||
      !(cauchy_scale_m > 0)) {
    throw UsageError(
        "scan alignment: pair_radius_m, source_voxel_size_m, point_sigma_m and cauchy_scale_m "
        "must be > 0");
  }
  // True pairs lie up to a few sigmas of point noise apart: a tighter threshold drops them, the
  // revisits first, and the key frames drift apart with the odometry (measured at 0.05 m on the
  // CARMEN logs: Edmonton 0.12 -> 0.7 m).
  for (double d : max_correspondence_distances_m) {
    if (!(d >= 3 * point_sigma_m)) {
      throw UsageError(
          "scan alignment: correspondence distances must be at least 3 point sigmas (" +
          std::to_string(3 * point_sigma_m) + " m)");
    }
  }
  normals.Validate();
  if (max_iterations_per_round < 1) {
    throw UsageError("scan alignment: max_iterations_per_round must be >= 1");
  }
}

namespace {

void CheckInputs(const std::vector<KeyFrame>& frames, const std::vector<PoseGraphEdge>& odometry,
                 const std::vector<PlanarPose>& poses) {
  if (poses.size() != frames.size()) {
    throw InternalError("scan alignment: " + std::to_string(poses.size()) + " poses for " +
                        std::to_string(frames.size()) + " key frames");
  }
  for (const PoseGraphEdge& edge : odometry) {
    if (edge.from >= poses.size() || edge.to >= poses.size()) {
      throw InternalError("scan alignment: odometry edge " + std::to_string(edge.from) + " -> " +
                          std::to_string(edge.to) + " names a missing pose");
    }
  }
}

// The association rounds over the pairs, every pose i with fixed[i] held (one flag per pose).
// A round whose problem holds no held pose has nothing to anchor it: the rounds stop.
ScanAlignmentResult Solve(const std::vector<Frame>& frames, const std::vector<Pair>& pairs,
                          const std::vector<PoseGraphEdge>& odometry,
                          const std::vector<bool>& fixed, std::vector<PlanarPose>* poses,
                          const ScanAlignmentOptions& options) {
  ScanAlignmentResult result;
  result.usable = true;
  result.pairs = pairs.size();
  std::vector<std::array<double, 3>> parameters(poses->size());
  for (std::size_t i = 0; i < poses->size(); ++i) {
    parameters[i] = {(*poses)[i].x_m, (*poses)[i].y_m, (*poses)[i].theta_rad};
  }
  for (double max_distance_m : options.max_correspondence_distances_m) {
    ceres::Problem problem;
    result.pairs_matched = 0;
    result.correspondences = 0;
    for (const Pair& pair : pairs) {
      const PlanarPose T_target_source = Between((*poses)[pair.target], (*poses)[pair.source]);
      const PairForm form = Associate(frames[pair.source], frames[pair.target], T_target_source,
                                      max_distance_m, options);
      if (form.correspondences < options.min_pair_correspondences) continue;
      ++result.pairs_matched;
      result.correspondences += form.correspondences;
      problem.AddResidualBlock(PairError::Create(form.M), nullptr, parameters[pair.target].data(),
                               parameters[pair.source].data());
    }
    for (const PoseGraphEdge& edge : odometry) {
      problem.AddResidualBlock(RelativePoseError::Create(edge.T_from_to, edge.information), nullptr,
                               parameters[edge.from].data(), parameters[edge.to].data());
    }
    bool anchored = false;
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      if (fixed[i] && problem.HasParameterBlock(parameters[i].data())) {
        problem.SetParameterBlockConstant(parameters[i].data());
        anchored = true;
      }
    }
    if (!anchored) break;
    const ceres::Solver::Summary summary =
        SolvePoseProblem(&problem, options.max_iterations_per_round);
    if (!summary.IsSolutionUsable()) {
      result.usable = false;
      return result;
    }
    if (result.rounds == 0) result.initial_cost = summary.initial_cost;
    result.final_cost = summary.final_cost;
    ++result.rounds;
    for (std::size_t i = 0; i < poses->size(); ++i) {
      (*poses)[i] = {parameters[i][0], parameters[i][1], WrapAngle(parameters[i][2])};
    }
  }
  return result;
}

}  // namespace

ScanAlignmentResult AlignScans(const std::vector<KeyFrame>& key_frames,
                               const std::vector<PoseGraphEdge>& odometry,
                               std::vector<PlanarPose>* poses,
                               const ScanAlignmentOptions& options) {
  options.Validate();
  CheckInputs(key_frames, odometry, *poses);
  if (poses->size() < 2) return {.usable = true};
  std::vector<Frame> frames;
  frames.reserve(key_frames.size());
  for (const KeyFrame& key_frame : key_frames) frames.push_back(MakeFrame(key_frame, options));
  std::vector<bool> first_held(poses->size(), false);
  first_held[0] = true;
  return Solve(frames, SelectPairs(*poses, options), odometry, first_held, poses, options);
}

ScanAlignmentResult AlignScansToHeld(const std::vector<KeyFrame>& key_frames,
                                     const std::vector<PoseGraphEdge>& odometry,
                                     const std::vector<bool>& fixed, std::vector<PlanarPose>* poses,
                                     const ScanAlignmentOptions& options) {
  options.Validate();
  CheckInputs(key_frames, odometry, *poses);
  if (fixed.size() != poses->size()) {
    throw InternalError("scan alignment: " + std::to_string(fixed.size()) + " held flags for " +
                        std::to_string(poses->size()) + " poses");
  }
  if (poses->size() < 2) return {.usable = true};
  std::vector<Frame> frames;
  frames.reserve(key_frames.size());
  for (std::size_t i = 0; i < key_frames.size(); ++i) {
    frames.push_back(MakeFrame(key_frames[i], options, fixed[i]));
  }
  return Solve(frames, SelectPairsToHeld(*poses, fixed, options), odometry, fixed, poses, options);
}

}  // namespace littermap::reconstruct
